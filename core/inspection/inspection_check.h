// The rake-face checks of DIN 3968 that the calculator grades, and the accuracy classes AA to D
// (docs/inspection.md).
#pragma once

#include <array>
#include <optional>
#include <string>

namespace hobsharp {

// docs/inspection.md says what each measures and which table row grades it.
enum class Check { CuttingFaceForm, RadialAlignment, GashLead, AdjacentSpacing, PitchJump };
constexpr int kCheckCount = 5;
constexpr std::array<Check, kCheckCount> kChecks{Check::CuttingFaceForm, Check::RadialAlignment, Check::GashLead,
                                                 Check::AdjacentSpacing, Check::PitchJump};

// The classes, tightest first.
enum class ToleranceClass { AA, A, B, C, D };
constexpr int kClassCount = 5;
constexpr std::array<ToleranceClass, kClassCount> kClasses{ToleranceClass::AA, ToleranceClass::A, ToleranceClass::B,
                                                           ToleranceClass::C, ToleranceClass::D};

// A check's verdict: a class, worse than the loosest class the table gives (D's, or B's where the
// table stops at B), or no tolerance to grade against. Worse grades are larger.
enum class Grade { AA, A, B, C, D, OutsideD, NotGraded };

// Where a tolerance comes from: printed in the source the table names, filled from the series the
// source prints for other rows (not confirmed), or entered by the engineer (the case's own table).
enum class Confidence { Printed, Series, Entered };

// ISO 14253-1: a check conforms when its value lies within the tolerance less the measurement's
// uncertainty U, does not conform when beyond the tolerance plus U, and is undecided in between.
enum class Conformity { Conforms, DoesNotConform, Undecided, NotGraded };

// The name of a check as the case and the result write it: "cuttingFaceForm" .. "cumulativeSpacing".
const char* checkName(Check check);
const char* className(ToleranceClass c);  // "AA" .. "D"
const char* checkWords(Check check);      // "cutting-face form" .. "pitch jump", as the engineer says it
const char* gradeName(Grade g);           // "AA" .. "D", "outside D", "not graded"
const char* confidenceName(Confidence c);  // "printed", "series", "entered"
std::optional<Confidence> confidenceNamed(const std::string& name);  // confidenceName's inverse
const char* conformityName(Conformity c);  // "conforms", "does not conform", "undecided", "not graded"
inline Grade gradeOf(ToleranceClass c) { return static_cast<Grade>(static_cast<int>(c)); }

}  // namespace hobsharp
