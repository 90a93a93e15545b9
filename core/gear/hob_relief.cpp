#include "hob_relief.h"

#include <cmath>

#include "number_text.h"
#include "units.h"

namespace hobsharp {

Outcome<void> checkRelief(const HobReliefInput& out, double outerDiameter, double pitchDiameter,
                          double normalPressureAngle) {
  if (out.gashes && (*out.gashes < 1 || *out.gashes > kMaxHobGashes))
    return refuse("hob.gashes", "must be a whole number from 1 to " + std::to_string(kMaxHobGashes) + "; got " +
                                    std::to_string(*out.gashes) + ".");
  const double radius = outerDiameter / 2;
  if (out.relief && (*out.relief <= 0 || *out.relief >= radius))
    return refuse("hob.relief", "must be positive and below the hob's outer radius (" + numberText(radius) +
                                    " mm); got " + exactText(*out.relief) + " mm.");
  if (out.sideReliefAngle && (*out.sideReliefAngle <= 0 || *out.sideReliefAngle > kMaxSideReliefAngle))
    return refuse("hob.sideReliefAngle", "must lie over 0 up to " + numberText(kMaxSideReliefAngle) + " deg; got " +
                                             exactText(*out.sideReliefAngle) + " deg.");
  if (out.relief && out.sideReliefAngle && !out.gashes)
    return refuse("hob.gashes", "is needed to check hob.relief against hob.sideReliefAngle.");
  // The relief and the gashes give a side relief angle: held to the same limit as one given (a
  // slipped digit, 39 for 3.9 mm, is a side relief of 39 deg on a module-4.5 hob), and, when the
  // side relief angle is given too, to it.
  if (out.relief && out.gashes) {
    const double alpha = normalPressureAngle * kRadPerDeg, rp = pitchDiameter / 2;
    if (alpha > 0 && rp > 0) {
      const double implied = sideReliefAngleAt(reliefPerRadianFromCam(*out.relief, *out.gashes), rp, alpha) * kDegPerRad;
      if (implied > kMaxSideReliefAngle)
        return refuse("hob.relief", "with " + std::to_string(*out.gashes) + " gashes gives a side relief angle of " +
                                        numberText(std::ceil(implied * 100) / 100) + " deg at the pitch diameter, more than the " +
                                        numberText(kMaxSideReliefAngle) + " deg a hob has; got " +
                                        exactText(*out.relief) + " mm (the cam rise over one gash pitch).");
      if (out.sideReliefAngle && std::abs(implied - *out.sideReliefAngle) > kSideReliefAgreement)
        return refuse("hob.sideReliefAngle", "disagrees with hob.relief and hob.gashes, which give " +
                                                 numberText(implied) + " deg at the pitch diameter; got " +
                                                 exactText(*out.sideReliefAngle) + " deg.");
    }
  }
  return success();
}

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
