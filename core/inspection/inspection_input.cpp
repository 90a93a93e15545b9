#include "inspection_input.h"

#include "default_tolerances.h"
#include "gash_spacing.h"

namespace hobsharp {

const ToleranceTable& toleranceTableOf(const InspectionInput& in) {
  return in.tolerances ? *in.tolerances : defaultToleranceTable();
}

Outcome<void> checkInspectionInput(const InspectionInput& in) {
  if (!in.gashDeviations.empty())
    if (auto r = checkGashDeviations(in.gashDeviations, "inspection.gashDeviations"); !r) return r;
  if (in.tolerances)
    if (auto r = checkToleranceTable(*in.tolerances, "inspection.tolerances"); !r) return r;
  return success();
}

}  // namespace hobsharp
