#include "face_prediction.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "face_vectors.h"
#include "fold_margin.h"
#include "probe_points.h"
#include "sensitivity_matrix.h"
#include "topography.h"

namespace hobsharp {
namespace {

// Samples of the error the face cannot show, and their seed: the same figures on every run.
constexpr int kUnseenSamples = 6;
// The size of the error the face cannot show, per term, as a multiple of the identified error's.
constexpr double kUnseenScale = 2;
// The share of the identified error along the axis changes that mimic the wheel taken as the wheel's.
constexpr double kMimicScale = 2;
constexpr unsigned kUnseenSeed = 20;
// A direction of the coefficients moves the face no more than this share of the strongest one: it
// is a direction the face cannot show.
constexpr double kUnseenShare = 1e-4;
// The same over the faces of several passes (shownBy): their singular values fall with no gap
// down to about 1e-6 of the strongest, and the identification takes directions that far (faces at
// two operating points show what one face does not). Set on the campaign's seed 20261125 and
// checked on seeds 3, 7, 11 and 2026 (docs/validation.md): 1e-4 here makes the bound 10 to 100
// times the face left on passes that end at nanometres.
constexpr double kUnseenShareJoined = 1e-6;
// The fold check warns where a point's envelope determinant is less than this many times its worst
// first-order change within the samples' radius (fold_margin.h): the first order in one Newton step
// understates the change near a fold. Set on campaign seeds 1001 to 1030 and 7010 to 7015 (28,641
// passes; docs/validation.md, "The fold check"): with it, 98 of the 103 proposals the true machine
// does not grind in full carry a warning (7 of the 8 that said "Correctable"; at 1.5, 97 and 6; at
// 1, 92 and 4), and about 530 more verdicts say "Uncertain:" (330 at 1.5, 130 at 1).
constexpr double kFoldMargin = 2;
// The unseen part is sampled at no more than this many of the face's points, evenly through them:
// an rms over a couple of hundred points is as good a figure, at a tenth of the cost for a
// measuring machine's 2,000.
constexpr int kUnseenPoints = 200;

// `f` at the points `at` only, as probe points (warm starts from f's solutions, ground_face.h).
GroundFace pointsOf(const GroundFace& f, const std::vector<int>& at) {
  GroundFace s;
  s.gash = f.gash;
  s.grid = f.grid;
  s.meanPoint = f.meanPoint;
  s.meanEnvelope = f.meanEnvelope;
  for (int i : at) {
    s.points.push_back(f.points[static_cast<size_t>(i)]);
    s.envelope.push_back(f.envelope[static_cast<size_t>(i)]);
    s.probes.push_back(ProbePoint{f.points[static_cast<size_t>(i)].r, f.points[static_cast<size_t>(i)].x});
  }
  return s;
}

Eigen::MatrixXd rowsOf(const Eigen::MatrixXd& m, const std::vector<int>& at) {
  Eigen::MatrixXd out(static_cast<int>(at.size()), m.cols());
  for (size_t k = 0; k < at.size(); ++k) out.row(static_cast<int>(k)) = m.row(at[k]);
  return out;
}

// S's singular values, largest first, and its right singular vectors (S = U S V^T, V's columns in
// the same order), from the eigen-decomposition of S^T S: s_i = sqrt(lambda_i). The bound needs only
// the directions above kUnseenShare (1e-4 s_0: an eigenvalue of 1e-8 of the largest, far above
// S^T S's rounding, about 1e-15 of it) and the two subspaces the share splits, not the directions
// within them; the 25 x 25 eigenproblem costs a third of JacobiSVD's 45 x 25 SVD.
struct RightSingular {
  Eigen::VectorXd values;
  Eigen::MatrixXd V;
};
RightSingular rightSingularOf(const Eigen::MatrixXd& S) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e(S.transpose() * S);
  RightSingular r;
  // The solver's eigenvalues are increasing; a null direction's may round below 0.
  r.values = e.eigenvalues().reverse().cwiseMax(0.0).cwiseSqrt();
  r.V = e.eigenvectors().rowwise().reverse();
  return r;
}

}  // namespace

std::string predictionCondition(const Correction& c) {
  std::string axes;
  if (c.predictedUnseenPart > 0)
    axes = c.predictedWheelAlike
               ? "if the error the face cannot show, or cannot tell from the wheel's shape, is no larger than the one it shows"
               : "if the error the face cannot show is no larger than the one it shows";
  if (c.wheelKnots == 0) return axes;
  const std::string wheel = "if the wheel's shape between the probe rows is one a smooth curve through its " +
                            std::to_string(c.wheelKnots) + " points makes (the probe grid does not show the wheel between its rows)";
  return axes.empty() ? wheel : axes + ", and " + wheel;
}

