// The face and the axes as the least-squares solves see them (Eqs. 13-17): a grid of deviations
// as one vector, row by row (the order of GroundFace's points); a simulated face's normal
// deviations in µm in that order; and the axes moved by a change of some coefficients, or by a
// whole machine error.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "coefficient.h"
#include "ground_face.h"

namespace hobsharp {

Eigen::VectorXd flat(const Eigen::MatrixXd& m);
Eigen::MatrixXd gridOf(const Eigen::VectorXd& v, int rows, int cols);  // flat()'s inverse
Eigen::VectorXd faceNormal(const GroundFace& f);                         // µm, per point
AxisPolynomials plusChange(AxisPolynomials axes, const std::vector<Coefficient>& cs, const Eigen::VectorXd& change);
AxisPolynomials plusError(AxisPolynomials axes, const AxisPolynomials& error);

}  // namespace hobsharp
