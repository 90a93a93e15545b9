#include "case_json.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "number_text.h"
#include "grid_words.h"
#include "probe_points.h"
#include "units.h"

namespace hobsharp {
namespace {

using Json = nlohmann::json;

const char* typeName(const Json& j) {
  if (j.is_null()) return "null";
  if (j.is_boolean()) return "a boolean";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "a list";
  return "an object";
}

// A user's string as a message shows it: cut after 40 bytes (at a character boundary), with
// control characters, quotes and backslashes escaped as JSON writes them.
std::string escapedCut(const std::string& s) {
  constexpr std::size_t kShown = 40;
  std::size_t end = std::min(s.size(), kShown);
  while (end > 0 && end < s.size() && (static_cast<unsigned char>(s[end]) & 0xC0) == 0x80) --end;  // UTF-8
  std::string out;
  for (std::size_t i = 0; i < end; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      const char* hex = "0123456789abcdef";
      out += std::string("\\u00") + hex[c >> 4] + hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return end < s.size() ? out + "..." : out;
}
std::string quoted(const std::string& s) { return "\"" + escapedCut(s) + "\""; }

// A user's object key in a field name: as written, or quoted when empty.
std::string shownKey(const std::string& key) { return key.empty() ? "\"\"" : escapedCut(key); }

// Walks the text once before it is read, building nothing, and keeps the path of the value it
// is in. It refuses text that is not JSON, and lists and objects nested deeper than
// kMaxCaseNesting, naming the field where that happens (docs/case-format.md). So no later step
// (the document's own recursion, a message) ever meets deep input.
class Shape : public nlohmann::json_sax<Json> {
 public:
  const std::optional<Error>& error() const { return error_; }

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool start_array(std::size_t) override { return open(true); }
  bool key(string_t& k) override {
    frames_.back().key = shownKey(k);
    frames_.back().keyed = true;
    return true;
  }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    // nlohmann's message: "[json.exception...] parse error at ...: syntax error while parsing
    // value - <reason>; last read: '<the text>'". Keep the reason, never the text.
    std::string reason = e.what();
    const std::size_t dash = reason.find(" - ");
    reason = dash == std::string::npos ? "syntax error" : reason.substr(dash + 3);
    reason = reason.substr(0, reason.find("; last read: "));
    // nlohmann's out_of_range 406, "number overflow parsing '1e309'": not a syntax error.
    if (e.id == 406) reason = "a number too large: beyond ±1.8e308";
    error_ = refuse(path(false), "the case is not valid JSON here, at character " + std::to_string(position) +
                                     " (" + reason.substr(0, 200) + ").");
    return false;
  }

 private:
  struct Frame {
    bool list = false;
    std::size_t index = 0;  // of the current element (a list)
    std::string key;        // of the current member (an object), as shown
    bool keyed = false;     // an object: inside a member's value
  };

  bool value() {
    if (!frames_.empty()) {
      Frame& f = frames_.back();
      if (f.list) ++f.index;
      f.keyed = false;
    }
    return true;
  }
  bool open(bool list) {
    if (frames_.size() >= static_cast<std::size_t>(kMaxCaseNesting)) {
      error_ = refuse(path(true), "lists and objects are nested more than " + std::to_string(kMaxCaseNesting) +
                                      " deep here; a case nests them at most 3 deep.");
      return false;
    }
    Frame f;
    f.list = list;
    frames_.push_back(f);
    return true;
  }
  bool close() {
    frames_.pop_back();
    return value();
  }

  // The path of the current value ("measured[2][3]"), or only down to its innermost named field
  // ("hob.gashLead" for anything inside it); "case" for the document itself.
  std::string path(bool named) const {
    std::string p, upToName;
    for (const Frame& f : frames_) {
      if (f.list) {
        p += "[" + std::to_string(f.index) + "]";
      } else if (f.keyed) {
        p += (p.empty() ? "" : ".") + f.key;
        upToName = p;
      } else {
        break;  // between members: the object itself
      }
    }
    const std::string& chosen = named ? upToName : p;
    return chosen.empty() ? "case" : chosen;
  }

  std::vector<Frame> frames_;
  std::optional<Error> error_;
};

// An object of the document with its path, for reading fields and naming them in messages.
class Node {
 public:
  Node(const Json& j, std::string path) : j_(j), path_(std::move(path)) {}

  std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const Json* find(const char* key) const {
    auto it = j_.find(key);
    return it == j_.end() ? nullptr : &*it;
  }