std::string predictionText(const Correction& c) {
  std::ostringstream leaves;
  leaves.precision(3);
  // The bound alone (issue 20: the verdict quotes the bound and never a figure below it): the model's
  // figure, predictedRms, is what the pass leaves only if the identified error is all of the
  // machine's: on ten campaign seeds (6,409 passes) the face left on the probe grid was more than
  // three times it plus 0.02 µm in 40 % of them, and above the bound in 5 % (docs/method.md).
  // Below the pass's floor (machine_resolution.h): the exact axes' figure is not what the machine,
  // which quantises each axis position to its step, can hold; no pass promises a face below it.
  const bool belowFloor = c.resolutionFloor > c.predictedRmsHigh;
  leaves << "the face measured " << c.before.rms << " µm rms will be left at most " << c.predictedRmsHigh << " µm rms"
         << (belowFloor ? " with the exact axes" : "");
  const std::string condition = predictionCondition(c);
  if (!condition.empty()) leaves << " " << condition;
  if (belowFloor)
    leaves << "; quantising each axis position to the machine's resolution sets a floor of about " << c.resolutionFloor
           << " µm rms, which no pass goes below";
  return leaves.str();
}

FacePrediction predictFace(const SharpeningSetup& measuredSetup, const SharpeningSetup& passSetup,
                           const AxisPolynomials& run, const GroundFace& runFace, const Correction& c,
                           const Eigen::MatrixXd& unexplained, double sigma, const UnseenSampling& sampling) {
  FacePrediction p;
  const double n = std::max(1, runFace.size());
  const int k = c.rank;
  // The misfit is noise (sigma² per point, less what the k directions took) plus shape.
  const double afterSquares = c.after.normal.squaredNorm();
  const double noiseSquares = sigma * sigma * std::max(0.0, n - k);
  p.rms = std::sqrt(std::max(0.0, afterSquares - noiseSquares) / n);
  // A stop changes nothing: no noise is carried into the axes.
  p.noisePart = c.stop ? 0.0 : std::sqrt(sigma * sigma * (k + 3 * std::sqrt(2.0 * k)) / n);

  // The error the face cannot show: in units of the tip's displacement, per term at the range's end.
  const std::vector<Coefficient>& cs = c.coefficients;
  const int q = static_cast<int>(cs.size());
  if (q > 0) {
    const MotionRange range = motionRange(runFace);
    const double reach = std::max({std::abs(range.min), std::abs(range.max), 1e-12});
    const double tip = runFace.grid.r.empty() ? 1.0 : runFace.grid.r.back();
    Eigen::VectorXd w(q), y(q);
    for (int j = 0; j < q; ++j) {
      w(j) = std::pow(reach, cs[j].degree) * (isRotary(cs[j].axis) ? tip : 1.0);
      y(j) = c.identifiedError[cs[j].axis].coefficient(cs[j].degree) * w(j);
    }
    const double size = kUnseenScale * y.norm() / std::sqrt(static_cast<double>(q));
    // The points sampled: all of them on a small face, else kUnseenPoints evenly through them.
    const bool subset = runFace.size() > kUnseenPoints;
    std::vector<int> at;
    if (subset)
      for (int i = 0; i < kUnseenPoints; ++i) at.push_back(static_cast<int>(static_cast<long long>(i) * runFace.size() / kUnseenPoints));
    const GroundFace sampled = subset ? pointsOf(runFace, at) : GroundFace{};
    const GroundFace& like = subset ? sampled : runFace;
    const double m = subset ? kUnseenPoints : n;
    const Eigen::MatrixXd Sall = sensitivityMatrix(runFace, cs).normal;
    const Eigen::MatrixXd S = (subset ? rowsOf(Sall, at) : Sall) * w.cwiseInverse().asDiagonal();
    const RightSingular svd = rightSingularOf(S);
    const Eigen::VectorXd& s = svd.values;
    std::vector<int> unseen, seen, ownUnseen;
    for (int i = 0; i < q; ++i) (i >= s.size() || s(i) <= kUnseenShare * s(0) ? unseen : seen).push_back(i);
    // The face directions the axes make: the left singular vectors u_i = S v_i / s_i (S = U S V^T),
    // formed for the seen directions only (s_i above 1e-4 s_0). At E = 0, the run face's: the span
    // of the sensitivities at the identified error (the identification's last Jacobian) was tried,
    // and on campaign seeds 1001 to 1005 the bound held in 2 fewer of 2,950 noise-free passes and
    // informed in 4 fewer of 3,214.
    Eigen::MatrixXd U(S.rows(), static_cast<int>(seen.size()));
    for (size_t i = 0; i < seen.size(); ++i)
      U.col(static_cast<int>(i)).noalias() = S * svd.V.col(seen[i]) / s(seen[i]);
    // What none of the faces identified from shows: those of the history too, when given (by the SVD:
    // over several passes the share is 1e-6, which S^T S reads only to about 1e-4 of itself).
    std::optional<Eigen::JacobiSVD<Eigen::MatrixXd>> all;
    if (sampling.shownBy && sampling.shownBy->cols() == q) {
      all.emplace(*sampling.shownBy * w.cwiseInverse().asDiagonal(), Eigen::ComputeFullV);
      const Eigen::VectorXd t = all->singularValues();
      ownUnseen = unseen;
      unseen.clear();
      // Over several passes, also a direction the faces show so weakly that the probe noise alone
      // moves it by more than the samples' size per term (sigma / t_i, tip displacement): the faces
      // hold it, but not to within the error's own size, and a noise-free face explained to the
      // probe noise says no more of it (docs/method.md, "What the pass will leave").
      for (int i = 0; i < q; ++i)
        if (i >= t.size() || t(i) <= (sampling.passes ? kUnseenShareJoined : kUnseenShare) * t(0) ||
            (sampling.passes && sigma > size * t(i)))
          unseen.push_back(i);
    }
    const Eigen::MatrixXd& V = all ? all->matrixV() : svd.V;
    // With the wheel alongside: the identified error's part along the axis changes that mimic a wheel
    // shape (in the same units, y's), which the face cannot tell from the wheel: the error if all of
    // it were the wheel's (face_prediction.h, `mimicking`).
    Eigen::VectorXd mimic(0);
    if (sampling.mimicking && sampling.mimicking->rows() == q && sampling.mimicking->cols() > 0) {
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(w.asDiagonal() * *sampling.mimicking);
      qr.setThreshold(1e-8);
      const Eigen::MatrixXd Q = Eigen::MatrixXd(qr.householderQ()).leftCols(qr.rank());
      mimic = Q * (Q.transpose() * y);
    }
    Eigen::MatrixXd N(q, static_cast<int>(unseen.size()));
    for (size_t i = 0; i < unseen.size(); ++i) N.col(static_cast<int>(i)) = V.col(unseen[i]);
    // Joined, and linearised at the nominal axes (the axes run alone grind no face): the earlier
    // face shows the directions this face does not only through a model run far from any face the
    // wheel grinds, and one error explaining both faces need not be the machine's (seeds 9001 to
    // 9005, 3,000 scenarios: the face left exceeded the bound in 25 of 70 such passes when it
    // sampled what the joined faces do not show at 1e-6 of the strongest, in 19 with the weak
    // directions above as well, by 193 times on seed 9005's scenario 164). What this face
    // alone does not show is sampled as well: no such pass exceeds its bound, and 69 of the 70
    // bounds are more than 10 times the face left (docs/method.md, "What the pass will leave").
    if (all && sampling.passes && c.linearisedAtNominal && !ownUnseen.empty()) {
      Eigen::MatrixXd both(q, N.cols() + static_cast<int>(ownUnseen.size()));
      both.leftCols(N.cols()) = N;
      for (size_t i = 0; i < ownUnseen.size(); ++i) both.col(N.cols() + static_cast<int>(i)) = svd.V.col(ownUnseen[i]);
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(both);
      qr.setThreshold(1e-8);
      N = Eigen::MatrixXd(qr.householderQ()).leftCols(qr.rank());
    }
    const int unseenCount = static_cast<int>(N.cols());
    if (size > 0 && (unseenCount > 0 || mimic.size() > 0)) {
      const AxisPolynomials actual = plusError(c.axes, c.identifiedError);
      const AxisPolynomials measuredAt = plusError(run, c.identifiedError);
      Eigen::VectorXd base = flat(c.after.normal) - flat(unexplained);      // the model's face after
      Eigen::VectorXd explained = flat(c.before.normal) - flat(unexplained);  // ... at the measurement
      if (subset) {
        base = rowsOf(base, at);
        explained = rowsOf(explained, at);
      }
      // The face the pass grinds on the identified machine, at the sampled points: the fold check's
      // (below), and the base of the moves where they are measured from re-simulated faces.
      std::optional<Outcome<GroundFace>> ground;
      if (sampling.fromResimulated || unseenCount > 0)
        ground = simulateGroundFaceLike(like, passSetup, actual, Sensitivities::Skip, FaceStart::Near);
      if (sampling.fromResimulated) {
        auto before0 = simulateGroundFaceLike(like, measuredSetup, measuredAt, Sensitivities::Skip, FaceStart::Near);
        if (*ground && before0) base = faceNormal(**ground), explained = faceNormal(*before0);
      }
      double worst = 0;
      // The face the pass leaves with the error changed by dc (coefficient units), less what the
      // identification would take of that change at the measurement.
      const auto sample = [&](const Eigen::VectorXd& dc, double scale) {
        // Started from the run face's solutions on a grid too: the bound is a figure, no decision
        // rests on its last bits.
        auto after = simulateGroundFaceLike(like, passSetup, plusChange(actual, cs, dc), Sensitivities::Skip, FaceStart::Near);
        auto before = simulateGroundFaceLike(like, measuredSetup, plusChange(measuredAt, cs, dc), Sensitivities::Skip,
                                             FaceStart::Near);
        if (!after || !before) {
          // Only the pass's face speaks of the pass: an error with which the face measured cannot be
          // simulated is one the measurement does not bear out, not a part the pass leaves unground.
          if (!after) ++p.ungrindable;
          worst = std::max(worst, std::sqrt(afterSquares / n) + scale * 1e3);  // cannot say: as large as the error
          return;
        }
        const Eigen::VectorXd moved = faceNormal(*before) - explained;
        const Eigen::VectorXd left = faceNormal(*after) - base - U * (U.transpose() * moved);
        worst = std::max(worst, std::sqrt(left.squaredNorm() / m));
      };
      if (unseenCount > 0) {
        // mt19937's words are the same in every build; the standard's distributions are not (libstdc++
        // natively, libc++ in WebAssembly): each term uniform on +-sqrt(3), of unit variance.
        std::mt19937 rng(kUnseenSeed);
        const auto g = [&rng] { return std::sqrt(3.0) * (2.0 * rng() / 4294967295.0 - 1.0); };
        for (int t = 0; t < kUnseenSamples; ++t) {
          Eigen::VectorXd d(q);
          for (int j = 0; j < q; ++j) d(j) = g() * size;
          sample((N * (N.transpose() * d)).cwiseQuotient(w), size);  // what the face cannot show
        }
      }
      // The fold check: on the face the pass grinds, how near each point is to a fold, with an error
      // the face cannot show of the samples' radius (sqrt(#unseen) times the size per term) along
      // each of those directions (fold_margin.h).
      if (unseenCount > 0 && *ground) {
        const GroundFace& face = **ground;
        const double radius = size * std::sqrt(static_cast<double>(unseenCount));
        std::vector<AxisPolynomials> moved;
        for (int d = 0; d < N.cols(); ++d) moved.push_back(plusChange(actual, cs, (radius * N.col(d)).cwiseQuotient(w)));
        const FoldMargin fold = foldMargin(face, passSetup, actual, moved);
        p.foldMargin = fold.margin;
        if (fold.margin < kFoldMargin) p.foldAt = face.points[static_cast<size_t>(fold.at)];
      }
      // The error less kMimicScale times that part, the wheel taking it: the face the pass then
      // leaves, where the axes' mimicry of the wheel's shape holds at the measurement only.
      if (mimic.size() > 0) {
        sample((-kMimicScale * mimic).cwiseQuotient(w), kMimicScale * mimic.norm() / std::sqrt(static_cast<double>(q)));
        p.wheelAlike = true;
      }
      p.unseenPart = worst;
    }
  }
  // The misfit's shape: at most what it holds beyond the noise's expectation less three of the
  // noise's standard deviations (chi-square, n - k degrees of freedom).
  const double dof = std::max(0.0, n - k);
  // A stop keeps the face measured: all of its misfit may be shape.
  const double shapeSquares =
      c.stop ? afterSquares
             : std::min(afterSquares, std::max(0.0, afterSquares - noiseSquares + 3 * sigma * sigma * std::sqrt(2 * dof)));
  p.rmsHigh = std::sqrt(shapeSquares / n + p.noisePart * p.noisePart + p.unseenPart * p.unseenPart);
  return p;
}

}  // namespace hobsharp
