#include "wheel_error.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "direction_decision.h"
#include "face_cache.h"
#include "face_vectors.h"
#include "levenberg_marquardt.h"
#include "number_text.h"
#include "sensitivity_matrix.h"
#include "solve_report.h"
#include "units.h"
#include "wheel_offset_sensitivity.h"
#include "wheel_profile.h"

namespace hobsharp {
namespace {

// As machine_error.cpp: how often the directions are decided.
constexpr int kDecisionRounds = 3;

// The parameters theta = (theta_E, theta_W): E = PE theta_E (coefficients), W = PW theta_W (µm).
// r(theta) = face(run + E; wheel + W) - measured, µm; its Jacobian [S(E, W) PE, S_W(E, W) PW].
struct JointResidual : Eigen::DenseFunctor<double> {
  JointResidual(const SharpeningSetup& s, const AxisPolynomials& r, const FaceGrid& g,
                const std::vector<Coefficient>& cs, const WheelKnots& k, const CubicSpline& b,
                const Eigen::MatrixXd& pe, const Eigen::MatrixXd& pw, const Eigen::VectorXd& m)
      : Eigen::DenseFunctor<double>(static_cast<int>(pe.cols() + pw.cols()), static_cast<int>(m.size())),
        setup(s), run(r), grid(g), coefficients(cs), knots(k), wheelBasis(b), PE(pe), PW(pw), measured(m) {}

  const SharpeningSetup& setup;
  const AxisPolynomials& run;
  const FaceGrid& grid;
  const std::vector<Coefficient>& coefficients;
  const WheelKnots& knots;
  const CubicSpline& wheelBasis;  // W's spline with zero values: its cardinal functions
  const Eigen::MatrixXd& PE;
  const Eigen::MatrixXd& PW;
  const Eigen::VectorXd& measured;
  FaceCache cache;

  Eigen::VectorXd axesPart(const Eigen::VectorXd& x) const { return PE * x.head(PE.cols()); }
  Eigen::VectorXd wheelPart(const Eigen::VectorXd& x) const { return PW * x.tail(PW.cols()); }

  // The face at x without sensitivities: a trial step needs only the deviations.
  const GroundFace* faceAt(const Eigen::VectorXd& x) {
    return cache.at(x, [&](const Eigen::VectorXd& t) {
      return simulateGroundFace(setupAt(t), axesAt(t), grid, Sensitivities::Skip);
    });
  }
  // The same face with its sensitivities (added to a copy: the same figures as simulating it with
  // them), where the solver asks for the Jacobian and at the solution. Kept apart from the trial
  // faces, so that the solution, when the last trial step was rejected, is not simulated again.
  const GroundFace* sensitiveFaceAt(const Eigen::VectorXd& x) {
    if (sensitive && sensitiveX.size() == x.size() && sensitiveX == x) return &*sensitive;
    const GroundFace* f = faceAt(x);
    if (!f) return nullptr;
    GroundFace g = *f;
    if (!addSensitivities(g, setupAt(x), axesAt(x))) return nullptr;
    sensitive = std::move(g);
    sensitiveX = x;
    return &*sensitive;
  }
  // `face`, with its sensitivities, is the face at x.
  void seed(const Eigen::VectorXd& x, const GroundFace& face) {
    cache.lastX = x;
    cache.lastFace = face;
    sensitive = face;
    sensitiveX = x;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) {
    faceResidual(faceAt(x), measured, fvec);
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    const GroundFace* f = sensitiveFaceAt(x);
    if (!f) return -1;  // never at an accepted iterate: those were all simulated
    jac.resize(values(), inputs());
    jac.leftCols(PE.cols()) = sensitivityMatrix(*f, coefficients).normal * PE;
    jac.rightCols(PW.cols()) = wheelOffsetSensitivity(*f, wheelBasis).normal * PW;
    return 0;
  }

