#include "direction_decision.h"

#include <cmath>

namespace hobsharp {
namespace {

// Directions whose singular value is below this share of the largest are numerically null.
constexpr double kNumericalRank = 1e-12;
// Wild directions are taken when they leave at most this share of the misfit the others leave.
constexpr double kExplainedShare = 0.01;

}  // namespace

DirectionDecision decideDirections(const Eigen::VectorXd& s, const Eigen::VectorXd& c, double dataNorm, int points,
                                   const CorrectionOptions& o, Wild rule) {
  DirectionDecision d;
  d.used.assign(static_cast<size_t>(s.size()), false);
  if (s.size() == 0 || !(s(0) > 0)) return d;
  // The step the strongest direction needs to make the whole data: the yardstick of "wild".
  const double yardstick = dataNorm / s(0);
  std::vector<int> wild;
  double misfit = dataNorm * dataNorm;  // what the directions taken leave, linearised
  for (int i = 0; i < s.size(); ++i) {
    if (s(i) <= kNumericalRank * s(0)) continue;  // numerically null: neither counted nor used
    if (std::abs(c(i)) <= o.significance * o.probeNoise) {
      ++d.withinNoise;
    } else if (std::abs(c(i)) / s(i) > o.spanAmplification * yardstick) {
      wild.push_back(i);
    } else {
      d.used[static_cast<size_t>(i)] = true;
      misfit -= c(i) * c(i);
    }
  }
  // The wild directions too where the data need them: the misfit without them is above the noise
  // floor, and with them it falls within the floor or to kExplainedShare of what it was. A shape
  // they only chase (a radial shape the wheel makes) is left out: it would take wild moves.
  double misfitWith = misfit;
  for (int i : wild) misfitWith -= c(i) * c(i);
  const double floor = noiseFloor(points, o);
  if (rule == Wild::TakenWhenNeeded && misfit > floor && misfitWith <= std::max(floor, kExplainedShare * misfit))
    for (int i : wild) d.used[static_cast<size_t>(i)] = true;
  else
    d.amplifying = static_cast<int>(wild.size());
  for (int i = 0; i < s.size(); ++i)
    if (d.used[static_cast<size_t>(i)]) d.kept.push_back(i);
  return d;
}

}  // namespace hobsharp
