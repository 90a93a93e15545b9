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

// How Newton's method finds the contact coordinate w* on Eq. 5 (contactCoordinate, wheelProfile).
struct ContactSolverOptions {
  // Newton steps tried before the contact is reported as not found.
  int maxIterations = 50;
  // rad: the longest step in beta (helical gash); a longer one is cut to this, so that the solve
  // keeps to the branch of Eq. 5 near its guess.
  double helicalStepLimit = 0.2;
  // mm: the same for x on a straight gash.
  double straightStepLimit = 10.0;
  // Dimensionless: w* is accepted when the last step |dw| is below this times (1 + |w|).
  double relativeStepTolerance = 1e-15;
};

// How Newton's method solves Eq. 5 and the rim equation R = wheel radius together for (w*, E_t)
// (centerDistanceFromWheelRim).
struct RimSolverOptions {
  // Newton steps tried before no centre distance is reported.
  int maxIterations = 50;
  // Dimensionless: (w*, E_t) is accepted when the last step's norm is below this times
  // (1 + |(w*, E_t)|); w* in rad (mm for a straight gash), E_t in mm.
  double relativeStepTolerance = 1e-13;
};

// The contact coordinate w*(u) of the line coordinate u, by Newton's method on Eq. 5.
Outcome<double> contactCoordinate(const ToothFace& face, const UniversalSettings& s,
                                  double normalSign, double u, double wGuess = 0.0,
                                  const ContactSolverOptions& options = {});

// The profile at the given tooth-face radii (ascending, mm), solved outwards from the pitch radius.
Outcome<WheelProfile> wheelProfile(const ToothFace& face, const UniversalSettings& s,
                                   double normalSign, const std::vector<double>& radii,
                                   const ContactSolverOptions& options = {});

// `points` >= 2 radii, evenly spaced from rootRadius to outerRadius, ends included.
std::vector<double> evenRadii(double rootRadius, double outerRadius, int points);

// The boundary equation: the centre distance E_t at which the wheel rim (R = wheelRadius)
// touches the gash root. Solves Eq. 5 and R = wheelRadius together for (w*, E_t).
Outcome<double> centerDistanceFromWheelRim(const ToothFace& face, const UniversalSettings& s,
                                           double normalSign, double rootRadius,
                                           double wheelRadius, const RimSolverOptions& options = {});

}  // namespace hobsharp
