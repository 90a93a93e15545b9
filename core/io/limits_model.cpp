#include "limits_model.h"

#include <nlohmann/json.hpp>

#include "axis_polynomials.h"
#include "case_input.h"
#include "case_json.h"
#include "correction_options.h"
#include "default_tolerances.h"
#include "evaluation.h"
#include "gash_spacing.h"
#include "inspection_input.h"
#include "result_model.h"

namespace hobsharp {
namespace {

// Records the entries, not their values.
class LimitList final : public LimitsVisitor {
 public:
  std::vector<LimitDescription> entries;

  void text(const LimitField& f, const std::string&) override { add(f, LimitKind::Text); }
  void texts(const LimitField& f, const std::vector<std::string>&) override { add(f, LimitKind::Texts); }
  void count(const LimitField& f, int) override { add(f, LimitKind::Count); }
  void number(const LimitField& f, double) override { add(f, LimitKind::Number); }
  void range(const LimitField& f, const LimitRange&) override { add(f, LimitKind::Range); }
  void document(const LimitField& f, const std::string&) override { add(f, LimitKind::Document); }

 private:
  void add(const LimitField& f, LimitKind kind) { entries.push_back({f.path, limitKindName(kind), f.unit, f.words}); }
};

// The machine's axes: per axis its name, kind and unit, as limits().axes[i].
void visitAxes(LimitsVisitor& v) {
  for (Axis a : kAxes) {
    const std::string base = "axes." + std::to_string(static_cast<int>(a)) + ".";
    const std::string name = base + "name", kind = base + "kind", unit = base + "unit";
    v.text({name.c_str(), "", "the axis's name, X .. B in the order of the result's axes"}, axisName(a));
    v.text({kind.c_str(), "", "\"linear\" or \"rotary\""}, isRotary(a) ? "rotary" : "linear");
    v.text({unit.c_str(), "", "the unit of the axis's position in the result: \"mm\" or \"rad\""}, axisUnit(a));
  }
}

// The correction's options (docs/method.md, "Correction"): methods, the probe noise and the
// resolution of each axis (µm for X, Y, Z, degrees for A, B) with their defaults and ranges.
void visitCorrection(LimitsVisitor& v) {
  const CorrectionOptions defaults;
  v.texts({"correction.methods", "", "the correction's methods"}, {"nonlinear", "linear"});
  v.text({"correction.defaultMethod", "", "the method a case without correction.method gets"}, "nonlinear");
  v.range({"correction.probeNoise", "µm", "the probe noise sigma: its default and the largest taken"},
          {defaults.probeNoise, std::nullopt, kMaxDeviation});
  for (Axis a : kAxes) {
    const std::string path = std::string("correction.resolution.") + axisName(a);
    const bool rotary = isRotary(a);
    v.range({path.c_str(), rotary ? "deg" : "µm", "the machine's position resolution of the axis: its default and range"},
            {defaults.resolution.step[static_cast<int>(a)], rotary ? kLeastRotaryResolution : kLeastLinearResolution,
             rotary ? kMostRotaryResolution : kMostLinearResolution});
  }
  v.count({"correction.coefficientDigits", "", "the significant digits the NC program carries each coefficient with (correction.roundedAxes)"},
          defaults.resolution.coefficientDigits);
}

// The inspection's names, limits and default tolerance table (docs/inspection.md).
void visitInspection(LimitsVisitor& v) {
  std::vector<std::string> checks, classes;
  for (Check c : kChecks) checks.push_back(checkName(c));
  for (ToleranceClass k : kClasses) classes.push_back(className(k));
  v.texts({"inspection.checks", "", "the checks of DIN 3968, as inspection.checks names them"}, checks);
  v.texts({"inspection.classes", "", "the tolerance classes, tightest first"}, classes);
  v.count({"inspection.maxGashes", "", "the most gashes inspection.gashDeviations and inspection.gashTopographies take"}, kMaxGashes);
  v.number({"inspection.maxGashDeviation", "µm", "the largest |gash deviation| taken"}, kMaxGashDeviation);
  v.document({"inspection.defaultTolerances", "µm", "the default tolerance table, in the shape inspection.tolerances takes (hobsharp-tolerances/1)"},
             defaultToleranceJson());
  v.range({"inspection.uncertainty", "µm", "the measurement's uncertainty U95: its default and range"},
          {InspectionInput::kDefaultUncertainty, 0, InspectionInput::kLargestUncertainty});
}

}  // namespace

const char* limitKindName(LimitKind kind) {
  switch (kind) {
    case LimitKind::Text: return "string";
    case LimitKind::Texts: return "strings";
    case LimitKind::Count: return "integer";
    case LimitKind::Number: return "number";
    case LimitKind::Range: return "range";
    case LimitKind::Document: return "document";
  }
  return "";
}

void visitLimits(LimitsVisitor& v) {
  v.text({"format", "", "the case file's format"}, kCaseFormat);
  v.count({"maxGridLines", "", "the most grid lines in each direction"}, kMaxGridLines);
  v.number({"gridTolerance", "mm", "how far a grid may reach past the face (root, tip, hob ends)"}, kGridTolerance);
  v.range({"degree", "", "the axis polynomials' degree: its default and range"},
          {static_cast<double>(kDefaultDegree), static_cast<double>(kMinDegree), static_cast<double>(kMaxDegree)});
  v.count({"defaultGrid.radial", "", "grid lines root to tip a case without grid.radial gets"}, kDefaultGridRadial);
  v.count({"defaultGrid.axial", "", "grid lines along the gash a case without grid.axial gets"}, kDefaultGridAxial);
  v.count({"wheelProfilePoints", "", "the points of the wheel's axial profile in the result (wheelProfile)"}, kWheelProfilePoints);
  v.count({"maxWheelPoints", "", "the most points of a wheel's profile (wheel.profileOffset, wheel.measuredProfile)"}, kMaxWheelPoints);
  visitAxes(v);
  v.text({"motionUnits.helical", "", "the motion parameter's unit for a helical gash (phi_1)"}, motionUnit(GashKind::Helical));
  v.text({"motionUnits.straight", "", "the motion parameter's unit for a straight gash (s)"}, motionUnit(GashKind::Straight));
  visitCorrection(v);
  visitInspection(v);
}

std::vector<LimitDescription> limitFields() {
  LimitList list;
  visitLimits(list);
  return list.entries;
}

std::string defaultToleranceJson() {
  using Json = nlohmann::ordered_json;
  const ToleranceTable& t = defaultToleranceTable();
  Json table = Json::object();
  table["format"] = kToleranceFormat;
  table["moduleBands"] = t.moduleEdges;
  Json byCheck = Json::object();
  for (Check c : kChecks) {
    Json rows = Json::object();
    for (ToleranceClass k : kClasses) {
      const auto& cells = t.cells[static_cast<int>(c)][static_cast<int>(k)];
      if (cells.empty()) continue;
      Json row = Json::array();
      for (const auto& cell : cells) row.push_back(cell ? Json(*cell) : Json(nullptr));
      rows[className(k)] = std::move(row);
    }
    if (rows.empty()) continue;
    rows["source"] = defaultToleranceSource(c);
    // Where the data file marks its cells "printed" or "series", and the series' source: as the
    // file has them, so that a table edited on the page keeps the marks of the cells not edited.
    if (*defaultSeriesSource(c)) rows["seriesSource"] = defaultSeriesSource(c);
    Json confidence = Json::object();
    for (ToleranceClass k : kClasses) {
      const auto& words = t.confidence[static_cast<int>(c)][static_cast<int>(k)];
      if (words.empty()) continue;
      Json row = Json::array();
      for (Confidence w : words) row.push_back(confidenceName(w));
      confidence[className(k)] = std::move(row);
    }
    if (!confidence.empty()) rows["confidence"] = std::move(confidence);
    byCheck[checkName(c)] = std::move(rows);
  }
  table["checks"] = std::move(byCheck);
  return table.dump();
}

}  // namespace hobsharp
