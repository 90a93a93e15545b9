#include "inspection_check.h"

namespace hobsharp {

const char* checkName(Check check) {
  switch (check) {
    case Check::CuttingFaceForm: return "cuttingFaceForm";
    case Check::RadialAlignment: return "radialAlignment";
    case Check::GashLead: return "gashLead";
    case Check::AdjacentSpacing: return "adjacentSpacing";
    case Check::CumulativeSpacing: return "cumulativeSpacing";
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

}  // namespace hobsharp
