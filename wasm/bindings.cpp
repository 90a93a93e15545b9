// The embind layer: a case (JSON text) in; out, the result as a JS object built by a visitor of the
// result model (core/io/result_model.h), or the C++ JSON writer's text; the result's field list;
// and the module's limits, as a visitor of their description (core/io/limits_model.h). Every call
// returns {ok: true, value} or {ok: false, code, field, message}; wasm/pre.js turns the latter into a thrown HobSharpError.
// No C++ exception crosses into JS: one caught here is reported with the code Internal.
#include <exception>
#include <string>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "limits_model.h"
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

// Sets "a.b.c" in `root`, making the objects a and a.b on the way; a segment that is a number is
// an index into a list ("axes.0.name").
void setAt(val root, const std::string& path, const val& value) {
  const auto isIndex = [](const std::string& key) { return !key.empty() && key.find_first_not_of("0123456789") == std::string::npos; };
  val node = root;
  std::size_t start = 0;
  for (std::size_t dot; (dot = path.find('.', start)) != std::string::npos; start = dot + 1) {
    const std::string key = path.substr(start, dot - start);
    const std::size_t next = path.find('.', dot + 1);
    val child = node[key];
    if (child.isUndefined()) {
      child = isIndex(path.substr(dot + 1, next == std::string::npos ? std::string::npos : next - dot - 1)) ? val::array() : val::object();
      node.set(key, child);
    }
    node = child;
  }
  node.set(path.substr(start), value);
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
  void set(const ResultField& f, const val& value) { setAt(root, f.path, value); }
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

// A description list as a JS array of objects, each given its members by `members(object, d)`.
template <class Description, class Members>
val descriptionList(const std::vector<Description>& list, Members members) {
  val a = val::array();
  for (const Description& d : list) {
    val o = val::object();
    members(o, d);
    a.call<void>("push", o);
  }
  return a;
}

val resultFieldList() {
  return descriptionList(resultFields(), [](val& o, const FieldDescription& d) {
    o.set("path", d.path);
    o.set("kind", d.kind);
    o.set("unit", d.unit);
    o.set("meaning", d.meaning);
    o.set("when", d.when);
    o.set("label", d.label);
  });
}

// The limits as JS data: each entry set at its path (limits_model.h), a range as {default, min,
// max, unit}, a document parsed.
class JsLimits final : public LimitsVisitor {
 public:
  val root = val::object();

  void text(const LimitField& f, const std::string& x) override { setAt(root, f.path, val(x)); }
  void texts(const LimitField& f, const std::vector<std::string>& x) override {
    val a = val::array();
    for (const std::string& s : x) a.call<void>("push", s);
    setAt(root, f.path, a);
  }
  void count(const LimitField& f, int x) override { setAt(root, f.path, val(x)); }
  void number(const LimitField& f, double x) override { setAt(root, f.path, val(x)); }
  void range(const LimitField& f, const LimitRange& r) override {
    val o = val::object();
    o.set("default", r.defaultValue);
    if (r.min) o.set("min", *r.min);
    if (r.max) o.set("max", *r.max);
    if (*f.unit) o.set("unit", std::string(f.unit));
    setAt(root, f.path, o);
  }
  void document(const LimitField& f, const std::string& json) override {
    setAt(root, f.path, val::global("JSON").call<val>("parse", json));
  }
};

// The limits' entries as core/io/limits_model.h describes them: [{path, kind, unit, words}].
val limitFieldList() {
  return descriptionList(limitFields(), [](val& o, const LimitDescription& d) {
    o.set("path", d.path);
    o.set("kind", d.kind);
    o.set("unit", d.unit);
    o.set("words", d.words);
  });
}

// What the page needs to know before it has a result: the case file's limits and defaults.
val limits() {
  JsLimits l;
  visitLimits(l);
  return l.root;
}

}  // namespace
}  // namespace hobsharp

EMSCRIPTEN_BINDINGS(hobsharp) {
  emscripten::function("evaluateJson", &hobsharp::evaluateJson);
  emscripten::function("evaluateJsonTyped", &hobsharp::evaluateJsonTyped);
  emscripten::function("evaluateJsonText", &hobsharp::evaluateJsonText);
  emscripten::function("resultFields", &hobsharp::resultFieldList);
  emscripten::function("limits", &hobsharp::limits);
  emscripten::function("limitFields", &hobsharp::limitFieldList);
}
