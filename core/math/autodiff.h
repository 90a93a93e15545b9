// Forward-mode automatic differentiation from Eigen: exact partial derivatives of the
// equations of meshing for Newton's method and for the implicit-function sensitivities.
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

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

}  // namespace hobsharp
