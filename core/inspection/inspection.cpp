#include "inspection.h"

#include <cmath>

namespace hobsharp {
namespace {

constexpr double kLeadLength = 100;  // mm: the gash lead is stated per 100 mm

// How far into its grade a check is: |value| over the tolerance of the class it got (the loosest's
// when outside), to choose the limiting check among equal grades.
double shareOfTolerance(const CheckResult& c) {
  if (c.tolerances.empty()) return 0;
  for (std::size_t k = 0; k < c.classes.size(); ++k)
    if (gradeOf(c.classes[k]) == c.grade) return std::abs(c.value) / c.tolerances[k];
  return std::abs(c.value) / c.tolerances.back();
}

// The tolerance of class `g` among the check's (or of its loosest class when g is outside it).
double toleranceOf(const CheckResult& c, Grade g) {
  for (std::size_t k = 0; k < c.classes.size(); ++k)
    if (gradeOf(c.classes[k]) == g) return c.tolerances[k];
  return c.tolerances.back();
}

// ISO 14253-1 against the tolerance T of the class graded: conformance is proven within T - U,
// non-conformance beyond T + U.
Conformity conformityTo(double magnitude, double tolerance, double u) {
  if (magnitude <= tolerance - u) return Conformity::Conforms;
  if (magnitude > tolerance + u) return Conformity::DoesNotConform;
  return Conformity::Undecided;
}

// The reading a grade compares: |value| to 1e-6 µm (or µm per 100 mm). A reading computed at a
// tolerance (25 µm as 34.7 - 16.0 x 24.25 / 40) carries rounding of about 1e-14 µm, which must not
// move it into the next class.
double gradedMagnitude(double value) { return std::round(std::abs(value) * 1e6) / 1e6; }

}  // namespace

MeasurementUncertainty MeasurementUncertainty::of(double deviation, double axialLength) {
  MeasurementUncertainty u;
  u.deviation = deviation;
  // The lead is a slope read over the axial length L: a reading's U there is U * 100 / L per 100 mm.
  u.lead = axialLength > 0 ? deviation * kLeadLength / axialLength : 0;
  return u;
}

const CheckResult* Inspection::find(Check check) const {
  for (const CheckResult& c : checks)
    if (c.check == check) return &c;
  return nullptr;
}

Inspection inspect(const FaceChecks& face, const std::optional<GashSpacing>& spacing, const ToleranceTable& table,
                   double normalModule, const MeasurementUncertainty& uncertainty, const std::string& faceNotGraded) {
  Inspection out;
  out.faceNotGraded = faceNotGraded;
  out.band = moduleBand(table, normalModule);
  out.face = face;
  out.spacing = spacing;
  out.uncertainty = uncertainty;
  auto add = [&](Check check, double value, bool graded = true) {
    CheckResult c;
    c.check = check;
    c.value = value;
    c.uncertainty = uncertainty.of(check);
    if (out.band) {
      for (ToleranceClass k : kClasses) {
        if (const std::optional<double> t = table.at(check, k, *out.band)) {
          c.classes.push_back(k);
          c.tolerances.push_back(*t);
        }
      }
      c.loosest = table.loosest(check, *out.band);
      const double magnitude = gradedMagnitude(value);
      c.grade = graded ? gradeOf(table, check, *out.band, magnitude) : Grade::NotGraded;
      if (c.grade != Grade::NotGraded) {
        const ToleranceClass rests = c.grade == Grade::OutsideD ? *c.loosest : static_cast<ToleranceClass>(c.grade);
        c.confidence = table.confidenceAt(check, rests, *out.band);
        c.conformity = conformityTo(magnitude, toleranceOf(c, c.grade), c.uncertainty);
        c.proven = Grade::OutsideD;
        for (std::size_t k = 0; k < c.classes.size(); ++k) {
          if (magnitude <= c.tolerances[k] - c.uncertainty) {
            c.proven = gradeOf(c.classes[k]);
            break;
          }
        }
        if (c.uncertainty > 0.1 * toleranceOf(c, c.grade)) out.uncertaintyAboveTenth.push_back(check);
      }
    }
    out.checks.push_back(c);
  };
  const bool faceGraded = faceNotGraded.empty();
  add(Check::CuttingFaceForm, face.cuttingFaceForm, faceGraded);
  add(Check::RadialAlignment, face.radialAlignment, faceGraded);
  if (face.gashLead) add(Check::GashLead, *face.gashLead, faceGraded);
  if (spacing) {
    add(Check::AdjacentSpacing, spacing->adjacentLargest);
    add(Check::PitchJump, spacing->pitchJumpLargest);
  }
  const CheckResult* worst = nullptr;
  for (const CheckResult& c : out.checks) {
    if (c.grade == Grade::NotGraded) continue;
    if (!worst || c.grade > worst->grade || (c.grade == worst->grade && shareOfTolerance(c) > shareOfTolerance(*worst)))
      worst = &c;
    if (out.proven == Grade::NotGraded || c.proven > out.proven) out.proven = c.proven;
  }
  if (worst) {
    out.grade = worst->grade;
    out.limiting = worst->check;
    // The hob's class holds when every graded check holds that class's tolerance (a check with no
    // tolerance in that class, being looser, is judged against its own grade).
    out.conformity = Conformity::Conforms;
    for (const CheckResult& c : out.checks) {
      if (c.grade == Grade::NotGraded) continue;
      bool has = false;
      for (ToleranceClass k : c.classes) has = has || gradeOf(k) == out.grade;
      const Conformity k = has ? conformityTo(gradedMagnitude(c.value), toleranceOf(c, out.grade), c.uncertainty) : c.conformity;
      if (k == Conformity::DoesNotConform) out.conformity = k;
      else if (k == Conformity::Undecided && out.conformity == Conformity::Conforms) out.conformity = k;
    }
  }
  return out;
}

std::string gradeText(Grade grade, std::optional<ToleranceClass> loosest) {
  if (grade == Grade::OutsideD && loosest) return std::string("outside ") + className(*loosest);
  return gradeName(grade);
}

std::string classText(const Inspection& in) {
  const CheckResult* c = in.limiting ? in.find(*in.limiting) : nullptr;
  return gradeText(in.grade, c ? c->loosest : std::nullopt);
}

std::string provenText(Grade proven) {
  if (proven == Grade::OutsideD) return "none";
  return gradeName(proven);
}

}  // namespace hobsharp
