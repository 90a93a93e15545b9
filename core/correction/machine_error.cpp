#include "machine_error.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "sensitivity_matrix.h"

namespace hobsharp {
namespace {

constexpr double kMicrometresPerMm = 1000.0;
// The residual given to the solver for a trial whose face cannot be simulated (a grid point the
// wheel does not reach): large enough that the step is always rejected and the trust region shrinks.
constexpr double kUnsolvableResidual = 1e12;  // µm
// Directions whose singular value is below this share of the largest are numerically null.
constexpr double kNumericalRank = 1e-12;
// How often the directions are decided: at E = 0, then at the solution (README, "Correction").
constexpr int kDecisionRounds = 3;

Eigen::VectorXd flat(const Eigen::MatrixXd& m) {
  Eigen::VectorXd v(m.size());
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) v(i * m.cols() + j) = m(i, j);
  return v;
}

Eigen::VectorXd faceNormal(const GroundFace& f) {
  Eigen::VectorXd v(f.size());
  for (int p = 0; p < f.size(); ++p) v(p) = kMicrometresPerMm * f.envelope[p].t;
  return v;
}

AxisPolynomials plus(AxisPolynomials axes, const std::vector<Coefficient>& cs, const Eigen::VectorXd& change) {
  for (size_t j = 0; j < cs.size(); ++j) axes[cs[j].axis].a[cs[j].degree] += change(static_cast<int>(j));
  return axes;
}

// r(theta) = face(run + P theta) - measured, µm; its Jacobian S(run + P theta) P (Eqs. 13-16).
struct FaceResidual : Eigen::DenseFunctor<double> {
  FaceResidual(const SharpeningSetup& s, const AxisPolynomials& r, const GroundFace& g,
               const std::vector<Coefficient>& cs, const Eigen::MatrixXd& basis, const Eigen::VectorXd& m)
      : Eigen::DenseFunctor<double>(static_cast<int>(basis.cols()), static_cast<int>(m.size())),
        setup(s), run(r), like(g), coefficients(cs), P(basis), measured(m) {}

  const SharpeningSetup& setup;
  const AxisPolynomials& run;
  const GroundFace& like;  // simulated at its points: the grid, or the probe points
  const std::vector<Coefficient>& coefficients;
  const Eigen::MatrixXd& P;
  const Eigen::VectorXd& measured;
  Eigen::VectorXd lastX;
  std::optional<GroundFace> lastFace;
  int evaluations = 0, unsolvable = 0, jacobians = 0;

  const GroundFace* faceAt(const Eigen::VectorXd& x) {
    if (lastFace && lastX.size() == x.size() && lastX == x) return &*lastFace;
    ++evaluations;
    auto f = simulateGroundFaceLike(like, setup, plus(run, coefficients, P * x));
    lastX = x;
    if (!f) {
      ++unsolvable;
      lastFace.reset();
      return nullptr;
    }
    lastFace = std::move(f).value();
    return &*lastFace;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) {
    const GroundFace* f = faceAt(x);
    if (!f) {
      fvec.setConstant(values(), kUnsolvableResidual);
      return 0;
    }
    fvec = faceNormal(*f) - measured;
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    const GroundFace* f = faceAt(x);
    if (!f) return -1;  // never at an accepted iterate: those were all simulated
    ++jacobians;
    jac = sensitivityMatrix(*f, coefficients).normal * P;
    return 0;
  }
};

// A tolerance as a share in words: 1e-10 -> "1 part in 1e+10".
std::string share(double tolerance) {
  std::ostringstream t;
  t.precision(2);
  t << "1 part in " << 1 / tolerance;
  return t.str();
}

void describe(LeastSquaresSummary& s, Eigen::LevenbergMarquardtSpace::Status st, const FaceResidual& r,
              const LeastSquaresOptions& o) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (st) {
    case RelativeReductionTooSmall:
    case RelativeErrorAndReductionTooSmall:
      s.status = SolveStatus::Converged;
      s.reason = "converged: a further step would lower the sum of squares by less than " + share(o.functionTolerance) +
                 " of it (function tolerance).";
      break;
    case RelativeErrorTooSmall:
      s.status = SolveStatus::Converged;
      s.reason = "converged: the last steps changed the identified error by less than " + share(o.parameterTolerance) +
                 " of it (parameter tolerance).";
      break;
    case CosinusTooSmall:
      s.status = SolveStatus::Converged;
      s.reason = "converged: what is left of the measured face is a shape no identified axis direction makes "
                 "(gradient tolerance).";
      break;
    case FtolTooSmall:
    case XtolTooSmall:
    case GtolTooSmall:
      if (r.unsolvable > 0) {
        s.status = SolveStatus::Stalled;
        s.reason = "stalled: every further step leaves the face the wheel can grind; the best estimate is kept.";
      } else {
        s.status = SolveStatus::Converged;
        s.reason = "converged: no step can reduce the sum of squares at the precision of the face simulation.";
      }
      break;
    case TooManyFunctionEvaluation:
    case Running:
      s.status = SolveStatus::NoConvergence;
      s.reason = "not converged after " + std::to_string(o.maxIterations) +
                 " iterations (maxIterations); the best estimate is kept.";
      break;
    default:
      s.status = SolveStatus::Stalled;
      s.reason = "stalled: the Jacobian could not be factorised; the best estimate is kept.";
      break;
  }
}

}  // namespace

