// The result of one evaluation, described once: every field the calculator hands out, with its
// path, unit and meaning, visited in one order. Every output is a visitor of this walk: the JSON
// text (command line, native_eval), the module's JS object (wasm/bindings.cpp) and the field
// list that docs/api.md's table is checked against (resultFields()).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "axis_polynomials.h"
#include "evaluation.h"
#include "outcome.h"

namespace hobsharp {

struct ResultField {
  const char* path;      // dotted, as in the JS API: "setup.settingAngle"
  const char* unit;      // "" when the field has none
  const char* meaning;   // a phrase for the engineer
  const char* when = "";  // when the field is present ("" = always)
  const char* label = "";  // the figure's short name where the page, the CSV or the report shows it ("" = none)
};

// What a field holds. Matrices are row-major: rows root to tip, columns along the gash.
enum class FieldKind { Number, Count, Flag, Text, Texts, Numbers, Matrix, Matrices, Axes };
const char* fieldKindName(FieldKind kind);  // "number", "integer", ... "axes"

class ResultVisitor {
 public:
  virtual ~ResultVisitor() = default;
  // A visitor that lists the fields sees the optional ones too (with placeholder values).
  virtual bool listsEveryField() const { return false; }

  virtual void number(const ResultField& f, double value) = 0;
  virtual void count(const ResultField& f, int value) = 0;
  virtual void flag(const ResultField& f, bool value) = 0;
  virtual void text(const ResultField& f, const std::string& value) = 0;
  virtual void texts(const ResultField& f, const std::vector<std::string>& values) = 0;
  virtual void numbers(const ResultField& f, const double* values, std::size_t n) = 0;
  virtual void matrix(const ResultField& f, const double* rowMajor, int rows, int cols) = 0;
  // `count` matrices of rows x cols, one after the other, each row-major.
  virtual void matrices(const ResultField& f, const double* data, int count, int rows, int cols) = 0;
  // An object X, Y, Z, A, B of coefficient lists a0..an.
  virtual void axes(const ResultField& f, const AxisPolynomials& axes) = 0;
};

// Units as the result states them.
const char* axisUnit(Axis axis);       // "mm" (X, Y, Z) or "rad" (A, B)
const char* motionUnit(GashKind gash);  // "rad" (phi_1, helical gash) or "mm" (s, straight gash)

// Hands every field of `e` to the visitor, in the order of the JS API.
void visitResult(const Evaluation& e, ResultVisitor& visitor);

struct FieldDescription {
  std::string path, kind, unit, meaning, when, label;
};
// Every field the result can hold, optional ones included, in the walk's order.
std::vector<FieldDescription> resultFields();

// The path of the first number of the result that is not finite ("topography.normal[2][3]"), or "".
std::string firstNonFinite(const Evaluation& e);

// The case file's text in, the evaluation out: parseCase, resolveJob, evaluate, then a check that
// every number of the result is finite (an Internal error naming the result's field if one is not).
Outcome<Evaluation> evaluateCase(const std::string& caseText);

// The result as JSON, in the JS API's names and shapes; indent < 0 writes one line. Numbers are
// written in the shortest form that reads back to the same double.
std::string resultJson(const Evaluation& e, int indent = -1);

}  // namespace hobsharp
