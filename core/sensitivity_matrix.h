// The sensitivity matrix of Eq. 16: the change of the normal deviation at every grid point, and
// of the thickness at the mean point, per unit change of each chosen polynomial coefficient.
// Built analytically (Eqs. 13-15) by the implicit function theorem on the solved envelope, not by
// the paper's finite differences.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "ground_face.h"

namespace hobsharp {

// The coefficient a_k of `axis` (Eq. 12), in mm or rad per (rad or mm)^k.
struct Coefficient {
  Axis axis = Axis::X;
  int degree = 0;
  std::string name() const { return std::string(axisName(axis)) + " a" + std::to_string(degree); }
  bool operator==(const Coefficient& o) const { return axis == o.axis && degree == o.degree; }
};

// Every coefficient of degree 0..degree, axis by axis: X a0..an, Y a0..an, ... B a0..an.
std::vector<Coefficient> allCoefficients(int degree);

struct SensitivityMatrix {
  std::vector<Coefficient> coefficients;
  int rows = 0, cols = 0;
  Eigen::MatrixXd normal;        // (rows * cols) x q, row-major grid order, µm per unit coefficient
  Eigen::RowVectorXd thickness;  // 1 x q, µm per unit coefficient
  double motionRange = 1;        // largest |phi| at the grid points: rad, or mm (straight gash)

  // The sensitivity topography of coefficient j (the paper's Fig. 6), rows x cols, µm per unit.
  Eigen::MatrixXd topography(int j) const;
};

SensitivityMatrix sensitivityMatrix(const GroundFace& face, const std::vector<Coefficient>& coefficients);

}  // namespace hobsharp
