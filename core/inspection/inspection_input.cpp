#include "inspection_input.h"

#include <cmath>
#include <string>

#include "default_tolerances.h"
#include "gash_spacing.h"
#include "number_text.h"

namespace hobsharp {

const ToleranceTable& toleranceTableOf(const InspectionInput& in) {
  return in.tolerances ? *in.tolerances : defaultToleranceTable();
}

Outcome<void> checkInspectionInput(const InspectionInput& in) {
  if (!in.gashDeviations.empty() && !in.gashTopographies.empty())
    return refuse("inspection.gashTopographies", "give the gashes as gashDeviations or as gashTopographies, not both.");
  if (!in.gashTopographies.empty() &&
      (in.gashTopographies.size() < 2 || in.gashTopographies.size() > static_cast<std::size_t>(kMaxGashes)))
    return refuse("inspection.gashTopographies", "needs one topography per gash, 2 to " + std::to_string(kMaxGashes) +
                                                      " of them; got " + std::to_string(in.gashTopographies.size()) + ".");
  if (!in.gashDeviations.empty())
    if (auto r = checkGashDeviations(in.gashDeviations, "inspection.gashDeviations"); !r) return r;
  if (!std::isfinite(in.uncertainty) || in.uncertainty < 0 || in.uncertainty > InspectionInput::kLargestUncertainty)
    return refuse("inspection.uncertainty", "must be the measurement's uncertainty U95 in µm, 0 to 100; got " +
                                                exactText(in.uncertainty) + " µm.");
  if (in.tolerances)
    if (auto r = checkToleranceTable(*in.tolerances, "inspection.tolerances"); !r) return r;
  return success();
}

}  // namespace hobsharp
