// Forward-mode automatic differentiation from Eigen: exact partial derivatives of the
// equations of meshing for Newton's method and for the implicit-function sensitivities.
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "rotations.h"

namespace hobsharp {

template <int N>
using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;

// A variable of value v that is the i-th of N independent variables.
template <int N>
Dual<N> variable(double v, int i) {
  return Dual<N>(v, N, i);
}

// A dependent input of value v with the given derivatives.
template <int N>
Dual<N> seeded(double v, const Eigen::Matrix<double, N, 1>& derivatives) {
  return Dual<N>(v, derivatives);
}

// cos and sin of a differentiated angle from one evaluation of both (the figures of cos(x), sin(x)).
template <class Der>
CosSin<Eigen::AutoDiffScalar<Der>> cosSin(const Eigen::AutoDiffScalar<Der>& x) {
  using Scalar = Eigen::AutoDiffScalar<Der>;
  const double c = std::cos(x.value()), s = std::sin(x.value());
  return {Scalar(c, x.derivatives() * (-s)), Scalar(s, x.derivatives() * c)};
}

// x, differentiated in M directions, as a function of N >= M directions: its directions are
// first, first + 1, ..., first + M - 1 of the N, and it does not depend on the others.
template <int N, int M>
Dual<N> embedded(const Dual<M>& x, int first) {
  Eigen::Matrix<double, N, 1> d = Eigen::Matrix<double, N, 1>::Zero();
  d.template segment<M>(first) = x.derivatives();
  return Dual<N>(x.value(), d);
}

}  // namespace hobsharp
