// The dressed wheel's axial profile and a measured one read back as a profile offset
// (wheel_surface.h): the conjugate profile of Eq. 6 (docs/errata.md) moved along its normal.
#pragma once

#include <string>
#include <vector>

#include "outcome.h"
#include "sharpening_setup.h"
#include "wheel_profile.h"

namespace hobsharp {

// Per point of a conjugate profile: its radius R, the offset delta(R) and the dressed point.
struct DressedProfile {
  std::vector<double> r;       // tooth-face radius of the conjugate point, mm
  std::vector<double> R;       // conjugate wheel radius, mm
  std::vector<double> offset;  // delta(R), mm (+ = more wheel)
  std::vector<double> dressedR, dressedZ;  // the dressed wheel's axial profile, mm
};

// The profile of setup.wheel at the points of `conjugate` (wheelProfile() of the same setup).
DressedProfile dressedProfile(const SharpeningSetup& setup, const WheelProfile& conjugate);

// A measured axial profile (R_i, Z_i) projected onto the conjugate profile: for each point the
// conjugate point whose normal passes through it, and the offset along that normal,
// delta = -(P - p) . n. The conjugate profile is searched between the tooth-face radii rLow and
// rHigh; a point whose normal foot is not there is refused as `field`[i].
struct ProjectedProfile {
  std::vector<double> r;       // tooth-face radius of the foot, mm
  std::vector<double> R;       // conjugate wheel radius of the foot, mm
  std::vector<double> offset;  // mm
};
Outcome<ProjectedProfile> projectOntoConjugateProfile(const SharpeningSetup& setup, const std::vector<double>& R,
                                                      const std::vector<double>& Z, double rLow, double rHigh,
                                                      const std::string& field);

}  // namespace hobsharp
