// Which directions of the linearised face an identification takes (identification.h; docs/method.md,
// "Correction"). Along each singular direction of the Jacobian the data's
// component c_i is the probe noise (sigma per point) plus the signal:
//   - a direction is left out as within the noise when |c_i| <= significance * sigma;
//   - a direction whose step |c_i| / s_i exceeds spanAmplification times the step the strongest
//     direction needs to make the whole data is wild: the wild directions are taken only when the
//     misfit without them is above the noise floor (points * sigma²) and with them it falls within
//     the floor or to 1 % of what it was: the data need them, and they explain it. Otherwise they
//     would chase a shape no axis makes (a radial shape the wheel makes) with wild moves.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "correction_options.h"

namespace hobsharp {

struct DirectionDecision {
  std::vector<bool> used;  // per singular value, largest first
  std::vector<int> kept;   // the used directions' indices
  int withinNoise = 0;     // left out: within the probe noise
  int amplifying = 0;      // left out: wild, and the misfit is within the noise floor without them
};

// s: singular values, largest first; c: the data's components along the left singular vectors;
// dataNorm: |data|; points: the measured values (the noise floor's count). With
// Wild::LeftOut the wild directions are never taken: the axes' and the wheel's directions when the
// wheel is in the model (wheel_error.h), where a wild direction of either chases the other's shapes.
enum class Wild { TakenWhenNeeded, LeftOut };
DirectionDecision decideDirections(const Eigen::VectorXd& s, const Eigen::VectorXd& c, double dataNorm, int points,
                                   const CorrectionOptions& o, Wild wild = Wild::TakenWhenNeeded);

// The noise floor of a misfit over `points` measured values: points * sigma², µm².
inline double noiseFloor(int points, const CorrectionOptions& o) { return points * o.probeNoise * o.probeNoise; }

}  // namespace hobsharp
