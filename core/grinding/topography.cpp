#include "topography.h"
#include "units.h"

#include <cmath>
#include <limits>

namespace hobsharp {
namespace {

// Bilinear interpolation of an evenly spaced grid at its centre.
double atCentre(const Eigen::MatrixXd& m) {
  const double fi = 0.5 * (m.rows() - 1), fj = 0.5 * (m.cols() - 1);
  const int i0 = static_cast<int>(std::floor(fi)), j0 = static_cast<int>(std::floor(fj));
  const int i1 = std::min<int>(i0 + 1, m.rows() - 1), j1 = std::min<int>(j0 + 1, m.cols() - 1);
  const double a = fi - i0, b = fj - j0;
  return (1 - a) * ((1 - b) * m(i0, j0) + b * m(i0, j1)) + a * ((1 - b) * m(i1, j0) + b * m(i1, j1));
}

// At probe points: the deviation of the point nearest the grid's mean point (no interpolation;
// docs/measured-points.md).
double atNearestToMean(const GroundFace& face, const Eigen::MatrixXd& m) {
  int best = 0;
  double bestD = std::numeric_limits<double>::infinity();
  for (int k = 0; k < face.size(); ++k) {
    const double d = std::hypot(face.points[k].r - face.meanPoint.r, face.points[k].x - face.meanPoint.x);
    if (d < bestD) bestD = d, best = k;
  }
  return m(best, 0);
}

}  // namespace

double circularFactor(const GroundFace& face, int i, int j) {
  const GridPoint& g = face.points[i * face.cols() + j];
  return face.grid.rMean() / (g.r * g.cosCircle);
}

double thicknessFactor(const GroundFace& face) { return 1.0 / face.meanPoint.cosCircle; }

double thicknessFromNormal(const GroundFace& face, const Eigen::MatrixXd& normal) {
  return (face.atProbes() ? atNearestToMean(face, normal) : atCentre(normal)) * thicknessFactor(face);
}

Topography topographyFromNormal(const GroundFace& face, const Eigen::MatrixXd& normal) {
  Topography t;
  t.grid = face.grid;
  t.normal = normal;
  t.circular.resize(normal.rows(), normal.cols());
  for (int i = 0; i < normal.rows(); ++i)
    for (int j = 0; j < normal.cols(); ++j) t.circular(i, j) = normal(i, j) * circularFactor(face, i, j);
  t.thickness = thicknessFromNormal(face, normal);
  t.sse = normal.squaredNorm();
  t.max = normal.cwiseAbs().maxCoeff();
  t.rms = std::sqrt(t.sse / static_cast<double>(normal.size()));
  t.peakToValley = normal.maxCoeff() - normal.minCoeff();
  return t;
}

Topography topographyOf(const GroundFace& face) {
  Eigen::MatrixXd normal(face.rows(), face.cols());
  for (int i = 0; i < face.rows(); ++i)
    for (int j = 0; j < face.cols(); ++j) normal(i, j) = kMicrometresPerMm * face.envelope[i * face.cols() + j].t;
  Topography t = topographyFromNormal(face, normal);
  t.thickness = kMicrometresPerMm * face.meanEnvelope.t * thicknessFactor(face);
  return t;
}

}  // namespace hobsharp
