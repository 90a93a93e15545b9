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

// The rotations of Eq. 3, fixed for a job: the cosines and sines of phi_1, gamma_m and eta.
struct ContactRotations {
  CosSin<double> phi1, gamma, tilt;
};

inline ContactRotations contactRotations(const UniversalSettings& s) {
  return {cosSin(s.rotation.coefficient(0)), cosSin(s.settingAngle.coefficient(0)), cosSin(s.tilt)};
}

// Eq. 3 at w = 0: r_t = M_tc(eta) M_cb(gamma_m) M_ba(E_t, L_t) M_a1(phi_1) r_1. The centre
// distance is a parameter of its own so that the boundary equation can solve for it.
template <class T, class E>
WheelContact<T> wheelContact(const ToothFace& face, const UniversalSettings& s, const ContactRotations& rotations,
                             double normalSign, const E& centerDistance, const T& u, const T& w) {
  const double ce = rotations.tilt.c, se = rotations.tilt.s, cg = rotations.gamma.c, sg = rotations.gamma.s;
  const double cp = rotations.phi1.c, sp = rotations.phi1.s;
  const auto face1 = face.pointAndNormal(u, w);
  Vec3<T> r = rotateX(face1.point, cp, sp);
  r.x() += s.axialMovement.coefficient(0);
  r.y() -= centerDistance;
  Vec3<T> n = rotateX(face1.normal, cp, sp);
  using std::sqrt;
  n *= normalSign / sqrt(n.squaredNorm());
  WheelContact<T> c;
  c.r = rotateX(rotateY(r, cg, sg), ce, -se);  // M_tc(eta) = Rx(-eta), M_cb = Ry(gamma_m)
  c.n = rotateX(rotateY(n, cg, sg), ce, -se);
  c.meshing = -c.n.x() * c.r.y() + c.n.y() * c.r.x();  // z_t x r_t = (-y_t, x_t, 0)
  return c;
}

template <class T, class E>
WheelContact<T> wheelContact(const ToothFace& face, const UniversalSettings& s, double normalSign,
                             const E& centerDistance, const T& u, const T& w) {
  return wheelContact(face, s, contactRotations(s), normalSign, centerDistance, u, w);
}

// +1 or -1: the orientation that makes r_u x r_w point out of the tooth material, fixed once at
// the pitch point: the outward normal points against the wheel axis z_t.
double outwardNormalSign(const ToothFace& face, const UniversalSettings& s);

}  // namespace hobsharp
