// A tolerance table by normal-module band and class (docs/inspection.md): DIN 3968's
// cutting-face values as a hob maker's catalogue prints them (defaultToleranceTable()), or the
// engineer's edited table from the case (`inspection.tolerances`, docs/case-format.md).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "inspection_check.h"
#include "outcome.h"

namespace hobsharp {

struct ToleranceTable {
  // Band b holds the normal modules over moduleEdges[b] up to and including moduleEdges[b + 1], mm.
  std::vector<double> moduleEdges;
  // Per check and class, one tolerance per band in µm (a ± value is its magnitude); an empty list
  // where the table has no row for that class, an empty cell where it has no value.
  std::array<std::array<std::vector<std::optional<double>>, kClassCount>, kCheckCount> cells;
  // Per cell, where its value comes from; empty rows (or cells past a row's end) are `fallback`'s.
  std::array<std::array<std::vector<Confidence>, kClassCount>, kCheckCount> confidence;
  Confidence fallback = Confidence::Entered;

  int bands() const { return moduleEdges.size() < 2 ? 0 : static_cast<int>(moduleEdges.size()) - 1; }
  std::optional<double> at(Check check, ToleranceClass c, int band) const;
  Confidence confidenceAt(Check check, ToleranceClass c, int band) const;
  // The loosest class with a value in the band (the one "outside" refers to), if any.
  std::optional<ToleranceClass> loosest(Check check, int band) const;
};

// The band of a normal module, or empty when the table's bands do not reach it.
std::optional<int> moduleBand(const ToleranceTable& table, double normalModule);

// The tightest class whose tolerance in the band holds `magnitude` (µm, >= 0); "outside D" when
// none does; "not graded" when the band has no tolerance for the check at all. A class without a
// value is skipped: a deviation within the next class's value gets that class.
Grade gradeOf(const ToleranceTable& table, Check check, int band, double magnitude);

// The table's rules: at least one band, edges positive, finite and increasing; every class row
// empty or one cell per band; every value positive and at most 10 mm; within a band, no class
// tighter than another with a larger tolerance. `field` names the table in the message
// ("inspection.tolerances"); a cell is named as field.checks.<check>.<class>[band].
Outcome<void> checkToleranceTable(const ToleranceTable& table, const std::string& field);

}  // namespace hobsharp
