// The axes the machine ran (`axes`, docs/case-format.md): the case's, checked against the degree,
// or the nominal ones (Eq. 9).
#pragma once

#include <optional>
#include <string>

#include "axis_polynomials.h"
#include "outcome.h"

namespace hobsharp {

// Axis polynomials of the case's degree with finite coefficients; `name` is their field ("axes",
// "passes[0].axes").
Outcome<void> checkAxes(const AxisPolynomials& axes, int degree, const std::string& name);

// `given` (checked as `axes`) when the case gives it, else `nominal`.
Outcome<AxisPolynomials> runAxes(const std::optional<AxisPolynomials>& given, const AxisPolynomials& nominal, int degree);

}  // namespace hobsharp
