// The embind layer: a case (JSON text) in; out, the result as a JS object built by a visitor of the
// result model (core/result_model.h), or the C++ JSON writer's text; and the module's limits and
// field list, read from the core's constants. Every call returns {ok: true, value} or
// {ok: false, code, field, message}; wasm/pre.js turns the latter into a thrown HobSharpError.
// No C++ exception crosses into JS: one caught here is reported with the code Internal.
#include <exception>
#include <string>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "case_input.h"
#include "case_json.h"
#include "default_tolerances.h"
#include "gash_spacing.h"
#include "inspection_input.h"
#include "result_model.h"

namespace hobsharp {
namespace {

using emscripten::val;

const char* codeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::InvalidInput: return "InvalidInput";
    case ErrorCode::Unsolvable: return "Unsolvable";
    case ErrorCode::Internal: return "Internal";
  }
  return "Internal";
}

// The result as JS data. Numeric lists are copied out of wasm memory at once, as Float64Arrays or
// (typed = false) as plain Arrays; a matrix is an Array of its rows.
class JsResult final : public ResultVisitor {
 public:
  explicit JsResult(bool typed) : typed_(typed) {}
  val root = val::object();

  void number(const ResultField& f, double x) override { set(f, val(x)); }
  void count(const ResultField& f, int x) override { set(f, val(x)); }
  void flag(const ResultField& f, bool x) override { set(f, val(x)); }
  void text(const ResultField& f, const std::string& x) override { set(f, val(x)); }
  void texts(const ResultField& f, const std::vector<std::string>& x) override {
    val a = val::array();
    for (const std::string& s : x) a.call<void>("push", s);
    set(f, a);
  }
  void numbers(const ResultField& f, const double* x, std::size_t n) override { set(f, list(x, n)); }
  void matrix(const ResultField& f, const double* x, int rows, int cols) override { set(f, grid(x, rows, cols)); }
  void matrices(const ResultField& f, const double* x, int count, int rows, int cols) override {
    val all = val::array();
    for (int k = 0; k < count; ++k) all.call<void>("push", grid(x + std::size_t(k) * rows * cols, rows, cols));
    set(f, all);
  }
  void axes(const ResultField& f, const AxisPolynomials& a) override {
    val o = val::object();
    for (Axis x : kAxes) o.set(axisName(x), list(a[x].a.data(), a[x].a.size()));
    set(f, o);
  }

 private:
  bool typed_;

  val list(const double* x, std::size_t n) const {
    const val view(emscripten::typed_memory_view(n, x));
    return typed_ ? view.call<val>("slice") : val::global("Array").call<val>("from", view);
  }
  val grid(const double* x, int rows, int cols) const {
    val g = val::array();
    for (int i = 0; i < rows; ++i) g.call<void>("push", list(x + std::size_t(i) * cols, std::size_t(cols)));
    return g;
  }
  // Sets "a.b.c", making the objects a and a.b on the way.
  void set(const ResultField& f, const val& value) {
    val node = root;
    const std::string path = f.path;
    std::size_t start = 0;
    for (std::size_t dot; (dot = path.find('.', start)) != std::string::npos; start = dot + 1) {
      const std::string key = path.substr(start, dot - start);
      val child = node[key];
      if (child.isUndefined()) {
        child = val::object();
        node.set(key, child);
      }
      node = child;
    }
    node.set(path.substr(start), value);
  }
};

val success(const val& value) {
  val o = val::object();
  o.set("ok", true);
  o.set("value", value);
  return o;
}

val failure(const Error& error) {
  val o = val::object();
  o.set("ok", false);
  o.set("code", std::string(codeName(error.code)));
  o.set("field", error.field);
  o.set("message", error.message);
  return o;
}

// Runs `work` on the evaluated case, with every failure as a value.
template <class Work>
val guarded(const std::string& caseText, Work work) {
  try {
    auto e = evaluateCase(caseText);
    if (!e) return failure(e.error());
    return success(work(*e));
  } catch (const std::exception& ex) {
    return failure(Error{"", std::string("The calculation failed: ") + ex.what(), ErrorCode::Internal});
  } catch (...) {
    return failure(Error{"", "The calculation failed for an unknown reason.", ErrorCode::Internal});
  }
}

val jsResult(const std::string& caseText, bool typedArrays) {
  return guarded(caseText, [typedArrays](const Evaluation& e) {
    JsResult r(typedArrays);
    visitResult(e, r);
    return r.root;
  });
}
val evaluateJson(const std::string& caseText) { return jsResult(caseText, false); }
val evaluateJsonTyped(const std::string& caseText) { return jsResult(caseText, true); }

val evaluateJsonText(const std::string& caseText) {
  return guarded(caseText, [](const Evaluation& e) { return val(resultJson(e, 1)); });
}

val resultFieldList() {
  val a = val::array();
  for (const FieldDescription& d : resultFields()) {
    val o = val::object();
    o.set("path", d.path);
    o.set("kind", d.kind);
    o.set("unit", d.unit);
    o.set("meaning", d.meaning);
    o.set("when", d.when);
    a.call<void>("push", o);
  }
  return a;
}