  Outcome<void> onlyKnown(std::initializer_list<const char*> known) const {
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      if (std::none_of(known.begin(), known.end(), [&](const char* k) { return it.key() == k; })) {
        std::string list;
        for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        return refuse(field(shownKey(it.key())), "unknown field (expected one of: " + list + ").");
      }
    }
    return success();
  }

  Outcome<Node> object(const char* key, bool required) const {
    const Json* v = find(key);
    if (!v) {
      if (required) return refuse(field(key), "is missing.");
      static const Json empty = Json::object();
      return Node(empty, field(key));
    }
    if (!v->is_object()) return refuse(field(key), std::string("must be an object; got ") + typeName(*v) + ".");
    return Node(*v, field(key));
  }

  // A required number, or an optional one (empty when absent).
  Outcome<double> number(const char* key) const {
    const Json* v = find(key);
    if (!v) return refuse(field(key), "is missing.");
    return toNumber(*v, field(key));
  }
  Outcome<std::optional<double>> optionalNumber(const char* key) const {
    const Json* v = find(key);
    if (!v) return std::optional<double>();
    auto d = toNumber(*v, field(key));
    if (!d) return d.error();
    return std::optional<double>(*d);
  }
  Outcome<std::optional<int>> optionalInteger(const char* key) const {
    auto d = optionalNumber(key);
    if (!d) return d.error();
    if (!*d) return std::optional<int>();
    if (**d != std::floor(**d) || std::abs(**d) > 1e9)
      return refuse(field(key), "must be a whole number.");
    return std::optional<int>(static_cast<int>(**d));
  }
  Outcome<std::optional<std::string>> choice(const char* key, std::initializer_list<const char*> options) const {
    const Json* v = find(key);
    if (!v) return std::optional<std::string>();
    std::string list;
    for (const char* o : options) list += (list.empty() ? "\"" : ", \"") + std::string(o) + "\"";
    if (!v->is_string()) return refuse(field(key), "must be one of " + list + "; got " + typeName(*v) + ".");
    const std::string s = v->get<std::string>();
    if (std::none_of(options.begin(), options.end(), [&](const char* o) { return s == o; }))
      return refuse(field(key), "must be one of " + list + "; got " + quoted(s) + ".");
    return std::optional<std::string>(s);
  }

  static Outcome<double> toNumber(const Json& v, const std::string& field) {
    if (!v.is_number()) return refuse(field, std::string("must be a number; got ") + typeName(v) + ".");
    const double d = v.get<double>();
    if (!std::isfinite(d)) return refuse(field, "must be a finite number.");
    return d;
  }

