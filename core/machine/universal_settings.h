// The universal machine settings of Eq. 3: tilt eta, setting angle gamma_m, centre distance E_t
// and axial movement L_t = P_t phi_1. gamma_m, E_t and L_t may be polynomials of the motion
// parameter w (the paper's auxiliary flank modification); eta is the manual axis psi_c.
#pragma once

#include "polynomial.h"
#include "tooth_face.h"

namespace hobsharp {

struct UniversalSettings {
  double tilt = 0;            // eta, rad
  Polynomial settingAngle;    // gamma_m(w), rad
  Polynomial centerDistance;  // E_t(w), mm
  Polynomial axialMovement;   // L_t(w), mm
  Polynomial rotation;        // phi_1(w), rad: w for a helical gash, 0 for a straight one

  double screwParameter() const { return axialMovement.coefficient(1); }  // P_t
};

// Constant settings with the standard screw motion: L_t = P_t w, P_t = L_c / 2 pi, phi_1 = w
// (helical); L_t = w, phi_1 = 0 (straight gash, w is the axial travel s in mm).
UniversalSettings constantUniversalSettings(const ToothFace& face, double tilt, double settingAngle,
                                            double centerDistance);

// The default setting angle: the gash helix angle at the pitch radius, signed by hand;
// tan(gamma_m) = r_p / p. Zero for a straight gash.
double defaultSettingAngle(const ToothFace& face);

}  // namespace hobsharp