// The inspection's names, limits and default tolerance table (docs/inspection.md), the
// table in the shape `inspection.tolerances` takes, so the page can show it, edit it and save it.
val inspectionLimits() {
  val o = val::object();
  val checks = val::array(), classes = val::array();
  for (Check c : kChecks) checks.call<void>("push", std::string(checkName(c)));
  for (ToleranceClass k : kClasses) classes.call<void>("push", std::string(className(k)));
  o.set("checks", checks);
  o.set("classes", classes);
  o.set("maxGashes", kMaxGashes);
  o.set("maxGashDeviation", kMaxGashDeviation);
  const ToleranceTable& t = defaultToleranceTable();
  val table = val::object();
  table.set("format", std::string(kToleranceFormat));
  val edges = val::array();
  for (double m : t.moduleEdges) edges.call<void>("push", m);
  table.set("moduleBands", edges);
  val byCheck = val::object();
  for (Check c : kChecks) {
    val rows = val::object();
    bool any = false;
    for (ToleranceClass k : kClasses) {
      const auto& cells = t.cells[static_cast<int>(c)][static_cast<int>(k)];
      if (cells.empty()) continue;
      val row = val::array();
      for (const auto& cell : cells) row.call<void>("push", cell ? val(*cell) : val::null());
      rows.set(className(k), row);
      any = true;
    }
    if (!any) continue;
    rows.set("source", std::string(defaultToleranceSource(c)));
    // Where the data file marks its cells "printed" or "series", and the series' source: as the
    // file has them, so that a table edited on the page keeps the marks of the cells not edited.
    if (*defaultSeriesSource(c)) rows.set("seriesSource", std::string(defaultSeriesSource(c)));
    val confidence = val::object();
    bool marked = false;
    for (ToleranceClass k : kClasses) {
      const auto& words = t.confidence[static_cast<int>(c)][static_cast<int>(k)];
      if (words.empty()) continue;
      val row = val::array();
      for (Confidence w : words) row.call<void>("push", std::string(confidenceName(w)));
      confidence.set(className(k), row);
      marked = true;
    }
    if (marked) rows.set("confidence", confidence);
    byCheck.set(checkName(c), rows);
  }
  table.set("checks", byCheck);
  o.set("defaultTolerances", table);
  // The measurement's uncertainty U95 (inspection.uncertainty): its default and range.
  val uncertainty = val::object();
  uncertainty.set("default", InspectionInput::kDefaultUncertainty);
  uncertainty.set("min", 0);
  uncertainty.set("max", InspectionInput::kLargestUncertainty);
  uncertainty.set("unit", std::string("µm"));
  o.set("uncertainty", uncertainty);
  return o;
}

// What the page needs to know before it has a result: the case file's limits and defaults.
val limits() {
  val o = val::object();
  o.set("format", std::string(kCaseFormat));
  o.set("maxGridLines", kMaxGridLines);
  o.set("gridTolerance", kGridTolerance);
  val degree = val::object();
  degree.set("min", kMinDegree);
  degree.set("max", kMaxDegree);
  degree.set("default", kDefaultDegree);
  o.set("degree", degree);
  val grid = val::object();
  grid.set("radial", kDefaultGridRadial);
  grid.set("axial", kDefaultGridAxial);
  o.set("defaultGrid", grid);
  o.set("wheelProfilePoints", kWheelProfilePoints);
  o.set("maxWheelPoints", kMaxWheelPoints);
  val axes = val::array();
  for (Axis a : kAxes) {
    val x = val::object();
    x.set("name", std::string(axisName(a)));
    x.set("kind", std::string(isRotary(a) ? "rotary" : "linear"));
    x.set("unit", std::string(axisUnit(a)));
    axes.call<void>("push", x);
  }
  o.set("axes", axes);
  val motion = val::object();
  motion.set("helical", std::string(motionUnit(GashKind::Helical)));
  motion.set("straight", std::string(motionUnit(GashKind::Straight)));
  o.set("motionUnits", motion);
  // The correction's options (docs/method.md, "Correction"): methods, the probe noise and the resolution
  // of each axis (µm for X, Y, Z, degrees for A, B) with their defaults and ranges.
  const CorrectionOptions defaults;
  val correction = val::object();
  val methods = val::array();
  methods.call<void>("push", std::string("nonlinear"));
  methods.call<void>("push", std::string("linear"));
  correction.set("methods", methods);
  correction.set("defaultMethod", std::string("nonlinear"));
  val noise = val::object();
  noise.set("default", defaults.probeNoise);
  noise.set("max", kMaxDeviation);
  noise.set("unit", std::string("µm"));
  correction.set("probeNoise", noise);
  val resolution = val::object();
  for (Axis a : kAxes) {
    val r = val::object();
    r.set("default", defaults.resolution.step[static_cast<int>(a)]);
    r.set("min", isRotary(a) ? kLeastRotaryResolution : kLeastLinearResolution);
    r.set("max", isRotary(a) ? kMostRotaryResolution : kMostLinearResolution);
    r.set("unit", std::string(isRotary(a) ? "deg" : "µm"));
    resolution.set(axisName(a), r);
  }
  correction.set("resolution", resolution);
  // The significant digits the NC program carries each coefficient with (correction.roundedAxes).
  correction.set("coefficientDigits", defaults.resolution.coefficientDigits);
  o.set("correction", correction);
  o.set("inspection", inspectionLimits());
  return o;
}

}  // namespace
}  // namespace hobsharp

EMSCRIPTEN_BINDINGS(hobsharp) {
  emscripten::function("evaluateJson", &hobsharp::evaluateJson);
  emscripten::function("evaluateJsonTyped", &hobsharp::evaluateJsonTyped);
  emscripten::function("evaluateJsonText", &hobsharp::evaluateJsonText);
  emscripten::function("resultFields", &hobsharp::resultFieldList);
  emscripten::function("limits", &hobsharp::limits);
}
