#include "inspection.h"

#include <cmath>

namespace hobsharp {
namespace {

// How far into its grade a check is: |value| over the tolerance of the class it got (D's when
// outside D), to choose the limiting check among equal grades.
double shareOfTolerance(const CheckResult& c) {
  if (c.tolerances.empty()) return 0;
  for (std::size_t k = 0; k < c.classes.size(); ++k)
    if (gradeOf(c.classes[k]) == c.grade) return std::abs(c.value) / c.tolerances[k];
  return std::abs(c.value) / c.tolerances.back();
}

}  // namespace

const CheckResult* Inspection::find(Check check) const {
  for (const CheckResult& c : checks)
    if (c.check == check) return &c;
  return nullptr;
}

Inspection inspect(const FaceChecks& face, const std::optional<GashSpacing>& spacing, const ToleranceTable& table,
                   double normalModule) {
  Inspection out;
  out.band = moduleBand(table, normalModule);
  out.face = face;
  out.spacing = spacing;
  auto add = [&](Check check, double value) {
    CheckResult c;
    c.check = check;
    c.value = value;
    if (out.band) {
      for (ToleranceClass k : kClasses) {
        if (const std::optional<double> t = table.at(check, k, *out.band)) {
          c.classes.push_back(k);
          c.tolerances.push_back(*t);
        }
      }
      c.grade = gradeOf(table, check, *out.band, std::abs(value));
    }
    out.checks.push_back(c);
  };
  add(Check::CuttingFaceForm, face.cuttingFaceForm);
  add(Check::RadialAlignment, face.radialAlignment);
  if (face.gashLead) add(Check::GashLead, *face.gashLead);
  if (spacing) {
    add(Check::AdjacentSpacing, spacing->adjacentLargest);
    add(Check::CumulativeSpacing, spacing->cumulative);
  }
  const CheckResult* worst = nullptr;
  for (const CheckResult& c : out.checks) {
    if (c.grade == Grade::NotGraded) continue;
    if (!worst || c.grade > worst->grade || (c.grade == worst->grade && shareOfTolerance(c) > shareOfTolerance(*worst)))
      worst = &c;
  }
  if (worst) {
    out.grade = worst->grade;
    out.limiting = worst->check;
  }
  return out;
}

}  // namespace hobsharp
