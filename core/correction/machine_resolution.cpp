#include "machine_resolution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "units.h"

namespace hobsharp {

// Samples of the motion range for a curve's largest value: enough for degree 6 to 1e-4 relative.
constexpr int kRangeSamples = 201;

double MachineResolution::inAxisUnit(Axis a) const {
  const double s = step[static_cast<int>(a)];
  return isRotary(a) ? s * kRadPerDeg : s * 1e-3;
}

double displayFactor(Axis a) { return isRotary(a) ? 1e6 : 1e3; }

double coefficientStep(const MachineResolution& resolution, const Coefficient& c, double motionRange) {
  return resolution.inAxisUnit(c.axis) / std::pow(motionRange, c.degree);
}

double programFactor(const Coefficient& c, bool helical) {
  const double value = isRotary(c.axis) ? kDegPerRad : 1.0;
  return helical ? value * std::pow(kRadPerDeg, c.degree) : value;
}

double roundToSignificant(double x, int digits) {
  if (x == 0 || !std::isfinite(x)) return x;
  // Decimal, correctly rounded: the number as a program line writes it.
  char text[40];
  std::snprintf(text, sizeof text, "%.*e", std::clamp(digits, 1, 17) - 1, x);
  return std::strtod(text, nullptr);
}

AxisPolynomials roundAsProgrammed(const AxisPolynomials& axes, const MachineResolution& resolution, bool helical) {
  AxisPolynomials r = axes;
  for (Axis a : kAxes)
    for (int k = 0; k <= r[a].degree(); ++k) {
      const double f = programFactor(Coefficient{a, k}, helical);
      r[a].a[k] = roundToSignificant(r[a].a[k] * f, resolution.coefficientDigits) / f;
    }
  return r;
}

double resolutionFloor(const Eigen::MatrixXd& perPosition, const MachineResolution& resolution) {
  if (perPosition.rows() == 0) return 0;
  double meanSquare = 0;
  for (Axis a : kAxes) {
    const double variance = std::pow(resolution.inAxisUnit(a), 2) / 12;  // uniform in +-step/2
    meanSquare += variance * perPosition.col(static_cast<int>(a)).squaredNorm() / static_cast<double>(perPosition.rows());
  }
  return std::sqrt(meanSquare);
}

double largestOverRange(const Polynomial& p, Axis a, double min, double max) {
  double best = 0, at = min;
  for (int i = 0; i < kRangeSamples; ++i) {
    const double w = min + (max - min) * i / (kRangeSamples - 1);
    const double v = p.at(w).value;
    if (std::abs(v) > std::abs(best)) best = v, at = w;
  }
  // Between the samples: Newton on p'(w) = 0 from the best one (an extremum inside the range).
  for (int k = 0; k < 8 && max > min; ++k) {
    const PolynomialValue f = p.at(at);
    if (f.d2 == 0) break;
    const double w = std::clamp(at - f.d1 / f.d2, min, max);
    const double v = p.at(w).value;
    if (std::abs(v) <= std::abs(best)) break;
    best = v, at = w;
  }
  return best * displayFactor(a);
}

}  // namespace hobsharp
