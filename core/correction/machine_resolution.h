// What a hob sharpening machine can be told: the smallest step of each CNC axis, and the
// polynomial coefficients rounded to what that step can express at the end of the motion range
// (docs/conventions.md §Machine resolution).
#pragma once

#include <array>

#include "axis_polynomials.h"
#include "coefficient.h"

namespace hobsharp {

// The smallest commanded step of each axis, in the case file's units: µm for X, Y, Z and degrees
// for A, B. The defaults are a hob sharpening machine's (0.1 µm, 0.0001 deg).
struct MachineResolution {
  std::array<double, kAxisCount> step{0.1, 0.1, 0.1, 1e-4, 1e-4};

  // The step in the axis's own unit: mm (X, Y, Z) or rad (A, B).
  double inAxisUnit(Axis a) const;
};

// The change of coefficient a_k that moves its axis by one step at the end of the motion range
// (|w| = motionRange): step / range^k, in mm or rad per (rad or mm)^k.
double coefficientStep(const MachineResolution& resolution, const Coefficient& c, double motionRange);

// Every coefficient rounded to a whole number of its coefficientStep.
AxisPolynomials roundToResolution(const AxisPolynomials& axes, const MachineResolution& resolution,
                                  double motionRange);

// A polynomial's value of largest magnitude over [min, max], signed, in the axis's display unit:
// µm for X, Y, Z, µrad for A, B (the polynomial in mm or rad).
double largestOverRange(const Polynomial& p, Axis a, double min, double max);

// The factor from the axis's unit (mm, rad) to its display unit (µm, µrad).
double displayFactor(Axis a);

}  // namespace hobsharp
