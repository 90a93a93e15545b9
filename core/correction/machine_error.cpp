#include "machine_error.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "direction_decision.h"
#include "face_cache.h"
#include "face_vectors.h"
#include "levenberg_marquardt.h"
#include "sensitivity_matrix.h"
#include "solve_report.h"
#include "units.h"

namespace hobsharp {
namespace {

// How often the directions are decided: at E = 0, then at the solution (README, "Correction").
constexpr int kDecisionRounds = 3;

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
  FaceCache cache;  // faces without sensitivities: the trial steps need only the deviations
  int jacobians = 0;
  // The cached face at sensitiveX was given its sensitivities, and S is its matrix over all
  // coefficients (Eqs. 13-16): for df, and for the decision and the covariance at the solution.
  Eigen::VectorXd sensitiveX;
  int sensitiveEvaluation = -1;  // cache.evaluations when it was: a later face replaced it
  Eigen::MatrixXd S;

  const GroundFace* faceAt(const Eigen::VectorXd& x) {
    return cache.at(x, [&](const Eigen::VectorXd& t) {
      return simulateGroundFaceLike(like, setup, plusChange(run, coefficients, P * t), Sensitivities::Skip);
    });
  }

  const GroundFace* sensitiveFaceAt(const Eigen::VectorXd& x) {
    const GroundFace* f = faceAt(x);
    if (!f) return nullptr;
    if (sensitiveEvaluation == cache.evaluations && sensitiveX == x) return f;
    if (!addSensitivities(*cache.lastFace, setup, plusChange(run, coefficients, P * x))) return nullptr;
    sensitiveX = x;
    sensitiveEvaluation = cache.evaluations;
    S = sensitivityMatrix(*f, coefficients).normal;
    return f;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) {
    faceResidual(faceAt(x), measured, fvec);
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    if (!sensitiveFaceAt(x)) return -1;  // never at an accepted iterate: those were all simulated
    ++jacobians;
    jac = S * P;
    return 0;
  }
};

}  // namespace

