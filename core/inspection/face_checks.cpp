#include "face_checks.h"

#include <algorithm>
#include <cmath>

namespace hobsharp {
namespace {

constexpr double kLeadLength = 100;  // mm: the gash lead deviation is stated per 100 mm
constexpr double kMmPerMicron = 1e-3;

// The least-squares straight line y = a + b (t - mean t): its value at t = 0, its slope b, and the
// spread of y about it.
struct LineFit {
  double atZero = 0;
  double slope = 0;
  double spread = 0;
};

LineFit fitLine(const Eigen::VectorXd& t, const Eigen::VectorXd& y) {
  LineFit f;
  const Eigen::Index n = t.size();
  if (n < 1) return f;
  f.atZero = y.mean();
  if (n < 2) return f;
  const Eigen::ArrayXd dt = t.array() - t.mean();
  const double stt = (dt * dt).sum();
  if (stt <= 0) return f;
  f.slope = (dt * (y.array() - y.mean())).sum() / stt;
  f.atZero = y.mean() - f.slope * t.mean();
  const Eigen::ArrayXd residual = y.array() - y.mean() - f.slope * dt;
  f.spread = residual.maxCoeff() - residual.minCoeff();
  return f;
}

// The value of largest magnitude, keeping its sign.
void keepLargest(double& kept, double candidate) {
  if (std::abs(candidate) > std::abs(kept)) kept = candidate;
}

}  // namespace

FaceChecks checkFace(const Eigen::MatrixXd& normal, const FaceLines& lines, bool helical) {
  FaceChecks out;
  const Eigen::Index rows = normal.rows();
  if (rows == 0 || normal.cols() == 0) return out;
  const Eigen::VectorXd rv = Eigen::Map<const Eigen::VectorXd>(lines.r.data(), rows);
  const Eigen::VectorXd s = Eigen::Map<const Eigen::VectorXd>(lines.alongLine.data(), rows);
  const Eigen::VectorXd xv = Eigen::Map<const Eigen::VectorXd>(lines.x.data(), static_cast<Eigen::Index>(lines.x.size()));
  const double sTip = s(rows - 1);
  double offsetSum = 0;
  for (Eigen::Index j = 0; j < normal.cols(); ++j) {
    out.cuttingFaceForm = std::max(out.cuttingFaceForm, fitLine(rv, normal.col(j)).spread);
    // The face's offset across the nominal line (µm, plus = excess material). Turning the line about
    // the hob axis by theta moves its point at s by theta s across it: the indicator zeroed at the
    // tip reads d(s) - d(tip) s / s(tip) (docs/inspection.md).
    const Eigen::VectorXd d = normal.col(j).cwiseQuotient(lines.acrossLine.col(j));
    if (sTip > 0)
      for (Eigen::Index i = 0; i < rows; ++i) keepLargest(out.radialAlignment, d(i) - d(rows - 1) * s(i) / sTip);
    // The line fitted across: its value at the foot (s = 0) is the line's parallel move (a turn about
    // the hob axis moves the foot by nothing).
    offsetSum += fitLine(s, d).atZero;
  }
  // Excess material on the whole line is stock left below the tip's radial line: a drag. A hook
  // (positive rake error) is a line moved into the tooth, a negative offset across.
  out.rakeOffset = -offsetSum / static_cast<double>(normal.cols()) * kMmPerMicron;
  // The rake angle at the tip, asin(e / r_a), changes by d(e) / sqrt(r_a^2 - e^2) to first order.
  if (sTip > 0) out.rakeAngle = out.rakeOffset / sTip;
  if (helical) {
    double lead = 0;
    for (Eigen::Index i = 0; i < rows; ++i) keepLargest(lead, fitLine(xv, normal.row(i).transpose()).slope * kLeadLength);
    out.gashLead = lead;
  }
  return out;
}

Eigen::MatrixXd rakeErrorFace(const FaceLines& lines, double rakeOffset) {
  return -rakeOffset / kMmPerMicron * lines.acrossLine;
}

}  // namespace hobsharp
