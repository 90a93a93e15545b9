#include "measured_points.h"

#include <cmath>
#include <sstream>

namespace hobsharp {
namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(7);
  s << v;
  return s.str();
}

std::string pointName(std::size_t k) { return "measuredPoints[" + std::to_string(k) + "]"; }

// The index of the line within `tolerance` of v, or -1.
int lineAt(const std::vector<double>& lines, double v, double tolerance) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (std::abs(lines[i] - v) <= tolerance) return static_cast<int>(i);
  return -1;
}

}  // namespace

Outcome<Eigen::MatrixXd> gridFromPoints(const std::vector<MeasuredPoint>& points, const FaceGrid& grid,
                                        const PointRegion& region) {
  if (points.empty()) return refuse("measuredPoints", "is empty; it needs one [r, x, deviation] per grid position.");
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(grid.rows(), grid.cols());
  std::vector<int> owner(static_cast<std::size_t>(grid.size()), -1);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const MeasuredPoint& p = points[k];
    const std::string at = "(r, x) = (" + num(p.r) + ", " + num(p.x) + ") mm";
    if (!std::isfinite(p.r) || !std::isfinite(p.x) || !std::isfinite(p.deviation))
      return refuse(pointName(k), "must hold three finite numbers [r, x, deviation].");
    if (std::abs(p.deviation) > region.maxDeviation)
      return refuse(pointName(k), "the deviation must lie within ±" + num(region.maxDeviation) + " µm (10 mm); got " +
                                      num(p.deviation) + " µm.");
    if (p.r < region.rootRadius - region.tolerance || p.r > region.outerRadius + region.tolerance)
      return refuse(pointName(k), at + " is off the rake face, which runs from the gash root (radius " +
                                      num(region.rootRadius) + " mm) to the outer radius (" + num(region.outerRadius) +
                                      " mm).");
    if (std::abs(p.x) > region.axialReach)
      return refuse(pointName(k), at + " lies outside the ground region: the face ends at x = ±" +
                                      num(region.axialReach) + " mm.");
    const int i = lineAt(grid.r, p.r, region.tolerance), j = lineAt(grid.x, p.x, region.tolerance);
    if (i < 0 || j < 0)
      return refuse(pointName(k), at + " is not at a position of the grid (" + std::to_string(grid.rows()) +
                                      " radii from " + num(grid.r.front()) + " to " + num(grid.r.back()) + " mm, " +
                                      std::to_string(grid.cols()) + " axial positions from " + num(grid.x.front()) +
                                      " to " + num(grid.x.back()) + " mm, within " + num(region.tolerance) +
                                      " mm). The calculator takes points at its grid's positions only; set the grid "
                                      "to the measuring pattern.");
    int& o = owner[static_cast<std::size_t>(i * grid.cols() + j)];
    if (o >= 0)
      return refuse(pointName(k), at + " is at the same grid position as " + pointName(static_cast<std::size_t>(o)) +
                                      "; each position is measured once.");
    o = static_cast<int>(k);
    m(i, j) = p.deviation;
  }
  for (int i = 0; i < grid.rows(); ++i)
    for (int j = 0; j < grid.cols(); ++j)
      if (owner[static_cast<std::size_t>(i * grid.cols() + j)] < 0)
        return refuse("measuredPoints", "has no point at the grid position (r, x) = (" + num(grid.r[i]) + ", " +
                                            num(grid.x[j]) + ") mm (row " + std::to_string(i) + ", column " +
                                            std::to_string(j) + "); the points must cover the whole grid.");
  return m;
}

}  // namespace hobsharp
