#include "correction_input.h"

#include <cmath>

#include "field_checks.h"
#include "measured_points.h"
#include "number_text.h"

namespace hobsharp {

Outcome<CorrectionOptions> correctionOptions(const CorrectionInput& c, int degree, const std::string& name) {
  CorrectionOptions o;
  if (c.method) {
    if (*c.method == "linear") o.method = CorrectionMethod::Linear;
    else if (*c.method == "nonlinear") o.method = CorrectionMethod::Nonlinear;
    else return refuse(name + ".method", "must be \"nonlinear\" or \"linear\"; got \"" + *c.method + "\".");
  }
  if (c.probeNoise) {
    if (!std::isfinite(*c.probeNoise)) return refuse(name + ".probeNoise", "must be a finite number.");
    if (*c.probeNoise <= 0)
      return refuse(name + ".probeNoise", "the probe's standard deviation must be positive; got " +
                                                 exactText(*c.probeNoise) + " µm.");
    if (*c.probeNoise > kMaxDeviation)
      return refuse(name + ".probeNoise", "must be at most " + numberText(kMaxDeviation) + " µm (10 mm); got " +
                                                 exactText(*c.probeNoise) + " µm.");
    o.probeNoise = *c.probeNoise;
  }
  for (Axis a : kAxes) {
    const std::optional<double>& r = c.resolution[static_cast<int>(a)];
    if (!r) continue;
    const std::string field = name + ".resolution." + axisName(a);
    if (auto ok = positive(field, *r, isRotary(a) ? "deg" : "µm"); !ok) return ok.error();
    // A step from a nanometre (a nanodegree) to a millimetre (a degree): beyond any machine, and
    // far from where the scaled coordinates of the correction lose their digits.
    const double least = isRotary(a) ? kLeastRotaryResolution : kLeastLinearResolution;
    const double most = isRotary(a) ? kMostRotaryResolution : kMostLinearResolution;
    if (*r < least || *r > most)
      return refuse(field, "must lie between " + numberText(least) + " and " + numberText(most) + (isRotary(a) ? " deg" : " µm") +
                               "; got " + exactText(*r) + (isRotary(a) ? " deg." : " µm."));
    o.resolution.step[static_cast<int>(a)] = *r;
  }
  if (c.truncation) {
    if (!(*c.truncation > 0 && *c.truncation < 1))
      return refuse(name + ".truncation", "must lie between 0 and 1; got " + exactText(*c.truncation) + ".");
    o.truncation = *c.truncation;
  }
  if (c.amplification) {
    if (!(*c.amplification >= 1 && std::isfinite(*c.amplification)))
      return refuse(name + ".amplification", "must be a finite number of at least 1; got " +
                                                    exactText(*c.amplification) + ".");
    o.amplification = *c.amplification;
  }
  for (const Coefficient& k : c.locked)
    if (k.degree < 0 || k.degree > degree)
      return refuse(name + ".locked", k.name() + " is beyond the polynomial degree " + std::to_string(degree) + ".");
  o.locked = c.locked;
  o.lockedAxes = c.lockedAxes;
  if (c.wheel.value_or(false)) {  // the wheel-profile correction (docs/method.md)
    if (o.method != CorrectionMethod::Nonlinear)
      return refuse(name + ".wheel", "needs correction.method \"nonlinear\": the wheel is identified together with the "
                                     "machine error, which the linear step does not do.");
    o.wheel = true;
  }
  return o;
}

}  // namespace hobsharp
