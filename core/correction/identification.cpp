#include "identification.h"

#include <algorithm>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "face_vectors.h"
#include "levenberg_marquardt.h"
#include "solve_report.h"

namespace hobsharp {
namespace {

// The residual of a trial face the wheel cannot grind: so large that the step is always rejected
// (the trust region shrinks), µm.
constexpr double kUnsolvableResidual = 1e12;

// r(theta) = face(x(theta)) - measured, µm, with x_b = P_b theta_b; its Jacobian [J_b(x) P_b].
// The faces are kept per x, since the solver asks for the residual and then the Jacobian at the
// same x: the last trial face, and apart from it the face with its sensitivities (so that the
// solution is not simulated again when the last trial step was rejected).
struct BlockResidual : Eigen::DenseFunctor<double> {
  BlockResidual(const FaceModel& m, const std::vector<Eigen::MatrixXd>& p, const Eigen::VectorXd& d)
      : Eigen::DenseFunctor<double>(columns(p), static_cast<int>(d.size())), model(m), P(p), measured(d) {}

  const FaceModel& model;
  const std::vector<Eigen::MatrixXd>& P;
  const Eigen::VectorXd& measured;
  int evaluations = 0, unsolvable = 0;  // faces simulated; of them, faces the wheel could not grind
  std::optional<GroundFace> trial;
  Eigen::VectorXd trialX;
  std::optional<GroundFace> sensitive;
  const GroundFace* borrowed = nullptr;  // the start face, not copied (2,000 points are most of a MB)
  Eigen::VectorXd sensitiveX;
  std::vector<Eigen::MatrixXd> J;  // per block, at the face with sensitivities

  static int columns(const std::vector<Eigen::MatrixXd>& p) {
    int n = 0;
    for (const auto& b : p) n += static_cast<int>(b.cols());
    return n;
  }

  std::vector<Eigen::VectorXd> valuesAt(const Eigen::VectorXd& theta) const {
    std::vector<Eigen::VectorXd> x;
    int at = 0;
    for (const auto& b : P) {
      x.emplace_back(b * theta.segment(at, b.cols()));
      at += static_cast<int>(b.cols());
    }
    return x;
  }

  const GroundFace* sensitiveFace() const { return borrowed ? borrowed : sensitive ? &*sensitive : nullptr; }
  bool sensitiveAt(const Eigen::VectorXd& x) const {
    return sensitiveFace() && sensitiveX.size() == x.size() && sensitiveX == x;
  }

  const GroundFace* faceAt(const Eigen::VectorXd& x) {
    if (sensitiveAt(x)) return sensitiveFace();
    if (trialX.size() == x.size() && trialX == x && evaluations > 0) return trial ? &*trial : nullptr;
    ++evaluations;
    auto f = model.simulate(valuesAt(x));
    trialX = x;
    if (!f) {
      ++unsolvable;
      trial.reset();
      return nullptr;
    }
    trial = std::move(f).value();
    return &*trial;
  }

  // The face at x with its sensitivities, or nullptr (no face, or its envelope equations singular).
  const GroundFace* sensitiveFaceAt(const Eigen::VectorXd& x) {
    if (sensitiveAt(x)) return sensitiveFace();
    if (!faceAt(x)) return nullptr;
    if (!model.addSensitivities(*trial, valuesAt(x))) return nullptr;
    sensitive = std::move(trial);
    trial.reset();
    trialX.resize(0);
    borrowed = nullptr;
    sensitiveX = x;
    J.clear();
    for (int b = 0; b < static_cast<int>(P.size()); ++b) J.push_back(model.jacobian(*sensitive, b));
    return &*sensitive;
  }

