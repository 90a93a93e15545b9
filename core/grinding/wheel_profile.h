// The wheel's axial profile (Eq. 6, docs/errata.md): for every radius of the tooth face from the gash
// root to the tip, the contact point of Eq. 5 at w = 0 and its wheel radius R and axial position Z.
#pragma once

#include <vector>

#include "outcome.h"
#include "tooth_face.h"
#include "universal_settings.h"

namespace hobsharp {

struct WheelProfile {
  std::vector<double> r;  // tooth-face radius from the hob axis, mm (root to tip)
  std::vector<double> w;  // face coordinate of the contact point: beta* (rad) or x* (mm)
  std::vector<double> R;  // wheel radius, mm
  std::vector<double> Z;  // axial position on the wheel, mm
};

// The contact coordinate w*(u) of the line coordinate u, by Newton's method on Eq. 5.
Outcome<double> contactCoordinate(const ToothFace& face, const UniversalSettings& s,
                                  double normalSign, double u, double wGuess = 0.0);

// The profile at the given tooth-face radii (ascending, mm), solved outwards from the pitch radius.
Outcome<WheelProfile> wheelProfile(const ToothFace& face, const UniversalSettings& s,
                                   double normalSign, const std::vector<double>& radii);

// `points` >= 2 radii, evenly spaced from rootRadius to outerRadius, ends included.
std::vector<double> evenRadii(double rootRadius, double outerRadius, int points);

// The boundary equation: the centre distance E_t at which the wheel rim (R = wheelRadius)
// touches the gash root. Solves Eq. 5 and R = wheelRadius together for (w*, E_t).
Outcome<double> centerDistanceFromWheelRim(const ToothFace& face, const UniversalSettings& s,
                                           double normalSign, double rootRadius,
                                           double wheelRadius);

}  // namespace hobsharp
