#include "run_axes.h"

#include <cmath>

#include "correction.h"
#include "number_text.h"
#include "units.h"

namespace hobsharp {

Outcome<void> checkAxes(const AxisPolynomials& axes, int degree, const std::string& name) {
  for (Axis a : kAxes) {
    const std::string field = name + "." + axisName(a);
    const Polynomial& p = axes[a];
    if (p.degree() != degree)
      return refuse(field, "needs " + std::to_string(degree + 1) + " coefficients a0..a" + std::to_string(degree) +
                               " (degree " + std::to_string(degree) + "); got " + std::to_string(p.a.size()) + ".");
    for (size_t k = 0; k < p.a.size(); ++k)
      if (!std::isfinite(p.a[k])) return refuse(field + "[" + std::to_string(k) + "]", "must be a finite number.");
  }
  return success();
}

Outcome<void> checkNearNominal(const AxisPolynomials& axes, const AxisPolynomials& nominal, double reach,
                               const std::string& name) {
  // axes - nominal of largest magnitude over the motion, µm or µrad (correction.h).
  const std::array<double, kAxisCount> off = axisChangeOver(axes, nominal, MotionRange{-reach, reach});
  for (Axis a : kAxes) {
    const bool rotary = isRotary(a);
    const double worst = std::abs(off[static_cast<size_t>(a)]) / (rotary ? 1e6 : kMicrometresPerMm);  // rad or mm
    if (worst > (rotary ? kMaxRunOffsetRotary : kMaxRunOffsetLinear)) {
      const std::string unit = rotary ? " rad" : " mm";
      return refuse(name + "." + axisName(a),
                    "differs from the nominal axis by up to " + numberText(worst, 4) + unit +
                        (rotary ? " (" + numberText(worst * kDegPerRad, 4) + " deg)" : "") +
                        " over the motion; a run is taken to differ from it by at most " +
                        (rotary ? "90 deg on A and B" : "1000 mm on X, Y and Z") + ", far beyond any correction. " +
                        (rotary ? "A and B are in rad: was it typed in degrees?" : "X, Y and Z are in mm: was it typed in µm?"));
    }
  }
  return success();
}

Outcome<AxisPolynomials> runAxes(const std::optional<AxisPolynomials>& given, const AxisPolynomials& nominal, int degree) {
  if (!given) return nominal;
  if (auto r = checkAxes(*given, degree, "axes"); !r) return r.error();
  return *given;
}

}  // namespace hobsharp
