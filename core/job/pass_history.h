// The case's earlier passes (`passes`, docs/case-format.md): not computed with, but each must fit
// the job as `axes`, `measured` (or `measuredPoints`) and `correction` do.
#pragma once

#include <vector>

#include "case_input.h"
#include "face_grid.h"
#include "outcome.h"

namespace hobsharp {

// Every pass checked, oldest first; the refusal names the field within it ("passes[1].axes.X").
Outcome<void> checkPasses(const std::vector<PassInput>& passes, int degree, const FaceGrid& grid, const PointRegion& region);

}  // namespace hobsharp
