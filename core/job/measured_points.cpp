#include "measured_points.h"
#include "number_text.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hobsharp {
namespace {

// "measured point 1" in a sentence; "Pass 2, measured point 1" keeps its capital.
std::string lowerFirst(std::string words) {
  if (words.rfind("Measured", 0) == 0) words[0] = 'm';
  return words;
}

// The index of the line within `tolerance` of v, or -1.
int lineAt(const std::vector<double>& lines, double v, double tolerance) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (std::abs(lines[i] - v) <= tolerance) return static_cast<int>(i);
  return -1;
}

}  // namespace

Outcome<void> checkPoints(const std::vector<MeasuredPoint>& points, const PointRegion& region, const std::string& field) {
  if (points.empty()) return refusePoints(field, "the list is empty; it needs the measured points [r, x, deviation].");
  for (std::size_t k = 0; k < points.size(); ++k) {
    const MeasuredPoint& p = points[k];
    if (!std::isfinite(p.r) || !std::isfinite(p.x) || !std::isfinite(p.deviation))
      return refusePoint(field, k, "must hold three finite numbers [r, x, deviation].");
    // Written only for a refusal: formatting it for every point took most of the check's time.
    const auto at = [&p] { return "(r, x) = (" + numberText(p.r, 7) + ", " + numberText(p.x, 7) + ") mm"; };
    if (std::abs(p.deviation) > region.maxDeviation)
      return refusePoint(field, k, "the deviation must lie within ±" + numberText(region.maxDeviation, 7) + " µm (10 mm); got " +
                                       exactText(p.deviation, 7) + " µm.");
    if (p.r < region.rootRadius - region.tolerance || p.r > region.outerRadius + region.tolerance)
      return refusePoint(field, k, at() + " is off the rake face, which runs from the gash root (radius " +
                                      numberText(region.rootRadius, 7) + " mm) to the outer radius (" + numberText(region.outerRadius, 7) +
                                      " mm).");
    if (std::abs(p.x) > region.axialReach)
      return refusePoint(field, k, at() + " lies outside the ground region: the face ends at x = ±" +
                                      numberText(region.axialReach, 7) + " mm.");
  }
  // Duplicates: sorted by r, each point is compared with those within the tolerance in r after it.
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a].r != points[b].r ? points[a].r < points[b].r : a < b;
  });
  std::size_t worst = points.size(), first = 0;
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && points[order[j]].r - points[order[i]].r <= region.tolerance; ++j) {
      if (std::abs(points[order[j]].x - points[order[i]].x) > region.tolerance) continue;
      const std::size_t later = std::max(order[i], order[j]), earlier = std::min(order[i], order[j]);
      if (later < worst) worst = later, first = earlier;  // the first duplicate in the list's order
    }
  if (worst < points.size()) {
    const MeasuredPoint& p = points[worst];
    return refusePoint(field, worst, "(r, x) = (" + numberText(p.r, 7) + ", " + numberText(p.x, 7) + ") mm is within " +
                                         numberText(region.tolerance, 7) + " mm of " + lowerFirst(pointWords(field, first)) +
                                         ": the same point measured twice; give each point once.");
  }
  return success();
}

std::optional<Eigen::MatrixXd> gridFromPoints(const std::vector<MeasuredPoint>& points, const FaceGrid& grid,
                                              double tolerance) {
  if (static_cast<int>(points.size()) != grid.size()) return std::nullopt;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(grid.rows(), grid.cols());
  std::vector<bool> taken(static_cast<std::size_t>(grid.size()), false);
  for (const MeasuredPoint& p : points) {
    const int i = lineAt(grid.r, p.r, tolerance), j = lineAt(grid.x, p.x, tolerance);
    if (i < 0 || j < 0) return std::nullopt;
    const std::size_t at = static_cast<std::size_t>(i * grid.cols() + j);
    if (taken[at]) return std::nullopt;
    taken[at] = true;
    m(i, j) = p.deviation;
  }
  return m;  // as many points as positions, none twice: every position covered
}

ProbePoints probePointsOf(const std::vector<MeasuredPoint>& points) {
  ProbePoints out;
  out.reserve(points.size());
  for (const MeasuredPoint& p : points) out.push_back(ProbePoint{p.r, p.x});
  return out;
}

Eigen::VectorXd deviationsOf(const std::vector<MeasuredPoint>& points) {
  Eigen::VectorXd d(static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) d(static_cast<Eigen::Index>(k)) = points[k].deviation;
  return d;
}

}  // namespace hobsharp
