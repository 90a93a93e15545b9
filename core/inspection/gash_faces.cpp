#include "gash_faces.h"

#include <algorithm>
#include <cmath>

namespace hobsharp {
namespace {

void keepLargest(double& kept, double candidate) {
  if (std::abs(candidate) > std::abs(kept)) kept = candidate;
}

}  // namespace

double deviationAtRadius(const Eigen::MatrixXd& normal, const std::vector<double>& r, double radius) {
  // The mean of the axial lines' fitted lines is the line fitted to the mean along the gash.
  const Eigen::VectorXd y = normal.rowwise().mean();
  const Eigen::VectorXd t = Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
  const Eigen::ArrayXd dt = t.array() - t.mean();
  const double stt = (dt * dt).sum();
  const double slope = stt > 0 ? (dt * (y.array() - y.mean())).sum() / stt : 0.0;
  return y.mean() + slope * (radius - t.mean());
}

GashFaces inspectGashFaces(const std::vector<Eigen::MatrixXd>& gashes, const FaceLines& lines, bool helical,
                           double pitchRadius) {
  GashFaces out;
  if (helical) out.worst.gashLead = 0.0;
  for (const Eigen::MatrixXd& g : gashes) {
    out.deviations.push_back(deviationAtRadius(g, lines.r, pitchRadius));
    const FaceChecks f = checkFace(g, lines, helical);
    out.faces.push_back(f);
    out.worst.cuttingFaceForm = std::max(out.worst.cuttingFaceForm, f.cuttingFaceForm);
    keepLargest(out.worst.radialAlignment, f.radialAlignment);
    keepLargest(out.worst.rakeOffset, f.rakeOffset);
    keepLargest(out.worst.rakeAngle, f.rakeAngle);
    if (f.gashLead) keepLargest(*out.worst.gashLead, *f.gashLead);
  }
  return out;
}

}  // namespace hobsharp
