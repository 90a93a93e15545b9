// The sensitivity matrix of Eq. 16: the change of the normal deviation at every grid point (or
// probe point, for a face simulated at a measuring machine's points: rows = points, cols = 1), and
// of the thickness at the mean point, per unit change of each chosen polynomial coefficient.
// Built analytically (Eqs. 13-15) by the implicit function theorem on the solved envelope, not by
// the paper's finite differences.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "coefficient.h"
#include "ground_face.h"

namespace hobsharp {

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