const char* statusName(SolveStatus s) {
  switch (s) {
    case SolveStatus::Converged: return "converged";
    case SolveStatus::AboveNoise: return "aboveNoise";
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
  Eigen::VectorXd zFull = Eigen::VectorXd::Zero(q);  // E in machine steps per coefficient
  // The face at the estimate: the run face until the solver has moved, then the solver's (the run
  // face is not copied: a face of 2,000 points is most of a megabyte).
  std::optional<GroundFace> solved;
  const auto current = [&]() -> const GroundFace& { return solved ? *solved : runFace; };
  Eigen::MatrixXd currentS = sensitivityMatrix(runFace, cs).normal;  // of current()
  std::vector<bool> previous;
  Eigen::MatrixXd keptP(q, 0);  // the last round's solution, kept if a later round cannot start
  Eigen::VectorXd keptTheta(0);
  int evaluations = 0;
  for (int round = 0; round < kDecisionRounds; ++round) {
    if (q == 0 || m.space.basis.cols() == 0) break;
    const Eigen::MatrixXd& basis = m.space.basis;
    const Eigen::VectorXd zE = basis.transpose() * zFull;
    const Eigen::MatrixXd Jz = currentS * m.space.step.asDiagonal() * basis;
    const Eigen::VectorXd data = d - faceNormal(current()) + Jz * zE;  // what E makes, linearised here
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
    const DirectionDecision decision = decideDirections(s, c, data.norm(), static_cast<int>(d.size()), o);
    const std::vector<bool>& used = decision.used;
    const std::vector<int>& kept = decision.kept;
    const int withinNoise = decision.withinNoise, amplifying = decision.amplifying;
    if (round > 0 && used == previous) break;
    previous = used;
    m.singularValues = s;
    m.used = used;
    m.withinNoise = withinNoise;
    m.amplifying = amplifying;
    Eigen::MatrixXd V(basis.cols(), static_cast<int>(kept.size()));
    for (size_t k = 0; k < kept.size(); ++k) V.col(static_cast<int>(k)) = svd.matrixV().col(kept[k]);
    P = m.space.step.asDiagonal() * (basis * V);
    theta = V.transpose() * zE;  // the estimate so far, in the directions decided here
    if (kept.empty()) {
      solved.reset();
      currentS = sensitivityMatrix(runFace, cs).normal;
      zFull.setZero();
      break;
    }
    FaceResidual residual(setup, run, runFace, cs, P, d);
    // The faces this round simulated, and those the wheel could not grind, into the summary.
    const auto countFaces = [&] {
      evaluations += residual.cache.evaluations;
      m.summary.unsolvableFaces += residual.cache.unsolvable;
    };
    if (round == 0) {
      residual.cache.lastX = theta;
      residual.cache.lastFace = runFace;  // with its sensitivities, and their matrix
      residual.sensitiveX = theta;
      residual.sensitiveEvaluation = residual.cache.evaluations;
      residual.S = std::move(currentS);  // back at the solution below, or formed again on failure
    }
    bool refused = false;
    const bool started = solveLeastSquares(residual, theta, o.solver, m.summary, "no identified axis direction", &refused);
    if (!started && round > 0) {
      countFaces();
      P = keptP;
      theta = keptTheta;
      m.summary.status = SolveStatus::Stalled;
      m.summary.reason = "stalled: the directions decided at the solution leave a face that cannot be simulated; "
                         "the estimate before is kept.";
      break;
    }
    if (!started) {
      m.summary.status = SolveStatus::Failed;
      m.summary.reason = refused ? "failed: the solver refused its inputs."
                                 : "failed: the face of the estimate cannot be simulated.";
      countFaces();
      theta.setZero();
      solved.reset();
      currentS = sensitivityMatrix(runFace, cs).normal;
      break;
    }
    // theta is the best iterate: the solver only ever accepts steps that reduce the sum of squares.
    const GroundFace* f = residual.sensitiveFaceAt(theta);
    countFaces();
    if (!f) {
      // The face at the estimate was simulated (the solver accepted it), but its envelope equations
      // are singular there, so it has no sensitivities: the estimate and its face are kept, and the
      // last Jacobian formed stands for the covariance.
      f = residual.faceAt(theta);
      if (!f) return refuse("measured", "the identified machine error leaves a face that cannot be simulated.",
                            ErrorCode::Unsolvable);
      solved = std::move(residual.cache.lastFace);
      currentS = residual.S.rows() == d.size() ? residual.S : sensitivityMatrix(runFace, cs).normal;
      zFull = basis * (V * theta);
      keptP = P;
      keptTheta = theta;
      m.summary.status = SolveStatus::Stalled;
      m.summary.reason = "stalled: at the estimate the face's envelope equations are singular (no sensitivities), so "
                         "the solve cannot go on; the estimate is kept.";
      break;
    }
    solved = std::move(residual.cache.lastFace);
    currentS = std::move(residual.S);
    zFull = basis * (V * theta);
    keptP = P;
    keptTheta = theta;
    if (m.summary.status != SolveStatus::Converged || m.summary.iterations >= o.solver.maxIterations) break;
  }
  if (P.cols() == 0) {
    m.summary.status = SolveStatus::Converged;
    m.summary.reason = "converged: the measurement shows nothing above the probe noise that the axes can make.";
    theta = Eigen::VectorXd::Zero(0);
  }
  m.face = solved ? std::move(*solved) : runFace;
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
  m.jacobian = currentS;
  judgeMisfit(m.summary, m.summary.finalCost, static_cast<int>(d.size()), o.probeNoise);
  m.covariancePerNoise = Eigen::MatrixXd::Zero(q, q);
  if (P.cols() > 0) {
    // (J^T J)^-1 in the identified directions, which the decision kept well conditioned.
    const Eigen::MatrixXd J = currentS * P;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(JtJ);
    const Eigen::MatrixXd covTheta = ldlt.solve(Eigen::MatrixXd::Identity(JtJ.rows(), JtJ.cols()));
    if (covTheta.allFinite()) m.covariancePerNoise = P * covTheta * P.transpose();
  }
  return m;
}

}  // namespace hobsharp
