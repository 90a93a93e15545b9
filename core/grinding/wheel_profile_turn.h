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
#include <string>

#include "tooth_face.h"
#include "universal_settings.h"
#include "wheel_profile.h"

namespace hobsharp {

// The meridian speed d(R, Z)/du . (n_Z, -n_R) at the contact point (u, w) of Eq. 5, mm per mm of
// the line coordinate u, w following the contact line (dw/du = -f_u / f_w on Eq. 5).
double meridianSpeed(const ToothFace& face, const UniversalSettings& s, double normalSign, double u, double w);

// The first tooth-face radius (mm) of `profile` (root to tip) where the meridian speed changes sign,
// refined by bisection between the two profile points that bracket it (to 1e-9 mm; the lower end
// of the bracket reached if a contact of Eq. 5 on the way cannot be found, so that the band said to
// lie past the edge is never too small); nothing when the profile runs one way from its first
// point to its last. Every point's speed is taken: the chords between the points can run one way
// over a stretch where the speed does not (a turn and the way back inside one interval).
std::optional<double> profileTurnRadius(const ToothFace& face, const UniversalSettings& s, double normalSign,
                                        const WheelProfile& profile);

// The band of the face past the edge of the wheel's envelope: from the radius where the conjugate
// profile turns back to the hob's outer radius, mm.
struct WheelEdge {
  double turnRadius = 0;
  double outerRadius = 0;
};

// The band in the engineer's words: what the wheel cannot grind as designed, and what moves it.
std::string wheelEdgeText(const WheelEdge& edge);

// The band in a correction's verdict, for a pass judged on a grid, or on measured points, that
// reaches above the turn: the figures the verdict quotes do not hold there, and the machine may
// leave part of it unground (on campaign seeds 7002 and 7003, two "Correctable" proposals failed
// only in that band; docs/validation.md).
std::string wheelEdgeVerdictText(const WheelEdge& edge);

}  // namespace hobsharp
