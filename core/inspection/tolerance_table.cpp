#include "tolerance_table.h"
#include "number_text.h"

#include <cmath>
#include <sstream>

namespace hobsharp {
namespace {

constexpr double kLargestTolerance = 1e4;  // µm

}  // namespace

std::optional<double> ToleranceTable::at(Check check, ToleranceClass c, int band) const {
  const auto& row = cells[static_cast<int>(check)][static_cast<int>(c)];
  if (band < 0 || band >= static_cast<int>(row.size())) return std::nullopt;
  return row[band];
}

Confidence ToleranceTable::confidenceAt(Check check, ToleranceClass c, int band) const {
  const auto& row = confidence[static_cast<int>(check)][static_cast<int>(c)];
  if (band < 0 || band >= static_cast<int>(row.size())) return fallback;
  return row[band];
}

std::optional<ToleranceClass> ToleranceTable::loosest(Check check, int band) const {
  std::optional<ToleranceClass> out;
  for (ToleranceClass c : kClasses)
    if (at(check, c, band)) out = c;
  return out;
}

std::optional<int> moduleBand(const ToleranceTable& table, double normalModule) {
  for (int b = 0; b < table.bands(); ++b)
    if (normalModule > table.moduleEdges[b] && normalModule <= table.moduleEdges[b + 1]) return b;
  return std::nullopt;
}

Grade gradeOf(const ToleranceTable& table, Check check, int band, double magnitude) {
  bool any = false;
  for (ToleranceClass c : kClasses) {
    const std::optional<double> t = table.at(check, c, band);
    if (!t) continue;
    any = true;
    if (magnitude <= *t) return gradeOf(c);
  }
  return any ? Grade::OutsideD : Grade::NotGraded;
}

Outcome<void> checkToleranceTable(const ToleranceTable& table, const std::string& field) {
  const std::string edges = field + ".moduleBands";
  if (table.moduleEdges.size() < 2)
    return refuse(edges, "needs at least two module edges (one band), such as [0.63, 1, 1.6].");
  for (std::size_t k = 0; k < table.moduleEdges.size(); ++k) {
    const double m = table.moduleEdges[k];
    const std::string cell = edges + "[" + std::to_string(k) + "]";
    if (!std::isfinite(m) || m <= 0) return refuse(cell, "must be a positive module in mm; got " + exactText(m) + ".");
    if (k > 0 && m <= table.moduleEdges[k - 1])
      return refuse(cell, "must be larger than the edge before it (" + numberText(table.moduleEdges[k - 1]) + " mm); got " +
                              exactText(m) + " mm.");
  }
  for (Check check : kChecks) {
    for (ToleranceClass c : kClasses) {
      const std::string row = field + ".checks." + checkName(check) + "." + className(c);
      const auto& cells = table.cells[static_cast<int>(check)][static_cast<int>(c)];
      if (!cells.empty() && static_cast<int>(cells.size()) != table.bands())
        return refuse(row, "has " + std::to_string(cells.size()) + " values; the table has " +
                               std::to_string(table.bands()) + " module bands.");
      for (std::size_t b = 0; b < cells.size(); ++b) {
        if (!cells[b]) continue;
        const std::string cell = row + "[" + std::to_string(b) + "]";
        const double t = *cells[b];
        if (!std::isfinite(t) || t <= 0 || t > kLargestTolerance)
          return refuse(cell, "must be a tolerance in µm above 0 and at most 10000; got " + exactText(t) + ".");
        for (int tighter = 0; tighter < static_cast<int>(c); ++tighter) {
          const std::optional<double> u = table.at(check, kClasses[tighter], static_cast<int>(b));
          if (u && *u > t)
            return refuse(cell, numberText(t) + " µm is tighter than class " + className(kClasses[tighter]) + "'s " + numberText(*u) +
                                    " µm in the same band; a looser class needs a tolerance at least as large.");
        }
      }
    }
  }
  return success();
}

}  // namespace hobsharp
