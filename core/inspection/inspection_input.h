// What a case says about the inspection (`inspection`, docs/case-format.md): per-gash deviations
// (or per-gash topographies) for the spacing, and an edited tolerance table that replaces the default one.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "outcome.h"
#include "tolerance_table.h"

namespace hobsharp {

struct InspectionInput {
  std::vector<double> gashDeviations;        // µm at the pitch radius, gash 1 .. z; empty when not given
  std::optional<ToleranceTable> tolerances;  // empty: defaultToleranceTable()
  // One measured topography per gash, gash 1 .. z (µm, the grid's shape), instead of gashDeviations
  // (gash_faces.h); their shape is checked against the grid by resolveJob().
  std::vector<Eigen::MatrixXd> gashTopographies;
  // The measurement's expanded uncertainty U95 of a reading, µm (ISO 14253-1; docs/inspection.md).
  double uncertainty = kDefaultUncertainty;
  static constexpr double kDefaultUncertainty = 2;  // µm: a shop-floor gear measuring machine
  static constexpr double kLargestUncertainty = 100;  // µm
};

// The table the inspection grades by: the case's, or the default one.
const ToleranceTable& toleranceTableOf(const InspectionInput& in);

// The rules of checkGashDeviations() and checkToleranceTable(), naming inspection.* fields.
Outcome<void> checkInspectionInput(const InspectionInput& in);

}  // namespace hobsharp
