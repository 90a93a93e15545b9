#include "face_lines.h"

#include <cmath>

namespace hobsharp {

FaceLines FaceLines::of(const SharpeningSetup& setup, const FaceGrid& grid) {
  const ToothFace& f = setup.face;
  FaceLines out;
  out.r = grid.r;
  out.x = grid.x;
  for (double r : grid.r) out.alongLine.push_back(std::sqrt(r * r - f.rakeOffset * f.rakeOffset));
  out.acrossLine.resize(grid.rows(), grid.cols());
  for (int i = 0; i < grid.rows(); ++i) {
    for (int j = 0; j < grid.cols(); ++j) {
      const GridPoint g = gridPoint(setup, grid.r[i], grid.x[j]);
      // Eq. 2 is linear in u: one step of u is the line's direction, which lies in the transverse plane.
      const Eigen::Vector3d along = f.point(g.u + 1.0, g.w) - g.p;
      const Eigen::Vector3d across = Eigen::Vector3d(0, -along.z(), along.y()).normalized();
      out.acrossLine(i, j) = std::abs(g.n.dot(across));
    }
  }
  return out;
}

FaceLines FaceLines::radial(const std::vector<double>& r, const std::vector<double>& x) {
  FaceLines out;
  out.r = r;
  out.x = x;
  out.alongLine = r;
  out.acrossLine = Eigen::MatrixXd::Ones(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(x.size()));
  return out;
}

}  // namespace hobsharp
