// A measurement at the measuring machine's own points (`measuredPoints`, docs/case-format.md):
// each point a radius r and axial position x on the rake face (mm) and the normal deviation there
// (µm). The points may lie anywhere on the ground face: the correction's rows are the points
// themselves (correctMeasuredPoints, correction.h), nothing is interpolated. Points exactly at
// the grid's positions, covering each once, are taken as the grid (docs/measured-points.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "face_grid.h"
#include "outcome.h"
#include "probe_points.h"

namespace hobsharp {

struct MeasuredPoint {
  double r = 0, x = 0;    // mm
  double deviation = 0;   // µm, plus = excess material
};

// The largest |measured deviation| taken, µm (10 mm): beyond any real grinding error or
// what-if, and far below where the correction's squares and sums overflow (docs/case-format.md).
constexpr double kMaxDeviation = 1e4;

// Where the points may lie: on the rake face between the gash root and the outer radius, and
// along the gash within `axialReach` of x = 0 (the hob's ends), each with `tolerance` (mm). Two
// points within `tolerance` of each other in both r and x are one point measured twice.
struct PointRegion {
  double rootRadius = 0, outerRadius = 0, axialReach = 0, tolerance = 0;
  double maxDeviation = 0;  // µm
};

// Every point checked, or a refusal naming the first bad one (measuredPoints[k]): not three finite
// numbers, a deviation beyond maxDeviation, off the face, outside the ground region, or within
// the tolerance of an earlier point (a duplicate); an empty list is refused as measuredPoints.
Outcome<void> checkPoints(const std::vector<MeasuredPoint>& points, const PointRegion& region,
                          const std::string& field = "measuredPoints");

// The measured grid when the points are the grid's positions (each within `tolerance` of one,
// every position once, in any order); otherwise none: the points are corrected as points.
std::optional<Eigen::MatrixXd> gridFromPoints(const std::vector<MeasuredPoint>& points, const FaceGrid& grid,
                                              double tolerance);

// The points' positions and their deviations (µm), in the points' order.
ProbePoints probePointsOf(const std::vector<MeasuredPoint>& points);
Eigen::VectorXd deviationsOf(const std::vector<MeasuredPoint>& points);

}  // namespace hobsharp
