#include "hob_relief.h"

#include <cmath>

#include "units.h"

namespace hobsharp {

double reliefPerRadianFromCam(double relief, int gashes) { return relief * gashes / (2 * kPi); }

double reliefPerRadianFromSideAngle(double sideAngle, double pitchRadius, double normalPressureAngle) {
  return pitchRadius * std::tan(sideAngle) / std::sin(normalPressureAngle);
}

double sideReliefAngleAt(double reliefPerRadian, double radius, double normalPressureAngle) {
  return std::atan(reliefPerRadian / radius * std::sin(normalPressureAngle));
}

ReliefPerRadian reliefPerRadian(const HobReliefInput& in, double pitchRadius, double normalPressureAngle) {
  if (in.sideReliefAngle)
    return {reliefPerRadianFromSideAngle(*in.sideReliefAngle * kRadPerDeg, pitchRadius, normalPressureAngle), ""};
  if (in.relief && in.gashes) return {reliefPerRadianFromCam(*in.relief, *in.gashes), ""};
  if (in.relief)
    return {std::nullopt, "The gear effect needs hob.gashes with hob.relief: the relief is the drop over one gash pitch."};
  return {std::nullopt,
          "No gear effect: the case gives no relief (hob.gashes with hob.relief, or hob.sideReliefAngle)."};
}

}  // namespace hobsharp
