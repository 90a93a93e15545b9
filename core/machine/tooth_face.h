// The tooth (rake) face of the hob gash, Eqs. 1-2, and the straight gash (docs/conventions.md §Straight gash).
//
// Helical gash: the screw surface of the straight line of Eq. 1,
//   r1(u, beta) = (p beta, y0 cos beta - e sin beta, y0 sin beta + e cos beta),
//   y0 = r_p cos(gamma_c) + u, p = L_c / 2 pi (negative for a left hand).
// Straight gash: the plane r1(u, x) = (x, y0, e), parallel to the hob axis.
// The second face coordinate w is beta (rad) for a helical gash and x (mm) for a straight one.
#pragma once

#include <cmath>

#include "autodiff.h"
#include "rotations.h"
#include "units.h"

namespace hobsharp {

enum class GashKind { Helical, Straight };
enum class Hand { Right, Left };

struct ToothFace {
  GashKind gash = GashKind::Helical;
  double pitchRadius = 0;     // r_p, mm
  double rakeOffset = 0;      // e, mm
  double screwParameter = 0;  // p = L_c / 2 pi, mm/rad, signed by hand (0 for a straight gash)

  // Eq. 1: the line coordinate u at the pitch point is 0.
  double y0Pitch() const { return std::sqrt(pitchRadius * pitchRadius - rakeOffset * rakeOffset); }
  double rakeAngle() const { return std::asin(rakeOffset / pitchRadius); }
  bool helical() const { return gash == GashKind::Helical; }
  Hand hand() const { return screwParameter < 0 ? Hand::Left : Hand::Right; }
  // Helical gash: the lead L_c = 2 pi |p|, mm, and the helix angle at the pitch radius,
  // tan = r_p / |p|, rad.
  double lead() const { return 2 * kPi * std::abs(screwParameter); }
  double helixAngle() const { return std::atan(pitchRadius / std::abs(screwParameter)); }

  // The line coordinate u of the point at `radius` from the hob axis.
  double uAtRadius(double radius) const {
    return std::sqrt(radius * radius - rakeOffset * rakeOffset) - y0Pitch();
  }
  // The face coordinate w of the point at axial position x.
  double wAtAxial(double x) const { return helical() ? x / screwParameter : x; }
  double axialAt(double w) const { return helical() ? screwParameter * w : w; }

  // Eq. 2.
  template <class T>
  Vec3<T> point(const T& u, const T& w) const {
    if (!helical()) return Vec3<T>(w, u + y0Pitch(), T(rakeOffset));
    return pointAt(u, w, cosSin(w));
  }

  // r_u x r_w, not normalised: (y0, p sin beta, -p cos beta), or (0, 0, -1) for a straight gash.
  template <class T>
  Vec3<T> normal(const T& u, const T& w) const {
    if (!helical()) return Vec3<T>(T(0), T(0), T(-1));
    return normalAt(u, cosSin(w));
  }

  // Both, from one cosine and sine of beta.
  template <class T>
  struct PointAndNormal {
    Vec3<T> point, normal;
  };
  template <class T>
  PointAndNormal<T> pointAndNormal(const T& u, const T& w) const {
    if (!helical()) return {point(u, w), normal(u, w)};
    const CosSin<T> beta = cosSin(w);
    return {pointAt(u, w, beta), normalAt(u, beta)};
  }

 private:
  template <class T>
  Vec3<T> pointAt(const T& u, const T& w, const CosSin<T>& beta) const {
    const T y0 = u + y0Pitch();
    return Vec3<T>(screwParameter * w, y0 * beta.c - rakeOffset * beta.s, y0 * beta.s + rakeOffset * beta.c);
  }
  template <class T>
  Vec3<T> normalAt(const T& u, const CosSin<T>& beta) const {
    return Vec3<T>(u + y0Pitch(), screwParameter * beta.s, -screwParameter * beta.c);
  }
};

// Lead <-> gash helix angle at the pitch radius: tan(helix) = r_p / p.
inline double screwParameterFromLead(double lead) { return lead / (2 * kPi); }
inline double helixAngleFromLead(double lead, double pitchRadius) {
  return std::atan(pitchRadius / screwParameterFromLead(lead));
}
inline double leadFromHelixAngle(double helixAngle, double pitchRadius) {
  return 2 * kPi * pitchRadius / std::tan(helixAngle);
}

}  // namespace hobsharp
