#include "face_vectors.h"
#include "units.h"

#include <cstddef>

namespace hobsharp {

Eigen::VectorXd flat(const Eigen::MatrixXd& m) {
  Eigen::VectorXd v(m.size());
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) v(i * m.cols() + j) = m(i, j);
  return v;
}

Eigen::MatrixXd gridOf(const Eigen::VectorXd& v, int rows, int cols) {
  Eigen::MatrixXd m(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) m(i, j) = v(i * cols + j);
  return m;
}

Eigen::VectorXd faceNormal(const GroundFace& f) {
  Eigen::VectorXd v(f.size());
  for (int p = 0; p < f.size(); ++p) v(p) = kMicrometresPerMm * f.envelope[p].t;
  return v;
}

AxisPolynomials plusChange(AxisPolynomials axes, const std::vector<Coefficient>& cs, const Eigen::VectorXd& change) {
  for (std::size_t j = 0; j < cs.size(); ++j) axes[cs[j].axis].a[cs[j].degree] += change(static_cast<int>(j));
  return axes;
}

AxisPolynomials plusError(AxisPolynomials axes, const AxisPolynomials& error) {
  for (Axis a : kAxes)
    for (std::size_t k = 0; k < axes[a].a.size(); ++k) axes[a].a[k] += error[a].coefficient(static_cast<int>(k));
  return axes;
}

}  // namespace hobsharp
