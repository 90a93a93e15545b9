#include "run_axes.h"

#include <cmath>

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

Outcome<AxisPolynomials> runAxes(const std::optional<AxisPolynomials>& given, const AxisPolynomials& nominal, int degree) {
  if (!given) return nominal;
  if (auto r = checkAxes(*given, degree, "axes"); !r) return r.error();
  return *given;
}

}  // namespace hobsharp
