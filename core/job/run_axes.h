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

// How far axes run may lie from the nominal ones anywhere over the motion: 1000 mm on X, Y, Z and
// 90 deg on A, B, beyond any correction and short of a unit slip of a setup value (µm typed in a
// mm field is 1000 times the value, degrees in a rad field 57 times); past it the run is such a
// slip, and a machine error identified to explain it would be proposed as a correction (an
// independent review: B typed in degrees gave usable axes). The calculator's own proposals reach
// far: on a straight gash with a 150 µm face, Y over the motion by 64 mm (the campaign's seed
// 20261125, scenario 314, whose next pass a 50 mm limit refused), and a linear correction of faces
// signed the wrong way round proposed 12 mm (test_pass_history.cpp).
constexpr double kMaxRunOffsetLinear = 1000;                // mm
constexpr double kMaxRunOffsetRotary = 90 * 3.14159265358979323846 / 180;  // rad

// Axes run within those limits of `nominal` at every motion parameter in [-reach, reach] (rad, or mm
// on a straight gash); `name` as checkAxes's.
Outcome<void> checkNearNominal(const AxisPolynomials& axes, const AxisPolynomials& nominal, double reach,
                               const std::string& name);

// `given` (checked as `axes`) when the case gives it, else `nominal`.
Outcome<AxisPolynomials> runAxes(const std::optional<AxisPolynomials>& given, const AxisPolynomials& nominal, int degree);

}  // namespace hobsharp
