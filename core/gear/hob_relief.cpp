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
  // In the words of the hob's form (web/index.html), never the case's names.
  if (in.relief)
    return {std::nullopt, "The gear effect needs the number of gashes z with the relief K: the relief is the drop "
                          "(the cam rise) over one gash pitch."};
  return {std::nullopt,
          "No gear effect: no relief is given. Give the number of gashes z and the relief K (the cam rise over one "
          "gash pitch, mm), or the side relief angle, in the hob data."};
}

}  // namespace hobsharp
