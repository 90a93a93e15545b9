// Elementary rotations about the coordinate axes, applied to a vector, for any scalar type
// (double or an automatic-differentiation scalar). Rx(t) = [1 0 0; 0 c -s; 0 s c],
// Ry(t) = [c 0 s; 0 1 0; -s 0 c], as in the matrices of Eqs. 2, 3 and 7.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace hobsharp {

template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

// The cosine and sine of one angle, as the rotations take them.
template <class T>
struct CosSin {
  T c, s;
};

inline CosSin<double> cosSin(double angle) { return {std::cos(angle), std::sin(angle)}; }

template <class T, class C, class S>
Vec3<T> rotateX(const Vec3<T>& v, const C& c, const S& s) {
  return Vec3<T>(v.x(), c * v.y() - s * v.z(), s * v.y() + c * v.z());
}

template <class T, class C, class S>
Vec3<T> rotateY(const Vec3<T>& v, const C& c, const S& s) {
  return Vec3<T>(c * v.x() + s * v.z(), v.y(), -s * v.x() + c * v.z());
}

}  // namespace hobsharp
