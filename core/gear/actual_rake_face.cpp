#include "actual_rake_face.h"

#include <cmath>

namespace hobsharp {

ActualRakeFace::ActualRakeFace(const ToothFace& face, double normalSign, const std::vector<double>& r,
                               const std::vector<double>& x, const Eigen::MatrixXd& deviation)
    : face_(face), normalSign_(normalSign) {
  for (Eigen::Index j = 0; j < deviation.cols(); ++j) {
    std::vector<double> mm(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) mm[i] = deviation(static_cast<Eigen::Index>(i), j) * 1e-3;
    columns_.emplace_back(r, mm);
  }
  axial_ = CubicSpline(x, std::vector<double>(x.size(), 0.0));
  // The cutting direction: the outward normal's component along the circle at the pitch point.
  const Eigen::Vector3d p = face_.point(0.0, 0.0);
  const Eigen::Vector3d n = normalSign_ * face_.normal(0.0, 0.0);
  const double theta = std::atan2(p.z(), p.y());
  cuttingSense_ = n.dot(Eigen::Vector3d(0, -std::sin(theta), std::cos(theta))) >= 0 ? 1.0 : -1.0;
}

double ActualRakeFace::deviation(double r, double x) const {
  const CubicSpline::Basis b = axial_.basis(x);
  double d = 0;
  for (std::size_t j = 0; j < columns_.size(); ++j) d += b.B(static_cast<Eigen::Index>(j)) * columns_[j].value(r);
  return d;
}

Eigen::Vector3d ActualRakeFace::point(double r, double x) const {
  const double u = face_.uAtRadius(r), w = face_.wAtAxial(x);
  const Eigen::Vector3d n = normalSign_ * face_.normal(u, w).normalized();
  return face_.point(u, w) + deviation(r, x) * n;
}

double ActualRakeFace::nominalAngle(double R, double X) const {
  const double e = face_.rakeOffset;
  const double line = std::atan2(e, std::sqrt(R * R - e * e));  // the generating line's point at radius R
  return face_.helical() ? X / face_.screwParameter + line : line;
}

}  // namespace hobsharp