 private:
  SharpeningSetup setupAt(const Eigen::VectorXd& x) const { return withWheelDeviation(setup, knots, wheelPart(x)); }
  AxisPolynomials axesAt(const Eigen::VectorXd& x) const { return plusChange(run, coefficients, axesPart(x)); }
  std::optional<GroundFace> sensitive;
  Eigen::VectorXd sensitiveX;
};

Eigen::MatrixXd columns(const Eigen::MatrixXd& m, const std::vector<int>& kept) {
  Eigen::MatrixXd out(m.rows(), static_cast<int>(kept.size()));
  for (size_t k = 0; k < kept.size(); ++k) out.col(static_cast<int>(k)) = m.col(kept[k]);
  return out;
}

// An orthonormal basis of the columns' span (they are independent: decided directions).
Eigen::MatrixXd orthonormalSpan(const Eigen::MatrixXd& a) {
  if (a.cols() == 0) return Eigen::MatrixXd(a.rows(), 0);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
  return qr.householderQ() * Eigen::MatrixXd::Identity(a.rows(), a.cols());
}

}  // namespace

Outcome<WheelKnots> wheelKnots(const SharpeningSetup& setup, const FaceGrid& grid, double rLow, double rHigh) {
  const int k = std::clamp(grid.rows(), kFewestWheelKnots, kMostWheelKnots);
  if (!(rHigh > rLow))
    return refuse("correction.wheel", "needs a grid that spans the face radially; it spans " + numberText(rLow) +
                                          " to " + numberText(rHigh) + " mm.");
  auto p = wheelProfile(setup.face, setup.universal, setup.normalSign, evenRadii(rLow, rHigh, k));
  if (!p) return p.error();
  // The wheel's rim grinds the gash root: R falls from root to tip; the spline's R must increase.
  WheelKnots knots{p->r, p->R};
  if (knots.R.back() < knots.R.front()) {
    std::reverse(knots.r.begin(), knots.r.end());
    std::reverse(knots.R.begin(), knots.R.end());
  }
  for (int i = 1; i < k; ++i)
    if (!(knots.R[i] > knots.R[i - 1]))
      return refuse("correction.wheel", "the wheel radius does not change monotonically from the gash root to the tip "
                                        "(R = " + numberText(knots.R[i - 1]) + " then " + numberText(knots.R[i]) +
                                            " mm): the offset cannot be given along R.");
  return knots;
}

SharpeningSetup withWheelDeviation(const SharpeningSetup& setup, const WheelKnots& knots, const Eigen::VectorXd& W) {
  SharpeningSetup s = setup;
  std::vector<double> y(knots.R.size());
  for (size_t k = 0; k < y.size(); ++k) y[k] = W(static_cast<int>(k)) / kMicrometresPerMm;
  s.wheel.added = CubicSpline(knots.R, std::move(y));
  return s;
}

Outcome<WheelErrorEstimate> identifyMachineAndWheelError(const SharpeningSetup& setup, const AxisPolynomials& run,
                                                         const GroundFace& runFace, const Eigen::MatrixXd& measured,
                                                         const CorrectionOptions& o, const WheelKnots& knots) {
  const FaceGrid& grid = runFace.grid;
  if (measured.rows() != grid.rows() || measured.cols() != grid.cols())
    return refuse("measured", "the topography has " + std::to_string(measured.rows()) + " x " +
                                  std::to_string(measured.cols()) + " values; the grid is " +
                                  std::to_string(grid.rows()) + " radial x " + std::to_string(grid.cols()) + " axial.");
  if (!measured.allFinite()) return refuse("measured", "holds a value that is not a finite number.");
  const MotionRange range = motionRange(runFace);
  const double reach = std::max({std::abs(range.min), std::abs(range.max), 1e-12});

  WheelErrorEstimate m;
  m.knots = knots;
  MachineErrorEstimate& a = m.axes;
  a.space = identifiableSpace(setup.face, run.degree(), o, reach);
  const std::vector<Coefficient>& cs = a.space.coefficients;
  const int q = static_cast<int>(cs.size());
  const int nb = static_cast<int>(a.space.basis.cols());
  const int K = static_cast<int>(knots.R.size());
  const Eigen::VectorXd d = flat(measured);
  const CubicSpline wheelBasis(knots.R, std::vector<double>(static_cast<size_t>(K), 0.0));

  // The run face with W = 0 in the model, so that it carries the partials to W: its envelope
  // points are runFace's (a zero offset grinds today's face), given the sensitivities again.
  GroundFace start = runFace;
  const SharpeningSetup withoutDeviation = withWheelDeviation(setup, knots, Eigen::VectorXd::Zero(K));
  if (runFace.atProbes()) {
    auto f = simulateGroundFace(withoutDeviation, run, grid);
    if (!f) return f.error();
    start = std::move(f).value();
  } else if (auto added = addSensitivities(start, withoutDeviation, run); !added) {
    return added.error();
  }
  GroundFace current = start;
  a.summary.initialCost = (faceNormal(current) - d).squaredNorm();

  Eigen::VectorXd zE = Eigen::VectorXd::Zero(nb);  // E in the identifiable basis, machine steps
  Eigen::VectorXd w = Eigen::VectorXd::Zero(K);    // W, µm
  Eigen::MatrixXd PE(q, 0), PW(K, 0);
  Eigen::VectorXd theta(0);
  Eigen::MatrixXd keptPE = PE, keptPW = PW;
  Eigen::VectorXd keptTheta(0);
  std::vector<bool> previousE, previousW;
  int evaluations = 0;
  for (int round = 0; round < kDecisionRounds; ++round) {
    // The linearisation at the current estimate; data: what E and W make, linearised here.
    const Eigen::MatrixXd SE = sensitivityMatrix(current, cs).normal * a.space.step.asDiagonal() * a.space.basis;
    const Eigen::MatrixXd SW = wheelOffsetSensitivity(current, wheelBasis).normal;
    const Eigen::VectorXd data = d - faceNormal(current) + SE * zE + SW * w;

    // The axes first, as machine_error.cpp decides them: the SVD of SE through its QR.
    DirectionDecision axes;
    Eigen::MatrixXd VE(nb, 0), QE(d.size(), 0);
    if (nb > 0) {
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(SE);
      const int mm = static_cast<int>(std::min(SE.rows(), SE.cols()));
      const Eigen::MatrixXd R = qr.matrixQR().topRows(mm).triangularView<Eigen::Upper>();
      const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(SE.rows(), mm);
      const Eigen::VectorXd qtd = Q.transpose() * data;
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
      axes = decideDirections(svd.singularValues(), svd.matrixU().transpose() * qtd, data.norm(),
                              static_cast<int>(d.size()), o, Wild::LeftOut);
      a.singularValues = svd.singularValues();
      VE = columns(svd.matrixV(), axes.kept);
      QE = Q * columns(svd.matrixU(), axes.kept);  // the face directions the axes take, orthonormal
    }
    // Then the wheel, off the span of what the axes take: only the shape the axes cannot make.
    const Eigen::MatrixXd SWoff = SW - QE * (QE.transpose() * SW);
    const Eigen::VectorXd dataOff = data - QE * (QE.transpose() * data);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svdW(SWoff, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const DirectionDecision wheel = decideDirections(svdW.singularValues(), svdW.matrixU().transpose() * dataOff,
                                                     dataOff.norm(), static_cast<int>(d.size()), o, Wild::LeftOut);

    if (round > 0 && axes.used == previousE && wheel.used == previousW) break;
    previousE = axes.used;
    previousW = wheel.used;
    a.used = axes.used;
    a.withinNoise = axes.withinNoise;
    a.amplifying = axes.amplifying;
    m.wheelSingularValues = svdW.singularValues();
    m.wheelUsed = wheel.used;
    m.wheelWithinNoise = wheel.withinNoise;
    m.wheelAmplifying = wheel.amplifying;

    const Eigen::MatrixXd VW = columns(svdW.matrixV(), wheel.kept);
    PE = a.space.step.asDiagonal() * (a.space.basis * VE);
    PW = VW;
    theta.resize(VE.cols() + VW.cols());
    theta << VE.transpose() * zE, VW.transpose() * w;  // the estimate so far, in the directions decided here
    if (theta.size() == 0) {
      current = start;
      zE.setZero();
      w.setZero();
      break;
    }
    JointResidual residual(setup, run, grid, cs, knots, wheelBasis, PE, PW, d);
    // The faces this round simulated, and those the wheel could not grind, into the summary.
    const auto countFaces = [&] {
      evaluations += residual.cache.evaluations;
      a.summary.unsolvableFaces += residual.cache.unsolvable;
    };
    if (round == 0) residual.seed(theta, start);
    bool refused = false;
    if (!solveLeastSquares(residual, theta, o.solver, a.summary,
                           "neither an identified axis direction nor the wheel's profile", &refused)) {
      countFaces();
      if (round > 0) {
        PE = keptPE, PW = keptPW, theta = keptTheta;
        a.summary.status = SolveStatus::Stalled;
        a.summary.reason = "stalled: the directions decided at the solution leave a face that cannot be simulated; "
                           "the estimate before is kept.";
        break;
      }
      a.summary.status = SolveStatus::Failed;
      a.summary.reason = refused ? "failed: the solver refused its inputs."
                                 : "failed: the face of the estimate cannot be simulated.";
      theta.setZero();
      current = start;
      break;
    }
    // theta is the best iterate: the solver only ever accepts steps that reduce the sum of squares.
    const GroundFace* f = residual.sensitiveFaceAt(theta);
    countFaces();
    if (!f) {
      // No sensitivities at the estimate (its envelope equations are singular there): the estimate
      // before this round is kept (none in the first).
      PE = keptPE, PW = keptPW, theta = keptTheta;
      a.summary.status = SolveStatus::Stalled;
      a.summary.reason = "stalled: at the estimate the face's envelope equations are singular (no sensitivities); "
                         "the estimate before is kept.";
      break;
    }
    current = *f;
    zE = VE * theta.head(VE.cols());
    w = VW * theta.tail(VW.cols());
    keptPE = PE, keptPW = PW, keptTheta = theta;
    if (a.summary.status != SolveStatus::Converged || a.summary.iterations >= o.solver.maxIterations) break;
  }
  if (theta.size() == 0) {
    a.summary.status = SolveStatus::Converged;
    a.summary.reason = "converged: the measurement shows nothing above the probe noise that the axes or the wheel "
                       "can make.";
  }
  const int kE = static_cast<int>(PE.cols()), kW = static_cast<int>(PW.cols());
  a.face = current;
  a.summary.faceEvaluations = evaluations;
  a.coefficientError = kE > 0 ? Eigen::VectorXd(PE * theta.head(kE)) : Eigen::VectorXd::Zero(q);
  m.deviation = kW > 0 ? Eigen::VectorXd(PW * theta.tail(kW)) : Eigen::VectorXd::Zero(K);
  a.error = run;
  for (Axis x : kAxes) std::fill(a.error[x].a.begin(), a.error[x].a.end(), 0.0);
  for (int j = 0; j < q; ++j) a.error[cs[j].axis].a[cs[j].degree] = a.coefficientError(j);
  a.explained = measured;
  for (int i = 0; i < grid.rows(); ++i)
    for (int j = 0; j < grid.cols(); ++j) a.explained(i, j) = kMicrometresPerMm * current.envelope[i * grid.cols() + j].t;
  a.unexplained = measured - a.explained;
  a.summary.finalCost = a.unexplained.squaredNorm();
  judgeMisfit(a.summary, a.summary.finalCost, static_cast<int>(d.size()), o.probeNoise);

  // E's covariance with W free: (J^T J)^-1 of the decided directions, its axes' block.
  a.jacobian = sensitivityMatrix(current, cs).normal;
  a.nuisance = wheelOffsetSensitivity(current, wheelBasis).normal * PW;
  const Eigen::MatrixXd JE = a.jacobian * PE;
  a.covariancePerNoise = Eigen::MatrixXd::Zero(q, q);
  if (kE + kW > 0) {
    Eigen::MatrixXd J(d.size(), kE + kW);
    J.leftCols(kE) = JE;
    J.rightCols(kW) = a.nuisance;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(JtJ);
    const Eigen::MatrixXd cov = ldlt.solve(Eigen::MatrixXd::Identity(JtJ.rows(), JtJ.cols()));
    if (cov.allFinite() && kE > 0) a.covariancePerNoise = PE * cov.topLeftCorner(kE, kE) * PE.transpose();
  }
  m.axesSpan = orthonormalSpan(JE);
  return m;
}

}  // namespace hobsharp
