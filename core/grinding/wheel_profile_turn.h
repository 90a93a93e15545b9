// Where the conjugate wheel's axial profile turns back (docs/method.md, "The edge of the wheel's
// envelope"). Along the face's radius r the contact point of Eq. 5 traces the wheel's meridian
// (R, Z) of Eq. 6; its speed along the meridian's tangent (n_Z, -n_R) keeps one sign while the
// profile runs one way. Where the speed passes through zero the profile stops and runs back over
// itself (a cusp of the meridian): the face beyond that radius is past the edge of the wheel's
// envelope. There the solution of Eqs. 5, 6, 11 is a minimum of the wheel's reach along the face
// normal instead of its maximum (the second-order condition of Eq. 11 fails), so no wheel dressed
// to this profile grinds that band of the face as designed.
#pragma once

#include <optional>

#include "tooth_face.h"
#include "universal_settings.h"
#include "wheel_profile.h"

namespace hobsharp {

// The meridian speed d(R, Z)/du . (n_Z, -n_R) at the contact point (u, w) of Eq. 5, mm per mm of
// the line coordinate u, w following the contact line (dw/du = -f_u / f_w on Eq. 5).
double meridianSpeed(const ToothFace& face, const UniversalSettings& s, double normalSign, double u, double w);

// The first tooth-face radius (mm) of `profile` (root to tip) where the meridian speed changes sign,
// refined between the two profile points that bracket it; nothing when the profile runs one way
// from its first point to its last.
std::optional<double> profileTurnRadius(const ToothFace& face, const UniversalSettings& s, double normalSign,
                                        const WheelProfile& profile);

}  // namespace hobsharp