 private:
  const Json& j_;
  std::string path_;
};

// Returns the Error of an Outcome that failed.
#define HOBSHARP_TRY(expr) \
  if (auto o_ = (expr); !o_) return o_.error()
// Assigns the value of an Outcome to `target`, or returns its Error.
#define HOBSHARP_ASSIGN(target, expr) \
  do {                                \
    auto o_ = (expr);                 \
    if (!o_) return o_.error();       \
    target = std::move(o_).value();   \
  } while (false)

// The hob's relief for the gear effect (docs/case-format.md): `hob.gashes`, and `hob.relief` or
// `hob.sideReliefAngle`; its value rules are checkRelief()'s (hob_relief.h), checked as it is read.
Outcome<HobReliefInput> readRelief(const Node& h, const HobInput& hob) {
  HobReliefInput out;
  HOBSHARP_ASSIGN(out.gashes, h.optionalInteger("gashes"));
  HOBSHARP_ASSIGN(out.relief, h.optionalNumber("relief"));
  HOBSHARP_ASSIGN(out.sideReliefAngle, h.optionalNumber("sideReliefAngle"));
  HOBSHARP_TRY(checkRelief(out, hob.outerDiameter, hob.pitchDiameter, hob.normalPressureAngle));
  return out;
}

Outcome<HobInput> readHob(const Node& h) {
  HOBSHARP_TRY(h.onlyKnown({"normalModule", "normalPressureAngle", "outerDiameter", "pitchDiameter", "gashDepth",
                            "length", "rakeOffset", "gash", "hand", "gashLead", "gashHelixAngle", "gashes", "relief",
                            "sideReliefAngle"}));
  HobInput hob;
  HOBSHARP_ASSIGN(hob.normalModule, h.number("normalModule"));
  HOBSHARP_ASSIGN(hob.normalPressureAngle, h.number("normalPressureAngle"));
  HOBSHARP_ASSIGN(hob.outerDiameter, h.number("outerDiameter"));
  HOBSHARP_ASSIGN(hob.pitchDiameter, h.number("pitchDiameter"));
  HOBSHARP_ASSIGN(hob.gashDepth, h.number("gashDepth"));
  HOBSHARP_ASSIGN(hob.length, h.number("length"));
  std::optional<double> rake;
  HOBSHARP_ASSIGN(rake, h.optionalNumber("rakeOffset"));
  hob.rakeOffset = rake.value_or(0.0);
  std::optional<std::string> gash, hand;
  HOBSHARP_ASSIGN(gash, h.choice("gash", {"helical", "straight"}));
  HOBSHARP_ASSIGN(hand, h.choice("hand", {"right", "left"}));
  hob.gash = gash.value_or("helical") == "straight" ? GashKind::Straight : GashKind::Helical;
  hob.hand = hand.value_or("right") == "left" ? Hand::Left : Hand::Right;
  HOBSHARP_ASSIGN(hob.gashLead, h.optionalNumber("gashLead"));
  HOBSHARP_ASSIGN(hob.gashHelixAngle, h.optionalNumber("gashHelixAngle"));
  HOBSHARP_ASSIGN(hob.relief, readRelief(h, hob));
  return hob;
}

Outcome<AxisPolynomials> readAxes(const Node& a) {
  HOBSHARP_TRY(a.onlyKnown({"X", "Y", "Z", "A", "B"}));
  AxisPolynomials axes;
  for (Axis axis : kAxes) {
    const char* name = axisName(axis);
    const Json* v = a.find(name);
    if (!v) return refuse(a.field(name), "is missing.");
    if (!v->is_array()) return refuse(a.field(name), std::string("must be a list of coefficients; got ") + typeName(*v) + ".");
    Polynomial p;
    for (std::size_t k = 0; k < v->size(); ++k) {
      double c = 0;
      HOBSHARP_ASSIGN(c, Node::toNumber((*v)[k], a.field(name) + "[" + std::to_string(k) + "]"));
      p.a.push_back(c);
    }
    if (p.a.empty()) return refuse(a.field(name), "must hold at least the coefficient a0.");
    axes[axis] = p;
  }
  return axes;
}

// A grid of measured deviations; `name` is its field ("measured", "passes[1].measured"). A refusal's
// field is the path; its message names the grid, row and value in words, counted from 1 (grid_words.h).
Outcome<Eigen::MatrixXd> readMeasured(const Json& m, const std::string& name = "measured") {
  const auto refuseGrid = [](const std::string& field, const std::string& words, const std::string& reason) {
    return Error{field, words + ": " + reason, ErrorCode::InvalidInput};
  };
  if (!m.is_array()) return refuseGrid(name, gridWords(name), std::string("must be a list of rows; got ") + typeName(m) + ".");
  if (m.empty()) return refuseGrid(name, gridWords(name), "the list is empty; it needs one row per radial grid line.");
  const std::size_t cols = m[0].is_array() ? m[0].size() : 0;
  // Every row's shape before the matrix is allocated: its size then follows from the text's.
  for (std::size_t i = 0; i < m.size(); ++i) {
    const std::string row = name + "[" + std::to_string(i) + "]";
    if (!m[i].is_array())
      return refuseGrid(row, gridRowWords(name, i), std::string("must be a list of values; got ") + typeName(m[i]) + ".");
    if (m[i].size() != cols)
      return refuseGrid(row, gridRowWords(name, i),
                        "has " + std::to_string(m[i].size()) + " values; the first row has " + std::to_string(cols) + ".");
  }
  Eigen::MatrixXd out(static_cast<Eigen::Index>(m.size()), static_cast<Eigen::Index>(cols));
  for (std::size_t i = 0; i < m.size(); ++i) {
    for (std::size_t j = 0; j < cols; ++j) {
      auto v = Node::toNumber(m[i][j], "");
      if (!v) return refuseGrid(name + "[" + std::to_string(i) + "][" + std::to_string(j) + "]", gridValueWords(name, i, j),
                                v.error().message.substr(2));
      out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = *v;
    }
  }
  return out;
}

Outcome<CorrectionInput> readCorrection(const Node& c);
Outcome<std::vector<MeasuredPoint>> readMeasuredPoints(const Json& p, const std::string& field);

// The pass history: a list of {"axes": {X..B}, "measured": rows, "correction": {...}}, oldest
// first, a pass's measurement a grid (`measured`) or the measuring machine's points
// (`measuredPoints`); a pass's correction is optional (the options its correction was computed
// with). Shapes against the grid and the degree are resolveJob()'s to check, as for `measured` and `axes`.
Outcome<std::vector<PassInput>> readPasses(const Json& p) {
  if (!p.is_array())
    return refuse("passes", std::string("must be a list of passes such as [{\"axes\": {...}, \"measured\": [[...]]}]; got ") +
                                typeName(p) + ".");
  std::vector<PassInput> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::string name = "passes[" + std::to_string(i) + "]";
    if (!p[i].is_object()) return refuse(name, std::string("must be an object with axes and measured; got ") + typeName(p[i]) + ".");
    const Node pass(p[i], name);
    HOBSHARP_TRY(pass.onlyKnown({"axes", "measured", "measuredPoints", "correction"}));
    PassInput in;
    auto axes = pass.object("axes", true);
    if (!axes) return axes.error();
    HOBSHARP_ASSIGN(in.axes, readAxes(*axes));
    const Json* m = pass.find("measured");
    const Json* points = pass.find("measuredPoints");
    if (m && points)
      return refuse(pass.field("measuredPoints"), "give the pass's measurement as `measured` (a grid) or as `measuredPoints`, not both.");
    if (!m && !points)
      return refuse(pass.field("measured"), "is missing: a pass needs the face measured after it, as `measured` (a grid) or `measuredPoints`.");
    if (m) HOBSHARP_ASSIGN(in.measured, readMeasured(*m, pass.field("measured")));
    if (points) HOBSHARP_ASSIGN(in.measuredPoints, readMeasuredPoints(*points, pass.field("measuredPoints")));
    if (pass.find("correction")) {
      auto c = pass.object("correction", true);
      if (!c) return c.error();
      HOBSHARP_ASSIGN(in.correction, readCorrection(*c));
    }
    out.push_back(std::move(in));
  }
  return out;
}

