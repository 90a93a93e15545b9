// The rake-face inspection with its class verdict (README, "Rake-face inspection"): every check
// that applies, graded by the normal-module band of the tolerance table; the hob's class is the
// worst graded check's, and that check limits it.
#pragma once

#include <optional>
#include <vector>

#include "face_checks.h"
#include "gash_spacing.h"
#include "inspection_check.h"
#include "tolerance_table.h"

namespace hobsharp {

struct CheckResult {
  Check check = Check::CuttingFaceForm;
  double value = 0;  // µm (µm per 100 mm for the gash lead); signed for alignment, lead, adjacent spacing
  Grade grade = Grade::NotGraded;
  std::vector<ToleranceClass> classes;  // the classes with a tolerance in the band, tightest first
  std::vector<double> tolerances;       // µm, one per class of `classes`
};

struct Inspection {
  std::optional<int> band;  // of the table, for the hob's normal module
  FaceChecks face;
  std::optional<GashSpacing> spacing;  // with per-gash deviations
  std::vector<CheckResult> checks;     // those that apply, in the order of kChecks
  Grade grade = Grade::NotGraded;      // the worst graded check's; "not graded" when none has a tolerance
  std::optional<Check> limiting;       // the check that sets `grade`

  const CheckResult* find(Check check) const;
};

Inspection inspect(const FaceChecks& face, const std::optional<GashSpacing>& spacing, const ToleranceTable& table,
                   double normalModule);

}  // namespace hobsharp
