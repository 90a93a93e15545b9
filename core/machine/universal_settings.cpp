#include "universal_settings.h"

#include <cmath>

namespace hobsharp {

UniversalSettings constantUniversalSettings(const ToothFace& face, double tilt, double settingAngle,
                                            double centerDistance) {
  UniversalSettings s;
  s.tilt = tilt;
  s.settingAngle = Polynomial::constant(settingAngle);
  s.centerDistance = Polynomial::constant(centerDistance);
  if (face.helical()) {
    s.axialMovement = Polynomial{{0.0, face.screwParameter}};
    s.rotation = Polynomial{{0.0, 1.0}};
  } else {
    s.axialMovement = Polynomial{{0.0, 1.0}};
    s.rotation = Polynomial::constant(0.0);
  }
  return s;
}

double defaultSettingAngle(const ToothFace& face) {
  if (!face.helical()) return 0.0;
  return std::atan(face.pitchRadius / face.screwParameter);
}

}  // namespace hobsharp
