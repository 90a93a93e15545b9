#include "inspection_plan.h"

#include <string>

#include "default_tolerances.h"
#include "measured_face.h"

namespace hobsharp {

const ToleranceTable& InspectionPlan::table() const { return ownTable ? *ownTable : defaultToleranceTable(); }

Outcome<InspectionPlan> inspectionPlan(const InspectionInput& in, double normalModule, const FaceGrid& grid,
                                       std::optional<int> gashes) {
  if (auto r = checkInspectionInput(in); !r) return r.error();  // docs/inspection.md
  // Spacing and indexing read gash k as the k-th of the hob's z: a list of another length is of
  // another hob.
  const auto perGash = [&](const char* field, std::size_t given, const char* what) -> Outcome<void> {
    if (!gashes || given == 0 || given == static_cast<std::size_t>(*gashes)) return success();
    return refuse(field, std::string("needs one ") + what + " per gash: the hob has " + std::to_string(*gashes) +
                             " gashes (hob.gashes); got " + std::to_string(given) + ".");
  };
  if (auto r = perGash("inspection.gashDeviations", in.gashDeviations.size(), "deviation"); !r) return r.error();
  if (auto r = perGash("inspection.gashTopographies", in.gashTopographies.size(), "topography"); !r) return r.error();
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
