#include "inspection_check.h"

namespace hobsharp {

const char* checkName(Check check) {
  switch (check) {
    case Check::CuttingFaceForm: return "cuttingFaceForm";
    case Check::RadialAlignment: return "radialAlignment";
    case Check::GashLead: return "gashLead";
    case Check::AdjacentSpacing: return "adjacentSpacing";
    case Check::PitchJump: return "pitchJump";
  }
  return "";
}

const char* checkWords(Check check) {
  switch (check) {
    case Check::CuttingFaceForm: return "cutting-face form";
    case Check::RadialAlignment: return "radial alignment";
    case Check::GashLead: return "gash lead";
    case Check::AdjacentSpacing: return "single pitch (adjacent spacing)";
    case Check::PitchJump: return "pitch jump";
  }
  return "";
}

const char* className(ToleranceClass c) {
  switch (c) {
    case ToleranceClass::AA: return "AA";
    case ToleranceClass::A: return "A";
    case ToleranceClass::B: return "B";
    case ToleranceClass::C: return "C";
    case ToleranceClass::D: return "D";
  }
  return "";
}

const char* gradeName(Grade g) {
  switch (g) {
    case Grade::OutsideD: return "outside D";
    case Grade::NotGraded: return "not graded";
    default: return className(static_cast<ToleranceClass>(static_cast<int>(g)));
  }
}

const char* confidenceName(Confidence c) {
  switch (c) {
    case Confidence::Printed: return "printed";
    case Confidence::Series: return "series";
    case Confidence::Entered: return "entered";
  }
  return "";
}

std::optional<Confidence> confidenceNamed(const std::string& name) {
  for (Confidence c : {Confidence::Printed, Confidence::Series, Confidence::Entered})
    if (name == confidenceName(c)) return c;
  return std::nullopt;
}

const char* conformityName(Conformity c) {
  switch (c) {
    case Conformity::Conforms: return "conforms";
    case Conformity::DoesNotConform: return "does not conform";
    case Conformity::Undecided: return "undecided";
    case Conformity::NotGraded: return "not graded";
  }
  return "";
}

}  // namespace hobsharp
