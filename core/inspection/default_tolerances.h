// The default tolerance table: data/din3968-cutting-face.json (DIN 3968's cutting-face values as a
// hob maker's catalogue prints them; docs/inspection.md), turned into C++ when the
// build is configured (core/inspection/CMakeLists.txt), so that the core reads no file.
#pragma once

#include "inspection_check.h"
#include "tolerance_table.h"

namespace hobsharp {

const ToleranceTable& defaultToleranceTable();

// Where the default table's values of a check come from ("" when it has none).
const char* defaultToleranceSource(Check check);
// Where its values marked "series" come from ("" when it has none).
const char* defaultSeriesSource(Check check);

}  // namespace hobsharp