const char* statusName(SolveStatus s) {
  switch (s) {
    case SolveStatus::Converged: return "converged";
    case SolveStatus::NoConvergence: return "notConverged";
    case SolveStatus::Stalled: return "stalled";
    case SolveStatus::Failed: return "failed";
  }
  return "failed";
}

Outcome<MachineErrorEstimate> identifyMachineError(const SharpeningSetup& setup, const AxisPolynomials& run,
                                                   const GroundFace& runFace, const Eigen::MatrixXd& measured,
                                                   const CorrectionOptions& o) {
  // The face's shape: the grid, or one column of probe points (ground_face.h).
  struct Shape {
    int r, c;
    int rows() const { return r; }
    int cols() const { return c; }
  } const grid{runFace.rows(), runFace.cols()};
  if (measured.rows() != grid.rows() || measured.cols() != grid.cols())
    return refuse("measured", "the topography has " + std::to_string(measured.rows()) + " x " +
                                  std::to_string(measured.cols()) + " values; the grid is " +
                                  std::to_string(grid.rows()) + " radial x " + std::to_string(grid.cols()) + " axial.");
  if (!measured.allFinite()) return refuse("measured", "holds a value that is not a finite number.");
  const MotionRange range = motionRange(runFace);
  const double reach = std::max({std::abs(range.min), std::abs(range.max), 1e-12});

  MachineErrorEstimate m;
  m.space = identifiableSpace(setup.face, run.degree(), o, reach);
  const std::vector<Coefficient>& cs = m.space.coefficients;
  const int q = static_cast<int>(cs.size());
  const Eigen::VectorXd d = flat(measured);
  const Eigen::VectorXd face0 = faceNormal(runFace);

  // Which directions the measurement shows above the noise, on the linearisation at the current
  // estimate (E = 0 first): the component of the data along each left singular vector is
  // sigma-distributed noise plus the signal; it is identified only beyond significance * sigma.
  // The decision is checked once more at the solution, where the linearisation holds; if it
  // differs there, the solve goes on from the solution in the directions decided there.
  m.summary.initialCost = (face0 - d).squaredNorm();
  Eigen::MatrixXd P(q, 0);
  Eigen::VectorXd theta(0);
  Eigen::VectorXd zE = Eigen::VectorXd::Zero(m.space.basis.cols());  // E in the basis, machine steps
  GroundFace current = runFace;
  std::vector<bool> previous;
  Eigen::MatrixXd keptP(q, 0);  // the last round's solution, kept if a later round cannot start
  Eigen::VectorXd keptTheta(0);
  int evaluations = 0;
  for (int round = 0; round < kDecisionRounds; ++round) {
    if (q == 0 || m.space.basis.cols() == 0) break;
    const Eigen::MatrixXd Jz = sensitivityMatrix(current, cs).normal * m.space.step.asDiagonal() * m.space.basis;
    const Eigen::VectorXd data = d - faceNormal(current) + Jz * zE;  // what E makes, linearised here
    // The SVD of Jz through its QR (Jz = Q R, R = U S V^T): the data's components along the
    // left singular vectors are U^T (Q^T data), without forming the p x m factor.
    // A grid with fewer points than directions (3 x 3 at degree 4) has a wide R.
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Jz);
    const int mm = static_cast<int>(std::min(Jz.rows(), Jz.cols()));
    const Eigen::MatrixXd R = qr.matrixQR().topRows(mm).triangularView<Eigen::Upper>();
    const Eigen::VectorXd qtd = (qr.householderQ().transpose() * data).head(mm);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::VectorXd s = svd.singularValues();
    const Eigen::VectorXd c = svd.matrixU().transpose() * qtd;
    // The step the strongest direction needs to make the whole face: the yardstick of "wild".
    const double yardstick = data.norm() / s(0);
    std::vector<int> kept;
    std::vector<bool> used;
    int withinNoise = 0, amplifying = 0;
    for (int i = 0; i < s.size(); ++i) {
      bool use = false;
      if (s(i) <= kNumericalRank * s(0)) {
        // numerically null: neither counted nor used
      } else if (std::abs(c(i)) <= o.significance * o.probeNoise) {
        ++withinNoise;
      } else if (std::abs(c(i)) / s(i) > o.spanAmplification * yardstick) {
        ++amplifying;
      } else {
        use = true;
        kept.push_back(i);
      }
      used.push_back(use);
    }
    if (round > 0 && used == previous) break;
    previous = used;
    m.singularValues = s;
    m.used = used;
    m.withinNoise = withinNoise;
    m.amplifying = amplifying;
    Eigen::MatrixXd V(m.space.basis.cols(), static_cast<int>(kept.size()));
    for (size_t k = 0; k < kept.size(); ++k) V.col(static_cast<int>(k)) = svd.matrixV().col(kept[k]);
    P = m.space.step.asDiagonal() * (m.space.basis * V);
    theta = V.transpose() * zE;  // the estimate so far, in the directions decided here
    if (kept.empty()) {
      current = runFace;
      zE.setZero();
      break;
    }
    FaceResidual residual(setup, run, runFace, cs, P, d);
    if (round == 0) {
      residual.lastX = theta;
      residual.lastFace = runFace;
    }
    Eigen::LevenbergMarquardt<FaceResidual> lm(residual);
    lm.setFtol(o.solver.functionTolerance);
    lm.setXtol(o.solver.parameterTolerance);
    lm.setGtol(o.solver.gradientTolerance);
    lm.setFactor(o.solver.initialTrustRegion);
    lm.setMaxfev(1000000);  // the iterations are counted below
    auto status = lm.minimizeInit(theta);
    if (status != Eigen::LevenbergMarquardtSpace::NotStarted && round > 0) {
      evaluations += residual.evaluations;
      P = keptP;
      theta = keptTheta;
      m.summary.status = SolveStatus::Stalled;
      m.summary.reason = "stalled: the directions decided at the solution leave a face that cannot be simulated; "
                         "the estimate before is kept.";
      break;
    }
    if (status != Eigen::LevenbergMarquardtSpace::NotStarted) {
      m.summary.status = SolveStatus::Failed;
      m.summary.reason = status == Eigen::LevenbergMarquardtSpace::ImproperInputParameters
                             ? "failed: the solver refused its inputs."
                             : "failed: the face of the estimate cannot be simulated.";
      evaluations += residual.evaluations;
      theta.setZero();
      current = runFace;
      break;
    }
    int iterations = 0;
    const int left = o.solver.maxIterations - m.summary.iterations;
    do {
      status = lm.minimizeOneStep(theta);
      ++iterations;
    } while (status == Eigen::LevenbergMarquardtSpace::Running && iterations < left);
    m.summary.iterations += iterations;
    describe(m.summary, status, residual, o.solver);
    // theta is the best iterate: the solver only ever accepts steps that reduce the sum of squares.
    const GroundFace* f = residual.faceAt(theta);
    evaluations += residual.evaluations;
    if (!f) return refuse("measured", "the identified machine error leaves a face that cannot be simulated.",
                          ErrorCode::Unsolvable);
    current = *f;
    zE = V * theta;
    keptP = P;
    keptTheta = theta;
    if (m.summary.status != SolveStatus::Converged || m.summary.iterations >= o.solver.maxIterations) break;
  }
  if (P.cols() == 0) {
    m.summary.status = SolveStatus::Converged;
    m.summary.reason = "converged: the measurement shows nothing above the probe noise that the axes can make.";
    theta = Eigen::VectorXd::Zero(0);
  }
  m.face = current;
  m.summary.faceEvaluations = evaluations;
  m.coefficientError = P * theta;
  m.error = run;
  for (Axis a : kAxes) std::fill(m.error[a].a.begin(), m.error[a].a.end(), 0.0);
  for (int j = 0; j < q; ++j) m.error[cs[j].axis].a[cs[j].degree] = m.coefficientError(j);
  m.explained = measured;
  for (int i = 0; i < grid.rows(); ++i)
    for (int j = 0; j < grid.cols(); ++j) m.explained(i, j) = kMicrometresPerMm * m.face.envelope[i * grid.cols() + j].t;
  m.unexplained = measured - m.explained;
  m.summary.finalCost = m.unexplained.squaredNorm();
  m.covariancePerNoise = Eigen::MatrixXd::Zero(q, q);
  if (P.cols() > 0) {
    // (J^T J)^-1 in the identified directions, which the decision kept well conditioned.
    const Eigen::MatrixXd J = sensitivityMatrix(m.face, cs).normal * P;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(JtJ);
    const Eigen::MatrixXd covTheta = ldlt.solve(Eigen::MatrixXd::Identity(JtJ.rows(), JtJ.cols()));
    if (covTheta.allFinite()) m.covariancePerNoise = P * covTheta * P.transpose();
  }
  return m;
}

}  // namespace hobsharp
