#include "face_checks.h"

#include <algorithm>
#include <cmath>

namespace hobsharp {
namespace {

constexpr double kLeadLength = 100;  // mm: the gash lead deviation is stated per 100 mm

// The least-squares straight line y = a + b (t - mean t): its slope b, and the spread of y about it.
struct LineFit {
  double slope = 0;
  double spread = 0;
};

LineFit fitLine(const Eigen::VectorXd& t, const Eigen::VectorXd& y) {
  LineFit f;
  const Eigen::Index n = t.size();
  if (n < 2) return f;
  const Eigen::ArrayXd dt = t.array() - t.mean();
  const double stt = (dt * dt).sum();
  if (stt <= 0) return f;
  f.slope = (dt * (y.array() - y.mean())).sum() / stt;
  const Eigen::ArrayXd residual = y.array() - y.mean() - f.slope * dt;
  f.spread = residual.maxCoeff() - residual.minCoeff();
  return f;
}

// The value of largest magnitude, keeping its sign.
void keepLargest(double& kept, double candidate) {
  if (std::abs(candidate) > std::abs(kept)) kept = candidate;
}

}  // namespace

FaceChecks checkFace(const Eigen::MatrixXd& normal, const std::vector<double>& r, const std::vector<double>& x,
                     bool helical) {
  FaceChecks out;
  const Eigen::VectorXd rv = Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
  const Eigen::VectorXd xv = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  const double rise = r.empty() ? 0 : r.back() - r.front();
  for (Eigen::Index j = 0; j < normal.cols(); ++j) {
    const LineFit f = fitLine(rv, normal.col(j));
    keepLargest(out.radialAlignment, f.slope * rise);
    out.cuttingFaceForm = std::max(out.cuttingFaceForm, f.spread);
  }
  if (helical) {
    double lead = 0;
    for (Eigen::Index i = 0; i < normal.rows(); ++i) keepLargest(lead, fitLine(xv, normal.row(i).transpose()).slope * kLeadLength);
    out.gashLead = lead;
  }
  return out;
}

}  // namespace hobsharp
