// A campaign scenario's pass as the case file `hobsharp-case/1` (docs/case-format.md) that the page
// loads and the command line evaluates: the hob, wheel, setup, machine, grid, the axes the machine
// ran, the face measured (with its noise), the correction's options and the earlier passes, every
// number as the double it is (nlohmann's shortest round-trip form), so that the file evaluates to
// the campaign's own correction of that pass (docs/validation.md, "Running it").
#pragma once

#include <nlohmann/json.hpp>

#include "case_input.h"

namespace hobsharp::validation {

nlohmann::json caseFile(const CaseInput& c);

}  // namespace hobsharp::validation
