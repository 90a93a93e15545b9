// The measured face the job corrects and inspects, resolved from the case's `measured` grid or
// its `measuredPoints` (docs/measured-points.md), with where it comes from; and the check of a
// measured grid against the job's grid (`measured`, a pass's, a gash's topography).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "face_grid.h"
#include "measured_points.h"
#include "outcome.h"
#include "probe_points.h"

namespace hobsharp {

// Where the face the inspection and the gear effect take comes from (inspection.source).
enum class FaceSource { Simulated, Measured, MeasuredPoints };
const char* sourceName(FaceSource s);  // "simulated", "measured", "measuredPoints"

// The measurement, as the correction takes it: on the job's grid (`measured`, or measuredPoints
// exactly at the grid's positions), or at the points themselves (measuredPoints off the grid);
// neither when the case gives no measurement (source Simulated).
struct MeasuredFace {
  FaceSource source = FaceSource::Simulated;
  std::optional<Eigen::MatrixXd> grid;  // µm, grid.radial x grid.axial
  ProbePoints probes;                   // measuredPoints off the grid, in the case's order
  Eigen::VectorXd deviations;           // µm, at `probes`
  bool given() const { return grid || !probes.empty(); }
  bool atPoints() const { return !probes.empty(); }
  // A measured grid (µm), as `measured` gives it.
  static MeasuredFace onGrid(Eigen::MatrixXd measured);
};

// A measured grid of the grid's shape, every value finite and within ±kMaxDeviation; `name` is
// its field ("measured", "passes[1].measured"). The field of a refused value is its path (for the
// page to find the input); the message names its row and value from 1, with r and x.
Outcome<void> checkMeasured(const Eigen::MatrixXd& m, const FaceGrid& grid, const std::string& name);

// The case's measurement on `grid`: `measured` checked against it, or `measuredPoints` checked
// against `region` and taken as the grid when they are its positions (gridFromPoints); refused
// when the case gives both.
Outcome<MeasuredFace> measuredFace(const std::optional<Eigen::MatrixXd>& measured,
                                   const std::optional<std::vector<MeasuredPoint>>& measuredPoints, const FaceGrid& grid,
                                   const PointRegion& region);

}  // namespace hobsharp
