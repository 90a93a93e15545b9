// What a hob sharpening machine can be told and what it can resolve (docs/conventions.md
// §Machine resolution): the polynomial coefficients as the NC program carries them, the smallest
// step of each CNC axis, and the face rms that step leaves (the pass's floor).
#pragma once

#include <array>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "coefficient.h"

namespace hobsharp {

struct MachineResolution {
  // The smallest commanded step of each axis, in the case file's units: µm for X, Y, Z and degrees
  // for A, B. The defaults are a hob sharpening machine's (0.1 µm, 0.0001 deg). It quantises the
  // interpolated position, not the coefficients (resolutionFloor).
  std::array<double, kAxisCount> step{0.1, 0.1, 0.1, 1e-4, 1e-4};
  // The significant decimal digits each polynomial coefficient is written with in the NC program,
  // in the program's units (programFactor): what the control is told, so what roundedAxes tests.
  // A Sinumerik REAL is an IEEE double and a TNC 640 Q parameter takes 16 digits; 10 is what the
  // page writes (the axes to run) and leaves both room. Unit: decimal digits, 1 to 17.
  int coefficientDigits = 10;

  // The step in the axis's own unit: mm (X, Y, Z) or rad (A, B).
  double inAxisUnit(Axis a) const;
};

// The change of coefficient a_k that moves its axis by one step at the end of the motion range
// (|w| = motionRange): step / range^k, in mm or rad per (rad or mm)^k. The identification's unit
// of each coefficient (structural_null_space.h), not a rounding.
double coefficientStep(const MachineResolution& resolution, const Coefficient& c, double motionRange);

// Coefficient a_k in the NC program's units per unit of the calculator's (mm or rad per (rad or
// mm)^k): mm (X, Y, Z) or deg (A, B) per (deg of hob rotation)^k on a helical gash, per (mm of
// travel)^k on a straight one.
double programFactor(const Coefficient& c, bool helical);

// x written with `digits` significant decimal digits (0 stays 0).
double roundToSignificant(double x, int digits);

// Every coefficient as the NC program carries it: in the program's units (programFactor), to
// resolution.coefficientDigits significant digits, and back in the calculator's units.
AxisPolynomials roundAsProgrammed(const AxisPolynomials& axes, const MachineResolution& resolution, bool helical);

// The pass's floor, µm rms over the rows of `perPosition`: the face rms that quantising each
// axis's position to its step causes. Column a of `perPosition` (rows = probe points, X Y Z A B)
// is the face's normal deviation per unit of a constant change of axis a (the degree-0 column of
// the sensitivity matrix, µm per mm or rad). Each position's error is uniform in +-step/2
// (standard deviation step / sqrt 12), independent between axes:
// floor² = sum_a (step_a² / 12) * mean over the points of perPosition(:, a)².
double resolutionFloor(const Eigen::MatrixXd& perPosition, const MachineResolution& resolution);

// A polynomial's value of largest magnitude over [min, max], signed, in the axis's display unit:
// µm for X, Y, Z, µrad for A, B (the polynomial in mm or rad).
double largestOverRange(const Polynomial& p, Axis a, double min, double max);

// The factor from the axis's unit (mm, rad) to its display unit (µm, µrad).
double displayFactor(Axis a);

}  // namespace hobsharp
