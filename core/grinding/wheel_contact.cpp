#include "wheel_contact.h"

namespace hobsharp {

double outwardNormalSign(const ToothFace& face, const UniversalSettings& s) {
  const WheelContact<double> c =
      wheelContact(face, s, 1.0, s.centerDistance.coefficient(0), 0.0, 0.0);
  return c.n.z() < 0 ? 1.0 : -1.0;
}

}  // namespace hobsharp
