// A measurement at the measuring machine's own points (`measuredPoints`, docs/case-format.md):
// each point a radius r and axial position x on the rake face (mm) and the normal deviation there
// (µm). The correction and the inspection take the points as the grid's rows: a point lies at a
// grid position when it is within the grid tolerance of it, and the points must cover every grid
// position once. No value is interpolated (README, "Measured points").
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "face_grid.h"
#include "outcome.h"

namespace hobsharp {

struct MeasuredPoint {
  double r = 0, x = 0;    // mm
  double deviation = 0;   // µm, plus = excess material
};

// Where the points may lie: on the rake face between the gash root and the outer radius, and
// along the gash within `axialReach` of x = 0 (the hob's ends), each with `tolerance` (mm).
struct PointRegion {
  double rootRadius = 0, outerRadius = 0, axialReach = 0, tolerance = 0;
  double maxDeviation = 0;  // µm
};

// The measured grid the points make, or a refusal naming the point (measuredPoints[k]): a
// deviation beyond maxDeviation, a point off the face or outside the ground region, one at no
// grid position, a second point at one position; or naming the grid position no point covers.
Outcome<Eigen::MatrixXd> gridFromPoints(const std::vector<MeasuredPoint>& points, const FaceGrid& grid,
                                        const PointRegion& region);

}  // namespace hobsharp
