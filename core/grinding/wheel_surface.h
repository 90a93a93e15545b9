// The grinding wheel as a surface of its own: the surface of revolution of the conjugate profile
// (Eqs. 3-6) moved along the profile's normal by an offset that is a function of the wheel radius R
// of the conjugate point (docs/method.md §The wheel's profile offset, docs/case-format.md).
//
// Sign: + is more wheel, so less material on the face. The face normal n_t at a contact point is
// the wheel's normal too and points out of the tooth material, into the wheel; the dressed
// profile point is therefore p - delta(R) n (meridian components), and a constant delta grinds
// the face delta deeper (t = -delta).
#pragma once

#include <optional>

#include "autodiff.h"
#include "cubic_spline.h"
#include "wheel_contact.h"

namespace hobsharp {

struct WheelSurface {
  // The offset delta(R), mm over mm, a not-a-knot cubic spline; none for the conjugate wheel.
  std::optional<CubicSpline> offset;
  // A second offset on top of `offset`, through its own points: what the wheel-profile correction
  // proposes to dress in addition (core/correction/wheel_correction.h). delta is their sum.
  std::optional<CubicSpline> added;
  bool hasOffset() const { return offset.has_value() || added.has_value(); }
  // delta(R), delta'(R), delta''(R) of the sum, mm (zero for the conjugate wheel): each spline
  // evaluated once.
  CubicSpline::Point at(double R) const {
    CubicSpline::Point p;
    for (const std::optional<CubicSpline>* s : {&offset, &added})
      if (*s) {
        const CubicSpline::Point q = (*s)->at(R);
        p.value += q.value, p.slope += q.slope, p.curvature += q.curvature;
      }
    return p;
  }
  double value(double R) const { return at(R).value; }
  double slope(double R) const { return at(R).slope; }
  double curvature(double R) const { return at(R).curvature; }
};

// The offset's value and slope at R, with R's derivatives carried by the chain rule
// (d delta = delta'(R) dR, d delta' = delta''(R) dR).
template <class T>
struct OffsetAt {
  T value, slope;
};
inline OffsetAt<double> offsetAt(const WheelSurface& s, double R) {
  const CubicSpline::Point p = s.at(R);
  return {p.value, p.slope};
}
template <class Der>
OffsetAt<Eigen::AutoDiffScalar<Der>> offsetAt(const WheelSurface& s, const Eigen::AutoDiffScalar<Der>& R) {
  const CubicSpline::Point p = s.at(R.value());
  return {Eigen::AutoDiffScalar<Der>(p.value, p.slope * R.derivatives()),
          Eigen::AutoDiffScalar<Der>(p.slope, p.curvature * R.derivatives())};
}

// The wheel's meridian at one conjugate point: the profile point (R, Z) and a normal (nR, nZ),
// not normalised, pointing like n_t.
template <class T>
struct WheelMeridian {
  T R, Z, nR, nZ;
};

// The dressed wheel at the conjugate point c (which must satisfy Eq. 5 for nR, nZ to be the
// profile's unit normal). `valueShift` and `slopeShift` are added to delta(R) and delta'(R):
// zero in value, they carry the derivatives with respect to the offset for the sensitivities.
//
// With the meridian tangent T = (nZ, -nR) and s its arc length, the dressed curve p - delta n
// has the tangent (1 - delta kappa) T - delta' nZ n (kappa: the profile's curvature, n' = kappa T),
// so its normal is (1 - delta kappa) n + delta' nZ T. The term delta kappa (a few µm over a
// radius of curvature of tens of mm: below 1e-4) is left out, which tilts this normal by less than
// 1e-4 of delta' and moves the envelope by its square only (Eq. 11 is stationary there).
template <class T>
WheelMeridian<T> wheelMeridian(const WheelSurface& wheel, const WheelContact<T>& c, const T& valueShift,
                               const T& slopeShift) {
  WheelMeridian<T> m{c.R(), c.Z(), c.nRadial(), c.n.z()};
  if (!wheel.hasOffset()) return m;
  const OffsetAt<T> o = offsetAt(wheel, m.R);
  const T delta = o.value + valueShift;
  const T slope = o.slope + slopeShift;
  const T nR = m.nR, nZ = m.nZ;
  m.R = m.R - delta * nR;
  m.Z = m.Z - delta * nZ;
  m.nR = nR + slope * nZ * nZ;
  m.nZ = nZ - slope * nZ * nR;
  return m;
}

}  // namespace hobsharp
