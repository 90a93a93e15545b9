// The wheel surface of a case (docs/case-format.md §The wheel's profile): the conjugate wheel, or
// one dressed with wheel.profileOffset, or a measured wheel, wheel.measuredProfile, projected onto
// the conjugate profile. Both are checked against the wheel's contact range.
#pragma once

#include "case_input.h"
#include "outcome.h"
#include "sharpening_setup.h"
#include "wheel_surface.h"

namespace hobsharp {

// The range of conjugate wheel radii R that grinds the face from the gash root to the tip, mm.
struct ContactRange {
  double min = 0, max = 0;
};
Outcome<ContactRange> wheelContactRange(const SharpeningSetup& setup, double rootRadius, double outerRadius);

// The largest |offset| taken, µm: 10 mm, as for a measured deviation.
constexpr double kMaxWheelOffset = 1e4;

// `setup` without a wheel offset; rootRadius and outerRadius the face's radii, mm.
Outcome<WheelSurface> resolveWheelSurface(const CaseInput& in, const SharpeningSetup& setup, double rootRadius,
                                          double outerRadius);

}  // namespace hobsharp
