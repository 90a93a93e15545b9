#include "face_grid.h"

#include <cmath>

namespace hobsharp {

FaceGrid FaceGrid::even(int radial, int axial, double rMin, double rMax, double xMin, double xMax) {
  FaceGrid g;
  for (int i = 0; i < radial; ++i) g.r.push_back(radial == 1 ? rMin : rMin + (rMax - rMin) * i / (radial - 1));
  for (int j = 0; j < axial; ++j) g.x.push_back(axial == 1 ? xMin : xMin + (xMax - xMin) * j / (axial - 1));
  return g;
}

GridPoint gridPoint(const SharpeningSetup& setup, double r, double x) {
  const ToothFace& f = setup.face;
  GridPoint g;
  g.r = r;
  g.x = x;
  g.u = f.uAtRadius(r);
  g.w = f.wAtAxial(x);
  g.p = f.point(g.u, g.w);
  g.n = setup.normalSign * f.normal(g.u, g.w).normalized();
  const Eigen::Vector3d tangent = Eigen::Vector3d(0, -g.p.z(), g.p.y()).normalized();
  g.cosCircle = std::abs(g.n.dot(tangent));
  return g;
}

}  // namespace hobsharp
