// The profile figures of one flank of the gear (docs/gear-effect.md), after ISO 1328-1:
// the mean profile line is the least-squares straight line of the profile deviation over the
// evaluation range;
//   profile slope deviation fH_alpha - the rise of that line from the start of the range (gear
//                                      root side) to its end (tip side); plus = more material
//                                      toward the tip, a smaller pressure angle;
//   pressure-angle error             - -fH_alpha / L_alpha, L_alpha the range's length along the
//                                      flank (heights / cos alpha_n);
//   profile form deviation ff_alpha  - the width of the band about the mean profile line that
//                                      holds the whole profile.
#pragma once

#include <vector>

namespace hobsharp {

struct ProfileFigures {
  double slope = 0;          // fH_alpha, µm
  double pressureAngle = 0;  // rad
  double form = 0;           // ff_alpha, µm, >= 0
};

// `height` on the gear tooth (mm, increasing toward the tip), `deviation` there (µm, plus = more
// material on the gear), at least 2 points; `pressureAngle` the flank's, rad.
ProfileFigures profileFigures(const std::vector<double>& height, const std::vector<double>& deviation,
                              double pressureAngle);

}  // namespace hobsharp
