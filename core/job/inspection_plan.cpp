#include "inspection_plan.h"

#include <string>

#include "default_tolerances.h"
#include "measured_face.h"

namespace hobsharp {

const ToleranceTable& InspectionPlan::table() const { return ownTable ? *ownTable : defaultToleranceTable(); }

Outcome<InspectionPlan> inspectionPlan(const InspectionInput& in, double normalModule, const FaceGrid& grid) {
  if (auto r = checkInspectionInput(in); !r) return r.error();  // docs/inspection.md
  for (std::size_t k = 0; k < in.gashTopographies.size(); ++k)
    if (auto r = checkMeasured(in.gashTopographies[k], grid, "inspection.gashTopographies[" + std::to_string(k) + "]"); !r)
      return r.error();
  InspectionPlan plan;
  plan.normalModule = normalModule;
  plan.gashDeviations = in.gashDeviations;
  plan.gashTopographies = in.gashTopographies;
  plan.ownTable = in.tolerances;
  plan.uncertainty = MeasurementUncertainty::of(in.uncertainty, grid.x.back() - grid.x.front());
  return plan;
}

}  // namespace hobsharp
