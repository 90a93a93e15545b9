// What the rake-face inspection (docs/inspection.md) takes from the case, checked against the job:
// the gashes (deviations or one topography per gash on the job's grid), the tolerance table, the
// measurement's uncertainty and the hob's normal module that picks the table's band.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "face_grid.h"
#include "inspection.h"
#include "inspection_input.h"
#include "outcome.h"
#include "tolerance_table.h"

namespace hobsharp {

struct InspectionPlan {
  double normalModule = 0;                    // mm
  std::vector<double> gashDeviations;         // µm at the pitch radius, gash 1 .. z; empty when not given
  std::vector<Eigen::MatrixXd> gashTopographies;  // µm on the job's grid, gash 1 .. z; empty when not given
  std::optional<ToleranceTable> ownTable;     // the case's table; empty: the default one
  MeasurementUncertainty uncertainty;         // U95 of a reading, and of the gash lead over the grid's length
  const ToleranceTable& table() const;        // the table the inspection grades by
};

// The case's `inspection` (checkInspectionInput) with its gash topographies checked against the
// grid, the refusal naming the inspection.* field; `normalModule` is hob.normalModule (mm). Where
// the hob's gashes are given (hob.gashes, z), the gashes given must be z: one per gash.
Outcome<InspectionPlan> inspectionPlan(const InspectionInput& in, double normalModule, const FaceGrid& grid,
                                       std::optional<int> gashes = std::nullopt);

}  // namespace hobsharp