// A list of numbers, each finite; `name` is its field.
Outcome<std::vector<double>> readNumbers(const Json& v, const std::string& name) {
  if (!v.is_array()) return refuse(name, std::string("must be a list of numbers; got ") + typeName(v) + ".");
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    double d = 0;
    HOBSHARP_ASSIGN(d, Node::toNumber(v[i], name + "[" + std::to_string(i) + "]"));
    out.push_back(d);
  }
  return out;
}

// {"R": [...], "<values>": [...]} of equal lengths, or nothing when the wheel has no `key`.
Outcome<std::optional<WheelPointsInput>> readWheelPoints(const Node& wheel, const char* key, const char* values) {
  if (!wheel.find(key)) return std::optional<WheelPointsInput>();
  auto o = wheel.object(key, true);
  if (!o) return o.error();
  HOBSHARP_TRY(o->onlyKnown({"R", values}));
  WheelPointsInput in;
  for (auto [name, target] : {std::pair{"R", &in.R}, std::pair{values, &in.values}}) {
    const Json* v = o->find(name);
    if (!v) return refuse(o->field(name), "is missing.");
    HOBSHARP_ASSIGN(*target, readNumbers(*v, o->field(name)));
  }
  if (in.R.size() > static_cast<size_t>(kMaxWheelPoints))
    return refuse(o->field("R"), "has " + std::to_string(in.R.size()) + " points; at most " +
                                     std::to_string(kMaxWheelPoints) + " are taken (a dressed wheel's profile has a few hundred).");
  if (in.values.size() != in.R.size())
    return refuse(o->field(values), "needs one value per radius in " + o->field("R") + " (" +
                                        std::to_string(in.R.size()) + "); got " + std::to_string(in.values.size()) + ".");
  return std::optional<WheelPointsInput>(std::move(in));
}

// wheel.profileOffset {R mm, offset µm} and wheel.measuredProfile {R mm, Z mm} (docs/case-format.md
// §The wheel's profile); resolveJob checks them against the wheel's contact range.
Outcome<void> readWheelProfile(const Node& wheel, CaseInput& in) {
  HOBSHARP_ASSIGN(in.wheelProfileOffset, readWheelPoints(wheel, "profileOffset", "offset"));
  HOBSHARP_ASSIGN(in.wheelMeasuredProfile, readWheelPoints(wheel, "measuredProfile", "Z"));
  if (in.wheelProfileOffset && in.wheelMeasuredProfile)
    return refuse(wheel.field("measuredProfile"), "give either wheel.profileOffset or wheel.measuredProfile, not both.");
  return success();
}

