#include "machine_resolution.h"

#include <cmath>

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

AxisPolynomials roundToResolution(const AxisPolynomials& axes, const MachineResolution& resolution,
                                  double motionRange) {
  AxisPolynomials r = axes;
  for (Axis a : kAxes)
    for (int k = 0; k <= r[a].degree(); ++k) {
      const double step = coefficientStep(resolution, Coefficient{a, k}, motionRange);
      r[a].a[k] = std::round(r[a].a[k] / step) * step;
    }
  return r;
}

double largestOverRange(const Polynomial& p, Axis a, double min, double max) {
  double best = 0;
  for (int i = 0; i < kRangeSamples; ++i) {
    const double v = p.at(min + (max - min) * i / (kRangeSamples - 1)).value;
    if (std::abs(v) > std::abs(best)) best = v;
  }
  return best * displayFactor(a);
}

}  // namespace hobsharp
