#include "measured_points.h"
#include "number_text.h"

#include <cmath>
#include <sstream>

namespace hobsharp {
namespace {

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
    const std::string at = "(r, x) = (" + numberText(p.r, 7) + ", " + numberText(p.x, 7) + ") mm";
    if (!std::isfinite(p.r) || !std::isfinite(p.x) || !std::isfinite(p.deviation))
      return refuse(pointName(k), "must hold three finite numbers [r, x, deviation].");
    if (std::abs(p.deviation) > region.maxDeviation)
      return refuse(pointName(k), "the deviation must lie within ±" + numberText(region.maxDeviation, 7) + " µm (10 mm); got " +
                                      numberText(p.deviation, 7) + " µm.");
    if (p.r < region.rootRadius - region.tolerance || p.r > region.outerRadius + region.tolerance)
      return refuse(pointName(k), at + " is off the rake face, which runs from the gash root (radius " +
                                      numberText(region.rootRadius, 7) + " mm) to the outer radius (" + numberText(region.outerRadius, 7) +
                                      " mm).");
    if (std::abs(p.x) > region.axialReach)
      return refuse(pointName(k), at + " lies outside the ground region: the face ends at x = ±" +
                                      numberText(region.axialReach, 7) + " mm.");
    const int i = lineAt(grid.r, p.r, region.tolerance), j = lineAt(grid.x, p.x, region.tolerance);
    if (i < 0 || j < 0)
      return refuse(pointName(k), at + " is not at a position of the grid (" + std::to_string(grid.rows()) +
                                      " radii from " + numberText(grid.r.front(), 7) + " to " + numberText(grid.r.back(), 7) + " mm, " +
                                      std::to_string(grid.cols()) + " axial positions from " + numberText(grid.x.front(), 7) +
                                      " to " + numberText(grid.x.back(), 7) + " mm, within " + numberText(region.tolerance, 7) +
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
        return refuse("measuredPoints", "has no point at the grid position (r, x) = (" + numberText(grid.r[i], 7) + ", " +
                                            numberText(grid.x[j], 7) + ") mm (row " + std::to_string(i) + ", column " +
                                            std::to_string(j) + "); the points must cover the whole grid.");
  return m;
}

}  // namespace hobsharp