Outcome<CorrectionInput> readCorrection(const Node& c) {
  HOBSHARP_TRY(c.onlyKnown({"method", "probeNoise", "resolution", "truncation", "amplification", "lockedAxes",
                            "locked", "wheel"}));
  CorrectionInput out;
  HOBSHARP_ASSIGN(out.method, c.choice("method", {"nonlinear", "linear"}));
  HOBSHARP_ASSIGN(out.probeNoise, c.optionalNumber("probeNoise"));
  auto resolution = c.object("resolution", false);
  if (!resolution) return resolution.error();
  HOBSHARP_TRY(resolution->onlyKnown({"X", "Y", "Z", "A", "B"}));
  for (Axis a : kAxes) HOBSHARP_ASSIGN(out.resolution[static_cast<int>(a)], resolution->optionalNumber(axisName(a)));
  HOBSHARP_ASSIGN(out.truncation, c.optionalNumber("truncation"));
  HOBSHARP_ASSIGN(out.amplification, c.optionalNumber("amplification"));
  auto axisOf = [](const std::string& s, Axis* a) {
    for (Axis x : kAxes)
      if (s == axisName(x)) return *a = x, true;
    return false;
  };
  if (const Json* v = c.find("lockedAxes")) {
    if (!v->is_array()) return refuse(c.field("lockedAxes"), "must be a list of axis names such as [\"X\", \"A\"].");
    for (const Json& s : *v) {
      Axis a;
      if (!s.is_string() || !axisOf(s.get<std::string>(), &a))
        return refuse(c.field("lockedAxes"), "holds something that is not one of \"X\", \"Y\", \"Z\", \"A\", \"B\".");
      out.lockedAxes.push_back(a);
    }
  }
  if (const Json* v = c.find("locked")) {
    if (!v->is_array()) return refuse(c.field("locked"), "must be a list of coefficients such as [\"X a0\", \"B a2\"].");
    for (const Json& s : *v) {
      const std::string text = s.is_string() ? s.get<std::string>() : "";
      Axis a;
      if (text.size() != 4 || text.substr(1, 2) != " a" || !axisOf(text.substr(0, 1), &a) || text[3] < '0' ||
          text[3] > '9')
        return refuse(c.field("locked"), "holds " + quoted(text) + "; write a coefficient as \"X a0\" .. \"B a6\".");
      out.locked.push_back(Coefficient{a, text[3] - '0'});
    }
  }
  if (const Json* v = c.find("wheel")) {  // the wheel-profile correction (docs/method.md)
    if (!v->is_boolean()) return refuse(c.field("wheel"), std::string("must be true or false; got ") + typeName(*v) + ".");
    out.wheel = v->get<bool>();
  }
  return out;
}

// A check's `confidence` (docs/inspection.md): per class, per band "printed" or "series" as the
// default table marks them, or "entered"; cells it leaves out are the engineer's ("entered").
Outcome<void> readConfidence(const Node& check, std::array<std::vector<Confidence>, kClassCount>& out) {
  auto c = check.object("confidence", false);
  if (!c) return c.error();
  const Json* given = check.find("confidence");
  if (!given) return success();
  HOBSHARP_TRY(c->onlyKnown({"AA", "A", "B", "C", "D"}));
  for (ToleranceClass k : kClasses) {
    const Json* row = c->find(className(k));
    if (!row) continue;
    const std::string field = c->field(className(k));
    if (!row->is_array()) return refuse(field, std::string("must be a list of \"printed\", \"series\" or \"entered\", one per module band; got ") + typeName(*row) + ".");
    for (std::size_t b = 0; b < row->size(); ++b) {
      const Json& w = (*row)[b];
      const std::optional<Confidence> confidence = confidenceNamed(w.is_string() ? w.get<std::string>() : "");
      if (!confidence) return refuse(field + "[" + std::to_string(b) + "]", "must be \"printed\", \"series\" or \"entered\".");
      out[static_cast<int>(k)].push_back(*confidence);
    }
  }
  return success();
}

