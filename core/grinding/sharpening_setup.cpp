#include "sharpening_setup.h"

#include "wheel_contact.h"

namespace hobsharp {

SharpeningSetup SharpeningSetup::make(const ToothFace& face, const UniversalSettings& universal,
                                      const MachineConstants& machine) {
  return SharpeningSetup{face, universal, machine, outwardNormalSign(face, universal), WheelSurface{}, std::nullopt};
}

}  // namespace hobsharp
