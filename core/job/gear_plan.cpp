#include "gear_plan.h"

#include "units.h"

namespace hobsharp {

GearPlan gearPlan(const HobInput& hob) {
  const double alpha = hob.normalPressureAngle * kRadPerDeg, pitchRadius = hob.pitchDiameter / 2;
  return GearPlan{BasicRack{hob.normalModule, alpha, pitchRadius}, reliefPerRadian(hob.relief, pitchRadius, alpha)};
}

}  // namespace hobsharp
