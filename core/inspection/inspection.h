// The rake-face inspection with its class verdict (docs/inspection.md): every check that applies,
// graded by the normal-module band of the tolerance table; the hob's class is the worst graded
// check's, and that check limits it. Each grade is also judged against the measurement's
// uncertainty U (ISO 14253-1): the class the measurement proves takes U off every tolerance.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "face_checks.h"
#include "gash_spacing.h"
#include "inspection_check.h"
#include "tolerance_table.h"

namespace hobsharp {

// The measurement's expanded uncertainty (U95) in each check's unit.
struct MeasurementUncertainty {
  double deviation = 2;  // µm, of a reading (inspection.uncertainty)
  double lead = 0;       // µm per 100 mm: U over the axial length measured, scaled to 100 mm

  // U for a deviation, and for the gash lead measured over `axialLength` (mm).
  static MeasurementUncertainty of(double deviation, double axialLength);
  double of(Check check) const { return check == Check::GashLead ? lead : deviation; }
};

struct CheckResult {
  Check check = Check::CuttingFaceForm;
  double value = 0;  // µm (µm per 100 mm for the gash lead); signed for alignment, lead, spacing
  Grade grade = Grade::NotGraded;
  std::optional<ToleranceClass> loosest;  // the loosest class with a tolerance in the band: "outside" it
  std::vector<ToleranceClass> classes;    // the classes with a tolerance in the band, tightest first
  std::vector<double> tolerances;         // µm, one per class of `classes`
  Confidence confidence = Confidence::Entered;  // of the tolerance the grade rests on
  double uncertainty = 0;                       // U in the check's unit
  Grade proven = Grade::NotGraded;  // the tightest class whose tolerance less U holds |value|; OutsideD: none
  Conformity conformity = Conformity::NotGraded;  // to the class graded (to the loosest when outside it)
};

struct Inspection {
  std::optional<int> band;  // of the table, for the hob's normal module
  FaceChecks face;
  std::optional<GashSpacing> spacing;  // with per-gash deviations
  std::vector<CheckResult> checks;     // those that apply, in the order of kChecks
  Grade grade = Grade::NotGraded;      // the worst graded check's; "not graded" when none has a tolerance
  std::optional<Check> limiting;       // the check that sets `grade`
  Grade proven = Grade::NotGraded;     // the worst graded check's proven class; OutsideD: none proven
  Conformity conformity = Conformity::NotGraded;  // of every graded check to the class `grade`
  MeasurementUncertainty uncertainty;
  std::vector<Check> uncertaintyAboveTenth;  // graded checks whose U exceeds a tenth of their tolerance
  // Why the face's checks (form, alignment, lead) carry their readings but no grade ("" when they
  // are graded as the table allows): the face inspected does not stand for the one measured.
  std::string faceNotGraded;

  const CheckResult* find(Check check) const;
};

// `faceNotGraded`: a reason to leave the face's checks ungraded (Inspection::faceNotGraded).
Inspection inspect(const FaceChecks& face, const std::optional<GashSpacing>& spacing, const ToleranceTable& table,
                   double normalModule, const MeasurementUncertainty& uncertainty, const std::string& faceNotGraded = {});

// A grade in words: "AA" .. "D", "outside D" ("outside B" where the table stops at B), "not graded".
std::string gradeText(Grade grade, std::optional<ToleranceClass> loosest);
// The class an inspection's verdict names, in words (its limiting check's loosest class for "outside").
std::string classText(const Inspection& in);
// A proven class in words: "AA" .. "D", or "none" (no class proven), "not graded".
std::string provenText(Grade proven);

}  // namespace hobsharp
