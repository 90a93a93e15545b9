// Reads a `hobsharp-case/1` document (docs/case-format.md) into typed values. Text in, typed
// CaseInput or an Error naming the field out; nothing throws. Value rules are checked later by
// resolveJob(); here only presence, type, finiteness, shape and unknown names.
#pragma once

#include <string>

#include "case_input.h"
#include "outcome.h"

namespace hobsharp {

inline constexpr const char* kCaseFormat = "hobsharp-case/1";

Outcome<CaseInput> parseCase(const std::string& json);

}  // namespace hobsharp
