// The five-axis machine of Eq. 7 read backwards: where a point fixed to the hob sits in the
// wheel frame S_t, and how fast it moves there with the motion parameter.
//   M_1t = M_1d(psi_a) M_de(C_x, C_y) M_ef(psi_b) M_fg(psi_c) M_gt(C_z), with (docs/errata.md §Eq. 7)
//   M_1d = Rx(-A), M_de = T(-X, Y, K1), M_ef = Ry(-B), M_fg = T(0, 0, K2) Rx(psi_c), M_gt = T(0, 0, Z).
// Its inverse: q = T(0,0,-Z) Rx(-psi_c) T(0,0,-K2) Ry(B) [Rx(A) G + (X, -Y, -K1)].
#pragma once

#include <array>
#include <cmath>

#include "autodiff.h"
#include "axis_polynomials.h"
#include "rotations.h"

namespace hobsharp {

// Axis positions and rates (d/dw) at one instant, in the order X, Y, Z, A, B.
template <class T>
struct AxisState {
  std::array<T, kAxisCount> value;
  std::array<T, kAxisCount> rate;
  const T& operator()(Axis a) const { return value[static_cast<int>(a)]; }
  const T& rateOf(Axis a) const { return rate[static_cast<int>(a)]; }
};

template <class T>
struct WheelFramePoint {
  Vec3<T> q;     // position in S_t
  Vec3<T> qDot;  // dq/dw with the hob point held fixed: minus the relative velocity of Eq. 11
};

// psi_c by its cosine and sine, which are fixed for a job.
template <class T, class P>
WheelFramePoint<T> hobPointInWheelFrame(const Vec3<P>& point, const AxisState<T>& s, const MachineConstants& m,
                                        const CosSin<double>& psiC) {
  const Vec3<T> ex(T(1), T(0), T(0)), ey(T(0), T(1), T(0));
  const CosSin<T> A = cosSin(s(Axis::A)), B = cosSin(s(Axis::B));
  const Vec3<T> G = point.template cast<T>();
  const Vec3<T> a = rotateX(G, A.c, A.s);
  const Vec3<T> aDot = s.rateOf(Axis::A) * ex.cross(a);
  const Vec3<T> b = a + Vec3<T>(s(Axis::X), -s(Axis::Y), T(-m.K1));
  const Vec3<T> bDot = aDot + Vec3<T>(s.rateOf(Axis::X), -s.rateOf(Axis::Y), T(0));
  const Vec3<T> c = rotateY(b, B.c, B.s);
  const Vec3<T> cDot = s.rateOf(Axis::B) * ey.cross(c) + rotateY(bDot, B.c, B.s);
  WheelFramePoint<T> w;
  w.q = rotateX(Vec3<T>(c - Vec3<T>(T(0), T(0), T(m.K2))), psiC.c, -psiC.s);
  w.q.z() -= s(Axis::Z);
  w.qDot = rotateX(cDot, psiC.c, -psiC.s);
  w.qDot.z() -= s.rateOf(Axis::Z);
  return w;
}

template <class T, class P>
WheelFramePoint<T> hobPointInWheelFrame(const Vec3<P>& point, const AxisState<T>& s,
                                        const MachineConstants& m, double psiC) {
  return hobPointInWheelFrame(point, s, m, cosSin(psiC));
}

}  // namespace hobsharp
