// Everything fixed during one sharpening job: the tooth face, the universal settings the wheel
// was derived from, the machine constants, and the outward orientation of the face normal.
#pragma once

#include "axis_polynomials.h"
#include "tooth_face.h"
#include "universal_settings.h"
#include "wheel_profile_turn.h"
#include "wheel_surface.h"

namespace hobsharp {

struct SharpeningSetup {
  ToothFace face;
  UniversalSettings universal;
  MachineConstants machine;
  double normalSign = 1.0;  // see outwardNormalSign() in wheel_contact.h
  WheelSurface wheel;       // the conjugate wheel, or one dressed with a profile offset
  // Where the conjugate wheel's profile turns back below the tip (wheel_profile_turn.h): the face
  // above lies past the edge of the wheel's envelope. Nothing when the profile reaches the tip.
  std::optional<WheelEdge> wheelEdge;

  // The setup with its normal sign, which the wheel contact of Eq. 3 fixes at the pitch point.
  static SharpeningSetup make(const ToothFace& face, const UniversalSettings& universal,
                              const MachineConstants& machine);
  double psiC() const { return universal.tilt; }
};

}  // namespace hobsharp
