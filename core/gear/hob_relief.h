// The hob's relief (docs/case-format.md, `hob.gashes`, `hob.relief`, `hob.sideReliefAngle`).
//
// A radially relieved hob tooth: behind the cutting edge the whole thread profile drops radially
// by the cam's relief K over one gash pitch 2 pi / z (an Archimedean cam), so at an angle psi
// behind the rake face the profile lies k psi lower, k = K z / 2 pi (mm/rad, `reliefPerRadian`).
// On a flank of normal pressure angle alpha_n that drop moves the flank by k psi sin(alpha_n)
// along its normal, over an arc of r psi: tan(side relief angle at r) = (k / r) sin(alpha_n).
#pragma once

#include <optional>
#include <string>

#include "outcome.h"

namespace hobsharp {

struct HobReliefInput {
  std::optional<int> gashes;             // z, number of gashes
  std::optional<double> relief;          // K, radial relief over one gash pitch, mm
  std::optional<double> sideReliefAngle;  // deg, at the pitch radius
};

// How far the side relief angle implied by hob.relief and hob.gashes may differ from
// hob.sideReliefAngle when the case gives all three, deg.
constexpr double kSideReliefAgreement = 0.01;
// The most gashes a hob may have (as inspection.gashDeviations).
constexpr int kMaxHobGashes = 100;
// The largest side relief angle taken, deg.
constexpr double kMaxSideReliefAngle = 30;

// hob.gashes a whole number from 1 to kMaxHobGashes, hob.relief positive and below the hob's outer
// radius, hob.sideReliefAngle over 0 up to kMaxSideReliefAngle, and, when the case gives the relief
// and the side relief angle, the gashes too and the two agreeing to kSideReliefAgreement at the
// pitch diameter; the hob's diameters in mm, its normal pressure angle in deg. The refusal names
// the hob.* field.
Outcome<void> checkRelief(const HobReliefInput& relief, double outerDiameter, double pitchDiameter,
                          double normalPressureAngle);

// k = K z / 2 pi, mm/rad.
double reliefPerRadianFromCam(double relief, int gashes);
// k from the side relief angle (rad) at the pitch radius r_p: k = r_p tan(angle) / sin(alpha_n).
double reliefPerRadianFromSideAngle(double sideAngle, double pitchRadius, double normalPressureAngle);
// The side relief angle (rad) at `radius`: atan((k / r) sin(alpha_n)).
double sideReliefAngleAt(double reliefPerRadian, double radius, double normalPressureAngle);

// The relief per radian the case gives (from the side relief angle when given, else from the cam
// relief and the gashes), or, when it gives none, the sentence that says what is missing.
struct ReliefPerRadian {
  std::optional<double> value;  // mm/rad
  std::string missing;          // "" when `value` holds
};
ReliefPerRadian reliefPerRadian(const HobReliefInput& in, double pitchRadius, double normalPressureAngle);

}  // namespace hobsharp
