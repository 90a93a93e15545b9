// The case's earlier passes (`passes`, docs/case-format.md): each must fit the job as `axes`,
// `measured` (or `measuredPoints`) and `correction` do; those measured on the grid are the history
// the machine's error is identified with (core/correction/earlier_passes.h).
#pragma once

#include <vector>

#include "case_input.h"
#include "face_grid.h"
#include "outcome.h"
#include "earlier_passes.h"

namespace hobsharp {

// Every pass checked, oldest first; the refusal names the field within it ("passes[1].axes.X").
Outcome<void> checkPasses(const std::vector<PassInput>& passes, int degree, const FaceGrid& grid, const PointRegion& region);

// The checked passes as the identification's history: those measured on the grid, oldest first.
// None where the wheel may have changed between the passes (this case or any pass asks for the
// wheel's correction, whose dressing changes the wheel): their faces were ground with another wheel.
PassHistory passHistory(const std::vector<PassInput>& passes, const AxisPolynomials& nominal, bool wheelCorrected);

}  // namespace hobsharp
