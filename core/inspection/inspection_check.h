// The rake-face checks of DIN 3968 that the calculator grades, and the accuracy classes AA to D
// (README, "Rake-face inspection").
#pragma once

#include <array>

namespace hobsharp {

enum class Check { CuttingFaceForm, RadialAlignment, GashLead, AdjacentSpacing, CumulativeSpacing };
constexpr int kCheckCount = 5;
constexpr std::array<Check, kCheckCount> kChecks{Check::CuttingFaceForm, Check::RadialAlignment, Check::GashLead,
                                                 Check::AdjacentSpacing, Check::CumulativeSpacing};

// The classes, tightest first.
enum class ToleranceClass { AA, A, B, C, D };
constexpr int kClassCount = 5;
constexpr std::array<ToleranceClass, kClassCount> kClasses{ToleranceClass::AA, ToleranceClass::A, ToleranceClass::B,
                                                           ToleranceClass::C, ToleranceClass::D};

// A check's verdict: a class, worse than D, or no tolerance to grade against. Worse grades are larger.
enum class Grade { AA, A, B, C, D, OutsideD, NotGraded };

// The name of a check as the case and the result write it: "cuttingFaceForm" .. "cumulativeSpacing".
const char* checkName(Check check);
const char* className(ToleranceClass c);  // "AA" .. "D"
const char* gradeName(Grade g);           // "AA" .. "D", "outside D", "not graded"
inline Grade gradeOf(ToleranceClass c) { return static_cast<Grade>(static_cast<int>(c)); }

}  // namespace hobsharp
