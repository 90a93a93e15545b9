// Reads a `hobsharp-case/1` document (docs/case-format.md) into typed values. Text in, typed
// CaseInput or an Error naming the field out (the JSON path; "case" for the document itself);
// nothing throws. Value rules are checked later by resolveJob(); here only JSON syntax, nesting
// depth, presence, type, finiteness, shape and unknown names.
#pragma once

#include <string>

#include "case_input.h"
#include "outcome.h"

namespace hobsharp {

inline constexpr const char* kCaseFormat = "hobsharp-case/1";
// The tolerance table's format (data/din3968-cutting-face.json, `inspection.tolerances`).
inline constexpr const char* kToleranceFormat = "hobsharp-tolerances/1";

// Lists and objects nest at most this deep in a case file; a real one nests them 3 deep
// (measured rows in a list in the document). Deeper text is refused before it is read.
inline constexpr int kMaxCaseNesting = 64;

Outcome<CaseInput> parseCase(const std::string& json);

}  // namespace hobsharp
