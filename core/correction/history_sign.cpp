#include "history_sign.h"

#include <algorithm>
#include <cmath>

#include "coefficient.h"
#include "face_vectors.h"
#include "sensitivity_matrix.h"

namespace hobsharp {
namespace {

// Reversed: the measured change is at most minus half the predicted one along it (as simulated it
// is +1 up to what the identification missed; reversed, -1 up to the same).
constexpr double kReversedAlong = -0.5;
// ... and the two changes point nearly opposite ways (the measured one is mostly minus the predicted).
constexpr double kReversedCosine = 0.8;
// Both the predicted change and the measured component along it exceed this many sigma sqrt 2 (the
// noise of a difference of two faces along one direction): pure noise does so about once in 1.7
// million draws.
constexpr double kSignSigmas = 5;
// The sigma the test takes where the case declares less (a noise-free declaration): µm.
constexpr double kSignFloor = 0.01;

}  // namespace

std::optional<HistorySign> historySign(const GroundFace& runFace, const AxisPolynomials& run,
                                       const Eigen::MatrixXd& measured, const EarlierPass& last, double probeNoise,
                                       bool joined) {
  if (last.measured.rows() != measured.rows() || last.measured.cols() != measured.cols() ||
      measured.size() != runFace.size())
    return std::nullopt;
  const std::vector<Coefficient> all = allCoefficients(run.degree());
  Eigen::VectorXd change(static_cast<int>(all.size()));
  for (size_t j = 0; j < all.size(); ++j)
    change(static_cast<int>(j)) =
        run[all[j].axis].coefficient(all[j].degree) - last.axes[all[j].axis].coefficient(all[j].degree);
  const Eigen::VectorXd predicted = sensitivityMatrix(runFace, all).normal * change;  // Eq. 17's S, µm
  const Eigen::VectorXd moved = flat(measured) - flat(last.measured);
  const double noise = std::max(probeNoise, kSignFloor) * std::sqrt(2.0);
  const double size = predicted.norm();
  if (!(size > kSignSigmas * noise)) return std::nullopt;
  HistorySign s;
  s.predictedRms = size / std::sqrt(static_cast<double>(predicted.size()));
  const double component = moved.dot(predicted) / size;
  s.along = component / size;
  s.alongSigmas = component / noise;
  const double movedSize = moved.norm();
  s.cosine = movedSize > 0 ? component / movedSize : 0.0;
  s.reversed = !joined && s.along <= kReversedAlong && s.cosine <= -kReversedCosine && -s.alongSigmas > kSignSigmas;
  return s;
}

const EarlierPass* earlierAtSamePoints(const PassHistory& history, const ProbePoints& probes) {
  if (!history.lastAtPoints || history.lastPoints.size() != probes.size()) return nullptr;
  for (size_t k = 0; k < probes.size(); ++k)
    if (std::abs(history.lastPoints[k].r - probes[k].r) > 1e-9 || std::abs(history.lastPoints[k].x - probes[k].x) > 1e-9)
      return nullptr;
  return &*history.lastAtPoints;
}

}  // namespace hobsharp