// The tolerance table (`inspection.tolerances`), in the shape of data/din3968-cutting-face.json:
// {"moduleBands": [edges], "checks": {"<check>": {"source": "...", "AA": [per band, a number or
// null], ..}}}, with the data file's "format", "title" and "missing" allowed as notes. The values'
// rules are checkToleranceTable()'s (resolveJob).
Outcome<ToleranceTable> readToleranceTable(const Node& t) {
  HOBSHARP_TRY(t.onlyKnown({"format", "title", "moduleBands", "checks", "missing"}));
  if (const Json* f = t.find("format"))
    if (!f->is_string() || f->get<std::string>() != kToleranceFormat)
      return refuse(t.field("format"), std::string("must be \"") + kToleranceFormat + "\" when given.");
  if (const Json* title = t.find("title"))
    if (!title->is_string()) return refuse(t.field("title"), std::string("must be a string; got ") + typeName(*title) + ".");
  auto missing = t.object("missing", false);
  if (!missing) return missing.error();
  if (const Json* m = t.find("missing"))
    for (auto it = m->begin(); it != m->end(); ++it)
      if (!it->is_string()) return refuse(missing->field(shownKey(it.key())), "must be a sentence (a string).");
  ToleranceTable table;
  const Json* edges = t.find("moduleBands");
  if (!edges) return refuse(t.field("moduleBands"), "is missing.");
  if (!edges->is_array()) return refuse(t.field("moduleBands"), std::string("must be a list of module edges in mm; got ") + typeName(*edges) + ".");
  for (std::size_t k = 0; k < edges->size(); ++k) {
    double m = 0;
    HOBSHARP_ASSIGN(m, Node::toNumber((*edges)[k], t.field("moduleBands") + "[" + std::to_string(k) + "]"));
    table.moduleEdges.push_back(m);
  }
  auto checks = t.object("checks", true);
  if (!checks) return checks.error();
  if (checks->find("cumulativeSpacing"))
    return refuse(checks->field("cumulativeSpacing"),
                  "is no longer graded: DIN 3968 item 9 (f_uN) is the pitch jump, the difference between two consecutive "
                  "single pitch deviations; give its tolerances as pitchJump.");
  HOBSHARP_TRY(checks->onlyKnown({"cuttingFaceForm", "radialAlignment", "gashLead", "adjacentSpacing", "pitchJump"}));
  for (Check check : kChecks) {
    if (!checks->find(checkName(check))) continue;
    auto c = checks->object(checkName(check), true);
    if (!c) return c.error();
    HOBSHARP_TRY(c->onlyKnown({"source", "seriesSource", "confidence", "AA", "A", "B", "C", "D"}));
    for (const char* note : {"source", "seriesSource"})
      if (const Json* source = c->find(note))
        if (!source->is_string()) return refuse(c->field(note), std::string("must be a string; got ") + typeName(*source) + ".");
    HOBSHARP_TRY(readConfidence(*c, table.confidence[static_cast<int>(check)]));
    for (ToleranceClass k : kClasses) {
      const Json* row = c->find(className(k));
      if (!row) continue;
      const std::string field = c->field(className(k));
      if (!row->is_array()) return refuse(field, std::string("must be a list of tolerances in µm, one per module band (null where there is none); got ") + typeName(*row) + ".");
      auto& cells = table.cells[static_cast<int>(check)][static_cast<int>(k)];
      for (std::size_t b = 0; b < row->size(); ++b) {
        if ((*row)[b].is_null()) {
          cells.emplace_back();
          continue;
        }
        double v = 0;
        HOBSHARP_ASSIGN(v, Node::toNumber((*row)[b], field + "[" + std::to_string(b) + "]"));
        cells.emplace_back(v);
      }
    }
  }
  return table;
}

// `measuredPoints`: a list of [r, x, deviation] (mm, mm, µm); `field` is its name ("measuredPoints",
// "passes[1].measuredPoints"). Where they lie is resolveJob()'s to check.
Outcome<std::vector<MeasuredPoint>> readMeasuredPoints(const Json& p, const std::string& field) {
  if (!p.is_array() || p.empty())
    return refusePoints(field, "must be a list of points [r, x, deviation] (mm, mm, µm), such as [[19, -70, 1.5], ...].");
  std::vector<MeasuredPoint> out;
  static const char* const kValue[3] = {"r", "x", "the deviation"};
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!p[k].is_array() || p[k].size() != 3)
      return refusePoint(field, k, std::string("must be a point [r, x, deviation] of three numbers; got ") +
                                       (p[k].is_array() ? std::to_string(p[k].size()) + " values" : typeName(p[k])) + ".");
    double v[3] = {0, 0, 0};
    for (std::size_t j = 0; j < 3; ++j) {
      auto n = Node::toNumber(p[k][j], "");
      if (!n) {  // named in words, the point counted from 1; the field stays the path
        Error e = refusePoint(field, k, std::string(kValue[j]) + " " + n.error().message.substr(2));
        e.field += "[" + std::to_string(j) + "]";
        return e;
      }
      v[j] = *n;
    }
    out.push_back(MeasuredPoint{v[0], v[1], v[2]});
  }
  return out;
}