  // `face`, with its sensitivities and their Jacobians `jacobian`, is the face at x.
  void seed(const Eigen::VectorXd& x, const GroundFace& face, const std::vector<Eigen::MatrixXd>& jacobian) {
    borrowed = &face;
    sensitive.reset();
    sensitiveX = x;
    J = jacobian;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) {
    const GroundFace* f = faceAt(x);
    if (f) fvec = faceNormal(*f) - measured;
    else fvec.setConstant(measured.size(), kUnsolvableResidual);
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    if (!sensitiveFaceAt(x)) return -1;  // never at an accepted iterate: those were all simulated
    jac.resize(values(), inputs());
    int at = 0;
    for (size_t b = 0; b < P.size(); ++b) {
      jac.middleCols(at, P[b].cols()) = J[b] * P[b];
      at += static_cast<int>(P[b].cols());
    }
    return 0;
  }
};

// A solved round of the identification: its estimate, face, Jacobians, summary and directions.
struct Round {
  std::optional<GroundFace> solved;
  std::vector<Eigen::MatrixXd> J;
  std::vector<Eigen::VectorXd> z;
  LeastSquaresSummary summary;
  std::vector<Eigen::MatrixXd> P;
  std::vector<BlockDirections> blocks;
  Eigen::VectorXd theta;
  double cost = 0;  // its sum of squares, µm²
  BlockDecomposition atSolution;  // the first block's, made at its solution
};

Eigen::MatrixXd columnsOf(const Eigen::MatrixXd& m, const std::vector<int>& kept) {
  Eigen::MatrixXd out(m.rows(), static_cast<int>(kept.size()));
  for (size_t k = 0; k < kept.size(); ++k) out.col(static_cast<int>(k)) = m.col(kept[k]);
  return out;
}

}  // namespace

Eigen::MatrixXd Identification::covariancePerNoise(int b) const {
  const Eigen::Index n = value[static_cast<size_t>(b)].size();
  Eigen::Index at = 0;
  for (int i = 0; i < b; ++i) at += blocks[static_cast<size_t>(i)].taken.cols();
  const Eigen::MatrixXd& P = blocks[static_cast<size_t>(b)].taken;
  if (P.cols() == 0 || thetaCovariancePerNoise.rows() < at + P.cols()) return Eigen::MatrixXd::Zero(n, n);
  return P * thetaCovariancePerNoise.block(at, at, P.cols(), P.cols()) * P.transpose();
}

Outcome<Identification> identify(const FaceModel& model, const GroundFace& start, const Eigen::VectorXd& d,
                                 const std::vector<ParameterBlock>& blocks, const CorrectionOptions& o,
                                 const IdentificationWords& words) {
  if (start.size() != d.size())
    return refuse("measured", "has " + std::to_string(d.size()) + " values; the face has " +
                                  std::to_string(start.size()) + " points.");
  const int B = static_cast<int>(blocks.size());
  const int points = static_cast<int>(d.size());
  Identification id;
  id.summary.initialCost = (faceNormal(start) - d).squaredNorm();

  // The estimate: each block's z (decision units); the face at it once the solver has moved (the
  // start face until then); each block's Jacobian there.
  std::vector<Eigen::VectorXd> z;
  for (const auto& b : blocks) z.push_back(Eigen::VectorXd::Zero(b.directions.cols()));
  std::optional<GroundFace> solved;
  const auto current = [&]() -> const GroundFace& { return solved ? *solved : start; };
  const auto jacobiansAt = [&](const GroundFace& f) {
    std::vector<Eigen::MatrixXd> J;
    for (int b = 0; b < B; ++b) J.push_back(model.jacobian(f, b));
    return J;
  };
  std::vector<Eigen::MatrixXd> J = jacobiansAt(start);
  std::vector<Eigen::MatrixXd> P;
  for (const auto& b : blocks) P.emplace_back(b.directions.rows(), 0);
  for (int b = 0; b < B; ++b) id.blocks.push_back({Eigen::VectorXd(0), {}, P[static_cast<size_t>(b)]});
  Eigen::VectorXd theta(0);
  // The last solved round's directions and estimate, kept if a later round cannot start.
  std::vector<Eigen::MatrixXd> keptP = P;
  std::vector<BlockDirections> keptBlocks = id.blocks;
  Eigen::VectorXd keptTheta(0);
  std::vector<std::vector<bool>> previous;
  int evaluations = 0;
  // The first block's decomposition at current(), while the estimate has not moved since it was made.
  BlockDecomposition atCurrent;
  const bool anything = std::any_of(blocks.begin(), blocks.end(), [](const auto& b) { return b.directions.cols() > 0; });
  const auto reset = [&] {
    atCurrent = BlockDecomposition{};
    solved.reset();
    J = jacobiansAt(start);
    for (auto& v : z) v.setZero();
  };
  for (int round = 0; anything && round < kDecisionRounds; ++round) {
    // What the blocks make, linearised at the current estimate.
    Eigen::VectorXd data = d - faceNormal(current());
    for (int b = 0; b < B; ++b) {
      const ParameterBlock& block = blocks[static_cast<size_t>(b)];
      Eigen::VectorXd x = block.directions * z[static_cast<size_t>(b)];
      if (block.startValue.size() == x.size()) x += block.startValue;
      data += J[static_cast<size_t>(b)] * x;
    }
    // Block by block, off the face directions the blocks before took (Q, orthonormal). Along each
    // singular direction of a block's columns the data's component is the probe noise plus the
    // signal (direction_decision.h). The SVD goes through the QR (A = Q R, R = U S V^T): the data's
    // components are U^T (Q^T data), without the points x points factor. A grid with fewer points
    // than directions (3 x 3 at degree 4) has a wide R.
    Eigen::MatrixXd Q(points, 0);
    std::vector<BlockDirections> decided(static_cast<size_t>(B));
    std::vector<Eigen::MatrixXd> V(static_cast<size_t>(B));
    std::vector<std::vector<bool>> used;
    BlockDecomposition here;
    for (int b = 0; b < B; ++b) {
      const ParameterBlock& block = blocks[static_cast<size_t>(b)];
      BlockDirections& out = decided[static_cast<size_t>(b)];
      Eigen::MatrixXd A = J[static_cast<size_t>(b)] * block.directions;
      Eigen::VectorXd off = data;
      if (Q.cols() > 0) {
        A -= Q * (Q.transpose() * A);
        off -= Q * (Q.transpose() * off);
      }
      const int m = static_cast<int>(A.cols());
      V[static_cast<size_t>(b)] = Eigen::MatrixXd(m, 0);
      out.taken = Eigen::MatrixXd(block.directions.rows(), 0);
      if (m > 0) {
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
        const int mm = static_cast<int>(std::min(A.rows(), A.cols()));
        const Eigen::MatrixXd R = qr.matrixQR().topRows(mm).triangularView<Eigen::Upper>();
        const Eigen::MatrixXd Qa = qr.householderQ() * Eigen::MatrixXd::Identity(A.rows(), mm);
        const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
        out.singularValues = svd.singularValues();
        out.decision = decideDirections(out.singularValues, svd.matrixU().transpose() * (Qa.transpose() * off),
                                        off.norm(), points, o, block.wild);
        V[static_cast<size_t>(b)] = columnsOf(svd.matrixV(), out.decision.kept);
        if (b == 0) here = BlockDecomposition{out.singularValues, block.directions * svd.matrixV()};
        out.taken = block.directions * V[static_cast<size_t>(b)];
        if (b + 1 < B && !out.decision.kept.empty()) {
          const Eigen::MatrixXd Qb = Qa * columnsOf(svd.matrixU(), out.decision.kept);
          Eigen::MatrixXd joined(points, Q.cols() + Qb.cols());
          joined << Q, Qb;
          Q = std::move(joined);
        }
      }
      used.push_back(out.decision.used);
    }
    if (round == 0) id.firstBlockAtStart = here;
    atCurrent = here;
    if (round > 0 && used == previous) break;
    previous = used;
    id.blocks = decided;
    int k = 0;
    for (int b = 0; b < B; ++b) {
      P[static_cast<size_t>(b)] = decided[static_cast<size_t>(b)].taken;
      k += static_cast<int>(P[static_cast<size_t>(b)].cols());
    }
    // The estimate so far, in the directions decided here.
    theta.resize(k);
    for (int b = 0, at = 0; b < B; ++b) {
      const Eigen::MatrixXd& Vb = V[static_cast<size_t>(b)];
      theta.segment(at, Vb.cols()) = Vb.transpose() * z[static_cast<size_t>(b)];
      at += static_cast<int>(Vb.cols());
    }
    if (k == 0) {
      reset();
      break;
    }
    // The round before, solved and converged: kept if this one does not converge (below).
    std::optional<Round> before;
    if (round > 0 && id.summary.status == SolveStatus::Converged)
      before = Round{solved, J, z, id.summary, keptP, keptBlocks, keptTheta, (d - faceNormal(current())).squaredNorm(),
                     atCurrent};
    BlockResidual residual(model, P, d);
    const auto countFaces = [&] {
      evaluations += residual.evaluations;
      id.summary.unsolvableFaces += residual.unsolvable;
    };
    if (round == 0) residual.seed(theta, start, J);
    bool refused = false;
    if (!solveLeastSquares(residual, theta, o.solver, id.summary, words.none, &refused)) {
      countFaces();
      if (round > 0) {
        P = keptP, id.blocks = keptBlocks, theta = keptTheta;
        id.summary.status = SolveStatus::Stalled;
        id.summary.reason = "stalled: the directions decided at the solution leave a face that cannot be simulated; "
                            "the estimate before is kept.";
        break;
      }
      id.summary.status = SolveStatus::Failed;
      id.summary.reason = refused ? "failed: the solver refused its inputs."
                                  : "failed: the face of the estimate cannot be simulated.";
      theta.setZero();
      reset();
      break;
    }
    // theta is the best iterate: the solver only ever accepts steps that reduce the sum of squares.
    const GroundFace* f = residual.sensitiveFaceAt(theta);
    countFaces();
    const auto take = [&] {
      atCurrent = BlockDecomposition{};
      if (residual.sensitiveAt(theta) && residual.borrowed) solved.reset();  // still the start face
      else if (residual.sensitiveAt(theta)) solved = std::move(residual.sensitive);
      else solved = std::move(residual.trial);
      if (!residual.J.empty()) J = std::move(residual.J);
      for (int b = 0, at = 0; b < B; ++b) {
        const Eigen::MatrixXd& Vb = V[static_cast<size_t>(b)];
        z[static_cast<size_t>(b)] = Vb * theta.segment(at, Vb.cols());
        at += static_cast<int>(Vb.cols());
      }
      keptP = P, keptBlocks = id.blocks, keptTheta = theta;
    };
    if (!f) {
      // The face at the estimate was simulated (the solver accepted it), but its envelope equations
      // are singular there, so it has no sensitivities: the estimate and its face are kept, and the
      // last Jacobian formed stands for the covariance.
      if (!residual.faceAt(theta)) {
        P = keptP, id.blocks = keptBlocks, theta = keptTheta;
        id.summary.status = SolveStatus::Stalled;
        id.summary.reason = "stalled: the face of the estimate cannot be simulated again; the estimate before is kept.";
        break;
      }
      take();
      id.summary.status = SolveStatus::Stalled;
      id.summary.reason = "stalled: at the estimate the face's envelope equations are singular (no sensitivities), so "
                          "the solve cannot go on; the estimate is kept.";
      break;
    }
    take();
    if (before && id.summary.status != SolveStatus::Converged &&
        (before->cost <= noiseCeiling(points, o.probeNoise) || (d - faceNormal(current())).squaredNorm() >= before->cost)) {
      // The directions decided again at a converged solution took one the face barely shows, and
      // the search along it did not converge, where the converged estimate had explained the face
      // to the noise or this search left no less (seed 11's scenario 274 of the calibration: 45
      // iterations to 56,596 machine steps from it, both within the noise): the converged estimate
      // is kept, with its directions, face and summary.
      const int iterations = id.summary.iterations, unsolvable = id.summary.unsolvableFaces;
      const char* ended = id.summary.status == SolveStatus::NoConvergence ? "ran out of iterations" : "stalled";
      solved = std::move(before->solved), J = std::move(before->J), z = std::move(before->z);
      id.summary = std::move(before->summary);
      P = before->P, id.blocks = before->blocks, theta = before->theta;
      keptP = std::move(before->P), keptBlocks = std::move(before->blocks), keptTheta = std::move(before->theta);
      atCurrent = std::move(before->atSolution);
      id.summary.iterations = iterations, id.summary.unsolvableFaces = unsolvable;
      id.summary.reason += " The search along the " + std::to_string(k) + " directions decided again at this estimate " +
                           ended + "; this estimate is kept.";
      break;
    }
    if (id.summary.status != SolveStatus::Converged || id.summary.iterations >= o.solver.maxIterations) break;
  }
  if (BlockResidual::columns(P) == 0) {
    id.summary.status = SolveStatus::Converged;
    id.summary.reason = "converged: the measurement shows nothing above the probe noise that " + words.makers +
                        " can make.";
    theta.resize(0);
  }
  id.face = solved ? std::move(*solved) : start;
  id.summary.faceEvaluations = evaluations;
  for (int b = 0, at = 0; b < B; ++b) {
    const Eigen::MatrixXd& Pb = P[static_cast<size_t>(b)];
    id.value.push_back(Pb.cols() > 0 ? Eigen::VectorXd(Pb * theta.segment(at, Pb.cols()))
                                     : Eigen::VectorXd::Zero(Pb.rows()));
    at += static_cast<int>(Pb.cols());
  }
  id.explained = faceNormal(id.face);
  id.summary.finalCost = (d - id.explained).squaredNorm();
  judgeMisfit(id.summary, id.summary.finalCost, points, o.probeNoise);
  id.jacobian = J;
  id.firstBlockAtSolution = std::move(atCurrent);
  const int k = BlockResidual::columns(P);
  if (k > 0) {
    // (J^T J)^-1 in the taken directions, which the decision kept well conditioned.
    Eigen::MatrixXd Jt(points, k);
    for (int b = 0, at = 0; b < B; ++b) {
      Jt.middleCols(at, P[static_cast<size_t>(b)].cols()) = J[static_cast<size_t>(b)] * P[static_cast<size_t>(b)];
      at += static_cast<int>(P[static_cast<size_t>(b)].cols());
    }
    const Eigen::MatrixXd JtJ = Jt.transpose() * Jt;
    const Eigen::MatrixXd cov = Eigen::LDLT<Eigen::MatrixXd>(JtJ).solve(Eigen::MatrixXd::Identity(k, k));
    id.thetaCovariancePerNoise = cov.allFinite() ? cov : Eigen::MatrixXd::Zero(k, k);
  }
  return id;
}

}  // namespace hobsharp
