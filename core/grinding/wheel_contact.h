// The tooth face seen from the wheel at w = 0 (Eqs. 3-4) and the equation of meshing (Eq. 5).
// The wheel is the surface of revolution about z_t swept by this contact line; Eq. 6
// (docs/errata.md) gives its axial profile (R, Z) = (sqrt(x_t^2 + y_t^2), z_t).
#pragma once

#include <cmath>

#include "rotations.h"
#include "tooth_face.h"
#include "universal_settings.h"

namespace hobsharp {

template <class T>
struct WheelContact {
  Vec3<T> r;  // r_t: the face point in S_t
  Vec3<T> n;  // n_t: unit normal in S_t, outward from the tooth material (docs/conventions.md §Sign)
  T meshing;  // f_t = n_t . (z_t x r_t), Eq. 5; zero on the contact line
  T R() const {
    using std::sqrt;
    return sqrt(r.x() * r.x() + r.y() * r.y());
  }
  T Z() const { return r.z(); }
  // The meridian components of the normal: along the radius of the wheel and along its axis.
  T nRadial() const { return (n.x() * r.x() + n.y() * r.y()) / R(); }
};

// Eq. 3 at w = 0: r_t = M_tc(eta) M_cb(gamma_m) M_ba(E_t, L_t) M_a1(phi_1) r_1. The centre
// distance is a parameter of its own so that the boundary equation can solve for it.
template <class T, class E>
WheelContact<T> wheelContact(const ToothFace& face, const UniversalSettings& s, double normalSign,
                             const E& centerDistance, const T& u, const T& w) {
  using std::cos;
  using std::sin;
  const double phi1 = s.rotation.coefficient(0), gamma = s.settingAngle.coefficient(0);
  const double ce = cos(s.tilt), se = sin(s.tilt), cg = cos(gamma), sg = sin(gamma);
  const double cp = cos(phi1), sp = sin(phi1);
  Vec3<T> r = rotateX(face.point(u, w), cp, sp);
  r.x() += s.axialMovement.coefficient(0);
  r.y() -= centerDistance;
  Vec3<T> n = rotateX(face.normal(u, w), cp, sp);
  using std::sqrt;
  n *= normalSign / sqrt(n.squaredNorm());
  WheelContact<T> c;
  c.r = rotateX(rotateY(r, cg, sg), ce, -se);  // M_tc(eta) = Rx(-eta), M_cb = Ry(gamma_m)
  c.n = rotateX(rotateY(n, cg, sg), ce, -se);
  c.meshing = -c.n.x() * c.r.y() + c.n.y() * c.r.x();  // z_t x r_t = (-y_t, x_t, 0)
  return c;
}

// +1 or -1: the orientation that makes r_u x r_w point out of the tooth material, fixed once at
// the pitch point: the outward normal points against the wheel axis z_t.
double outwardNormalSign(const ToothFace& face, const UniversalSettings& s);

}  // namespace hobsharp