// `inspection`: per-gash deviations and an edited tolerance table (docs/case-format.md).
Outcome<InspectionInput> readInspection(const Node& n) {
  HOBSHARP_TRY(n.onlyKnown({"gashDeviations", "gashTopographies", "tolerances", "uncertainty"}));
  InspectionInput out;
  if (const Json* u = n.find("uncertainty")) HOBSHARP_ASSIGN(out.uncertainty, Node::toNumber(*u, n.field("uncertainty")));
  if (const Json* d = n.find("gashDeviations")) {
    if (!d->is_array() || d->empty())
      return refuse(n.field("gashDeviations"), "must be a list of deviations in µm, one per gash, such as [0, 2.5, -1].");
    for (std::size_t k = 0; k < d->size(); ++k) {
      double v = 0;
      HOBSHARP_ASSIGN(v, Node::toNumber((*d)[k], n.field("gashDeviations") + "[" + std::to_string(k) + "]"));
      out.gashDeviations.push_back(v);
    }
  }
  if (const Json* g = n.find("gashTopographies")) {  // one grid per gash; its shape is the job's to check
    if (!g->is_array() || g->empty())
      return refuse(n.field("gashTopographies"), "must be a list of measured grids, one per gash, each as `measured`.");
    for (std::size_t k = 0; k < g->size(); ++k) {
      Eigen::MatrixXd m;
      HOBSHARP_ASSIGN(m, readMeasured((*g)[k], n.field("gashTopographies") + "[" + std::to_string(k) + "]"));
      out.gashTopographies.push_back(std::move(m));
    }
  }
  if (n.find("tolerances")) {
    auto t = n.object("tolerances", true);
    if (!t) return t.error();
    HOBSHARP_ASSIGN(out.tolerances, readToleranceTable(*t));
  }
  return out;
}

// One text of `job`: a string of at most `most` characters (UTF-8 code points), no control
// characters (line breaks and tabs only where `lines`). The message begins with the field, as
// every refusal does; the page puts its label in its place ("Job number must be at most ...").
Outcome<std::optional<std::string>> readJobText(const Node& n, const char* key, int most, bool lines) {
  const Json* v = n.find(key);
  if (!v) return std::optional<std::string>();
  const std::string what = "must be ";
  if (!v->is_string()) return refuse(n.field(key), what + "text; got " + typeName(*v) + ".");
  const std::string s = v->get<std::string>();
  int characters = 0;
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if ((u & 0xC0) != 0x80) ++characters;
    if ((u < 0x20 || u == 0x7f) && !(lines && (c == '\n' || c == '\r' || c == '\t')))
      return refuse(n.field(key), what + (lines ? "text without control characters (line breaks and tabs are kept)."
                                               : "one line of text, without line breaks or control characters."));
  }
  if (characters > most)
    return refuse(n.field(key), what + "at most " + std::to_string(most) + " characters; got " + std::to_string(characters) + ".");
  return std::optional<std::string>(s);
}

// `job`: the job's record (docs/case-format.md), each member optional.
Outcome<JobRecord> readJob(const Node& n) {
  HOBSHARP_TRY(n.onlyKnown({"number", "customer", "hobSerial", "operator", "notes"}));
  JobRecord out;
  HOBSHARP_ASSIGN(out.number, readJobText(n, "number", kMaxJobText, false));
  HOBSHARP_ASSIGN(out.customer, readJobText(n, "customer", kMaxJobCustomer, false));
  HOBSHARP_ASSIGN(out.hobSerial, readJobText(n, "hobSerial", kMaxJobText, false));
  HOBSHARP_ASSIGN(out.operatorName, readJobText(n, "operator", kMaxJobText, false));
  HOBSHARP_ASSIGN(out.notes, readJobText(n, "notes", kMaxJobNotes, true));
  return out;
}

}  // namespace

