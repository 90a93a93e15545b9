#include "axis_polynomials.h"

#include <cmath>

#include "taylor_series.h"

namespace hobsharp {

AxisPolynomials cncAxisPolynomials(const UniversalSettings& s, const MachineConstants& m, int degree) {
  const TaylorSeries gamma(s.settingAngle.a, degree), E(s.centerDistance.a, degree),
      L(s.axialMovement.a, degree), phi1(s.rotation.a, degree);
  TaylorSeries sinG({}, degree), cosG({}, degree);
  sinCos(gamma, &sinG, &cosG);
  const TaylorSeries one({1.0}, degree);
  const TaylorSeries secG = one / cosG;
  const double tanEta = std::tan(s.tilt), secEta = 1.0 / std::cos(s.tilt);

  AxisPolynomials p;
  p[Axis::A] = Polynomial{phi1.coefficients()};
  p[Axis::B] = Polynomial{gamma.coefficients()};
  p[Axis::X] = Polynomial{(L + m.K1 * (sinG / cosG)).coefficients()};
  p[Axis::Y] = Polynomial{(E - tanEta * (m.K1 * secG + m.K2)).coefficients()};
  p[Axis::Z] = Polynomial{(-secEta * (m.K1 * secG + m.K2)).coefficients()};
  return p;
}

}  // namespace hobsharp
