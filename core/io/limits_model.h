// The module's limits, described once: what the page and the command line need to know before they
// have a result (the case format, the grid and degree limits, the defaults, the axes and their units,
// the correction's options, the inspection's names and default table), each entry with its path,
// unit and words, visited in one order as the result model (result_model.h) visits the result. The
// module's limits() (wasm/bindings.cpp) is a visitor of this walk; limitFields() lists it.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hobsharp {

struct LimitField {
  const char* path;   // dotted, as in limits(): "correction.probeNoise"; a number is a list's index ("axes.0.name")
  const char* unit;   // "" when the entry has none
  const char* words;  // a phrase for the engineer
};

// A default with its range; min or max absent where the case has no such bound.
struct LimitRange {
  double defaultValue;
  std::optional<double> min, max;
};

// What an entry holds.
enum class LimitKind { Text, Texts, Count, Number, Range, Document };
const char* limitKindName(LimitKind kind);  // "string", "strings", "integer", ... "document"

class LimitsVisitor {
 public:
  virtual ~LimitsVisitor() = default;
  virtual void text(const LimitField& f, const std::string& value) = 0;
  virtual void texts(const LimitField& f, const std::vector<std::string>& values) = 0;
  virtual void count(const LimitField& f, int value) = 0;
  virtual void number(const LimitField& f, double value) = 0;
  // An object {default, min, max, unit}: min and max where given, unit where the entry has one.
  virtual void range(const LimitField& f, const LimitRange& r) = 0;
  // A JSON document in a format of its own (the default tolerance table, `hobsharp-tolerances/1`).
  virtual void document(const LimitField& f, const std::string& json) = 0;
};

// Hands every entry of the limits to the visitor, in the order of limits().
void visitLimits(LimitsVisitor& visitor);

struct LimitDescription {
  std::string path, kind, unit, words;
};
// Every entry of the limits, in the walk's order.
std::vector<LimitDescription> limitFields();

// The default tolerance table (data/din3968-cutting-face.json) as JSON text, in the shape
// `inspection.tolerances` takes: edited on the page and saved in a case, the reader takes it back.
std::string defaultToleranceJson();

}  // namespace hobsharp
