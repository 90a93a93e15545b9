// The per-gash indexing correction of the A axis that removes the spacing error (docs/inspection.md). The A axis turns the hob: with A + dA the wheel, and so the ground face,
// is turned by -dA about the hob axis (Eq. 7, r_1 = Rx(-A) ...), which moves a face point p by
// -dA (x_1 x p). Along the outward normal n that is a deviation of -dA n . (x_1 x p).
#pragma once

#include <vector>

#include "sharpening_setup.h"

namespace hobsharp {

// The normal deviation per radian of A at the face point at radius r and axial position x, µm/rad.
double deviationPerIndexAngle(const SharpeningSetup& setup, double r, double x);

struct IndexCorrection {
  double perRadian = 0;          // µm of deviation at the pitch radius per rad of A
  std::vector<double> angle;     // rad per gash: add to the gash's index position of A
  std::vector<double> rounded;   // the same, rounded to whole steps of the A axis
  std::vector<double> after;     // µm: the gash deviations predicted after running `rounded`
};

// Turns every gash by the angle that brings its deviation to the mean of all (a common offset is
// a thickness change, not a spacing error, and is left as it is), then rounds it to `stepRad`
// (the A axis's resolution, rad; 0 leaves it unrounded).
IndexCorrection indexCorrection(const std::vector<double>& deviations, double perRadian, double stepRad);

}  // namespace hobsharp