Outcome<CaseInput> parseCase(const std::string& text) {
  Shape shape;
  if (!Json::sax_parse(text, &shape)) {
    if (shape.error()) return *shape.error();
    return refuse("case", "is not valid JSON.");
  }
  const Json doc = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return refuse("case", "is not valid JSON.");  // the walk above found no fault
  if (!doc.is_object()) return refuse("case", std::string("must be a JSON object; got ") + typeName(doc) + ".");
  const Node root(doc, "");
  const Json* format = root.find("format");
  if (!format) return refuse("format", std::string("is missing; it must be \"") + kCaseFormat + "\".");
  if (!format->is_string() || format->get<std::string>() != kCaseFormat)
    return refuse("format", "unknown format " + (format->is_string() ? quoted(format->get<std::string>()) : typeName(*format)) +
                                "; this calculator reads \"" + kCaseFormat + "\".");
  HOBSHARP_TRY(root.onlyKnown({"format", "hob", "wheel", "setup", "machine", "degree", "grid", "axes", "measured",
                               "correction", "passes", "inspection", "measuredPoints", "job"}));
  CaseInput in;
  auto hob = root.object("hob", true);
  if (!hob) return hob.error();
  HOBSHARP_ASSIGN(in.hob, readHob(*hob));

  auto wheel = root.object("wheel", true);
  if (!wheel) return wheel.error();
  HOBSHARP_TRY(wheel->onlyKnown({"outerDiameter", "profileOffset", "measuredProfile"}));
  HOBSHARP_ASSIGN(in.wheelOuterDiameter, wheel->number("outerDiameter"));
  HOBSHARP_TRY(readWheelProfile(*wheel, in));

  auto setup = root.object("setup", true);
  if (!setup) return setup.error();
  HOBSHARP_TRY(setup->onlyKnown({"tilt", "settingAngle", "centerDistance"}));
  HOBSHARP_ASSIGN(in.tilt, setup->number("tilt"));
  HOBSHARP_ASSIGN(in.settingAngle, setup->optionalNumber("settingAngle"));
  HOBSHARP_ASSIGN(in.centerDistance, setup->optionalNumber("centerDistance"));

  auto machine = root.object("machine", true);
  if (!machine) return machine.error();
  HOBSHARP_TRY(machine->onlyKnown({"K1", "K2"}));
  HOBSHARP_ASSIGN(in.machine.K1, machine->number("K1"));
  HOBSHARP_ASSIGN(in.machine.K2, machine->number("K2"));

  std::optional<int> degree;
  HOBSHARP_ASSIGN(degree, root.optionalInteger("degree"));
  in.degree = degree.value_or(kDefaultDegree);

  auto grid = root.object("grid", false);
  if (!grid) return grid.error();
  HOBSHARP_TRY(grid->onlyKnown({"radial", "axial", "rMin", "rMax", "xMin", "xMax"}));
  HOBSHARP_ASSIGN(in.grid.radial, grid->optionalInteger("radial"));
  HOBSHARP_ASSIGN(in.grid.axial, grid->optionalInteger("axial"));
  HOBSHARP_ASSIGN(in.grid.rMin, grid->optionalNumber("rMin"));
  HOBSHARP_ASSIGN(in.grid.rMax, grid->optionalNumber("rMax"));
  HOBSHARP_ASSIGN(in.grid.xMin, grid->optionalNumber("xMin"));
  HOBSHARP_ASSIGN(in.grid.xMax, grid->optionalNumber("xMax"));

  if (root.find("axes")) {
    auto axes = root.object("axes", true);
    if (!axes) return axes.error();
    HOBSHARP_ASSIGN(in.axes, readAxes(*axes));
  }
  if (const Json* m = root.find("measured")) {
    HOBSHARP_ASSIGN(in.measured, readMeasured(*m));
  }
  auto correction = root.object("correction", false);
  if (!correction) return correction.error();
  HOBSHARP_ASSIGN(in.correction, readCorrection(*correction));
  if (const Json* p = root.find("passes")) {
    HOBSHARP_ASSIGN(in.passes, readPasses(*p));
  }
  if (const Json* p = root.find("measuredPoints")) {
    HOBSHARP_ASSIGN(in.measuredPoints, readMeasuredPoints(*p, "measuredPoints"));
  }
  auto inspection = root.object("inspection", false);
  if (!inspection) return inspection.error();
  HOBSHARP_ASSIGN(in.inspection, readInspection(*inspection));
  auto job = root.object("job", false);
  if (!job) return job.error();
  HOBSHARP_ASSIGN(in.job, readJob(*job));
  return in;
}

}  // namespace hobsharp
