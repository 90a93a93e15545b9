#include "result_model.h"

#include <cmath>
#include <sstream>
#include <utility>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "case_json.h"
#include "default_tolerances.h"
#include "face_prediction.h"
#include "inspection_input.h"
#include "units.h"

namespace hobsharp {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

constexpr const char* kHelicalOnly = "helical gash only";
constexpr const char* kWithMeasured = "only with `measured`";
constexpr const char* kWithSimulatedRun = "only with `measured`, where the axes run grind a face the wheel envelops (not correction.linearisedAtNominal)";
constexpr const char* kCoefficientUnit = "mm or rad per (rad or mm)^k";
constexpr const char* kMotionUnit = "rad or mm";
// The per-axis fields of the correction, as {X, Y, Z, A, B} objects.
constexpr const char* kIdentified[] = {"correction.identifiedError.X", "correction.identifiedError.Y",
                                       "correction.identifiedError.Z", "correction.identifiedError.A",
                                       "correction.identifiedError.B"};
constexpr const char* kChange[] = {"correction.axisChange.X", "correction.axisChange.Y", "correction.axisChange.Z",
                                   "correction.axisChange.A", "correction.axisChange.B"};
constexpr const char* kChangeOverFace[] = {"correction.axisChangeOverFace.X", "correction.axisChangeOverFace.Y",
                                           "correction.axisChangeOverFace.Z", "correction.axisChangeOverFace.A",
                                           "correction.axisChangeOverFace.B"};
constexpr const char* kUncertainty[] = {"correction.uncertainty.X", "correction.uncertainty.Y",
                                        "correction.uncertainty.Z", "correction.uncertainty.A",
                                        "correction.uncertainty.B"};
constexpr const char* kFacePerError[] = {
    "correction.precision.facePerError.X", "correction.precision.facePerError.Y", "correction.precision.facePerError.Z",
    "correction.precision.facePerError.A", "correction.precision.facePerError.B"};
constexpr const char* kChangePerNoise[] = {
    "correction.precision.changePerNoise.X", "correction.precision.changePerNoise.Y",
    "correction.precision.changePerNoise.Z", "correction.precision.changePerNoise.A",
    "correction.precision.changePerNoise.B"};

void matrix(ResultVisitor& v, const ResultField& f, const Eigen::MatrixXd& m) {
  const RowMajor r = m;
  v.matrix(f, r.data(), static_cast<int>(r.rows()), static_cast<int>(r.cols()));
}
void numbers(ResultVisitor& v, const ResultField& f, const std::vector<double>& x) {
  v.numbers(f, x.data(), x.size());
}
template <class Vector>
void eigenNumbers(ResultVisitor& v, const ResultField& f, const Vector& x) {
  v.numbers(f, x.data(), static_cast<std::size_t>(x.size()));
}
std::vector<std::string> names(const std::vector<Coefficient>& coefficients) {
  std::vector<std::string> out;
  for (const Coefficient& c : coefficients) out.push_back(c.name());
  return out;
}

// Finds the first number of the result that is not finite; its path names the cell.
class FiniteCheck final : public ResultVisitor {
 public:
  std::string path;
  double value = 0;

  void number(const ResultField& f, double x) override { note(x, f.path); }
  void count(const ResultField&, int) override {}
  void flag(const ResultField&, bool) override {}
  void text(const ResultField&, const std::string&) override {}
  void texts(const ResultField&, const std::vector<std::string>&) override {}
  void numbers(const ResultField& f, const double* x, std::size_t n) override {
    for (std::size_t i = 0; i < n && path.empty(); ++i) note(x[i], f.path, {i});
  }
  void matrix(const ResultField& f, const double* x, int rows, int cols) override {
    for (int i = 0; i < rows * cols && path.empty(); ++i) note(x[i], f.path, {std::size_t(i / cols), std::size_t(i % cols)});
  }
  void matrices(const ResultField& f, const double* x, int count, int rows, int cols) override {
    const int cells = rows * cols;
    for (int i = 0; i < count * cells && path.empty(); ++i)
      note(x[i], f.path, {std::size_t(i / cells), std::size_t(i % cells / cols), std::size_t(i % cols)});
  }
  void axes(const ResultField& f, const AxisPolynomials& a) override {
    for (Axis x : kAxes)
      for (std::size_t k = 0; k < a[x].a.size() && path.empty(); ++k)
        note(a[x].a[k], std::string(f.path) + "." + axisName(x), {k});
  }

 private:
  void note(double x, const std::string& where, std::initializer_list<std::size_t> index = {}) {
    if (std::isfinite(x) || !path.empty()) return;
    path = where;
    for (std::size_t i : index) path += "[" + std::to_string(i) + "]";
    value = x;
  }
};

// The JSON text: objects in the walk's order, matrices as lists of rows.
class JsonWriter final : public ResultVisitor {
 public:
  using Json = nlohmann::ordered_json;
  Json root = Json::object();

  void number(const ResultField& f, double x) override { at(f) = x; }
  void count(const ResultField& f, int x) override { at(f) = x; }
  void flag(const ResultField& f, bool x) override { at(f) = x; }
  void text(const ResultField& f, const std::string& x) override { at(f) = x; }
  void texts(const ResultField& f, const std::vector<std::string>& x) override { at(f) = x; }
  void numbers(const ResultField& f, const double* x, std::size_t n) override { at(f) = list(x, n); }
  void matrix(const ResultField& f, const double* x, int rows, int cols) override { at(f) = grid(x, rows, cols); }
  void matrices(const ResultField& f, const double* x, int count, int rows, int cols) override {
    Json all = Json::array();
    for (int k = 0; k < count; ++k) all.push_back(grid(x + std::size_t(k) * rows * cols, rows, cols));
    at(f) = std::move(all);
  }
  void axes(const ResultField& f, const AxisPolynomials& a) override {
    Json o = Json::object();
    for (Axis x : kAxes) o[axisName(x)] = a[x].a;
    at(f) = std::move(o);
  }

 private:
  Json& at(const ResultField& f) {
    Json* node = &root;
    const std::string path = f.path;
    for (std::size_t start = 0;;) {
      const std::size_t dot = path.find('.', start);
      node = &(*node)[path.substr(start, dot - start)];
      if (dot == std::string::npos) return *node;
      start = dot + 1;
    }
  }
  static Json list(const double* x, std::size_t n) { return Json(std::vector<double>(x, x + n)); }
  static Json grid(const double* x, int rows, int cols) {
    Json g = Json::array();
    for (int i = 0; i < rows; ++i) g.push_back(list(x + std::size_t(i) * cols, std::size_t(cols)));
    return g;
  }
};

// Records the fields, not their values.
class FieldList final : public ResultVisitor {
 public:
  std::vector<FieldDescription> fields;

  bool listsEveryField() const override { return true; }
  void number(const ResultField& f, double) override { add(f, FieldKind::Number); }
  void count(const ResultField& f, int) override { add(f, FieldKind::Count); }
  void flag(const ResultField& f, bool) override { add(f, FieldKind::Flag); }
  void text(const ResultField& f, const std::string&) override { add(f, FieldKind::Text); }
  void texts(const ResultField& f, const std::vector<std::string>&) override { add(f, FieldKind::Texts); }
  void numbers(const ResultField& f, const double*, std::size_t) override { add(f, FieldKind::Numbers); }
  void matrix(const ResultField& f, const double*, int, int) override { add(f, FieldKind::Matrix); }
  void matrices(const ResultField& f, const double*, int, int, int) override { add(f, FieldKind::Matrices); }
  void axes(const ResultField& f, const AxisPolynomials&) override { add(f, FieldKind::Axes); }

 private:
  void add(const ResultField& f, FieldKind kind) {
    fields.push_back({f.path, fieldKindName(kind), f.unit, f.meaning, f.when, f.label});
  }
};

// As JS names them, which is how the engineer sees them in the page's messages.
const char* nonFiniteName(double x) { return std::isnan(x) ? "NaN" : x > 0 ? "Infinity" : "-Infinity"; }

constexpr const char* kWithGashes = "only with `inspection.gashDeviations` or `inspection.gashTopographies`";
constexpr const char* kWithEitherCorrection = "only with `measured`, `inspection.gashDeviations` or `inspection.gashTopographies`";
constexpr const char* kWithGashTopographies = "only with `inspection.gashTopographies`";

// The units of a check's value.
const char* checkUnit(Check c) { return c == Check::GashLead ? "µm per 100 mm" : "µm"; }

// What a check applies to: every face, a helical gash, or per-gash deviations.
const char* checkWhen(Check c) {
  if (c == Check::GashLead) return kHelicalOnly;
  if (c == Check::AdjacentSpacing || c == Check::PitchJump) return kWithGashes;
  return "";
}

// The class verdict of an inspection: its class, the check that limits it, and (measured, not
// predicted) the class the measurement proves with its uncertainty taken off (ISO 14253-1).
// `measured`: the face inspected was measured; on a simulated one (the axes run, nothing measured)
// no conformity is decided and no class proven, though measured gash deviations keep theirs.
constexpr const char* kNotDecided = "not decided";
void verdict(ResultVisitor& v, const Inspection& in, const std::string& prefix, const char* when, bool proven,
             bool measured = true) {
  const std::string klass = prefix + "class", limiting = prefix + "limitingCheck";
  v.text({klass.c_str(), "", "\"AA\" .. \"D\", \"outside D\" (\"outside B\" where the table stops at B), or \"not graded\" (no check has a tolerance for the module): the worst graded check's class, without the measurement's uncertainty", when},
         classText(in));
  v.text({limiting.c_str(), "", "the check that sets the class (\"\" when not graded)", when},
         in.limiting ? checkName(*in.limiting) : "");
  if (!proven) return;
  // On a simulated face only the measured checks (the gashes' spacing) decide, and only against:
  // one beyond the table's loosest class plus U proves that the hob does not conform.
  bool measuredFails = false, measuredProvesNone = false;
  for (const CheckResult& c : in.checks) {
    if (c.check != Check::AdjacentSpacing && c.check != Check::PitchJump) continue;
    measuredFails = measuredFails || c.conformity == Conformity::DoesNotConform;
    measuredProvesNone = measuredProvesNone || (c.grade != Grade::NotGraded && c.proven == Grade::OutsideD);
  }
  v.text({"inspection.provenClass", "", "the class the measurement proves (ISO 14253-1): every graded check within its tolerance less inspection.uncertainty; \"none\" when no class is proven, \"not graded\" when nothing is graded, \"not decided\" when the face inspected is simulated (nothing measured proves a class; \"none\" still where a measured gash spacing proves none)"},
         in.grade == Grade::NotGraded ? std::string("not graded")
         : measured                   ? provenText(in.proven)
         : measuredProvesNone         ? provenText(Grade::OutsideD)
                                      : std::string(kNotDecided));
  v.text({"inspection.conformity", "", "of every graded check to inspection.class (ISO 14253-1): \"conforms\" (within the tolerance less U), \"does not conform\" (beyond it plus U), \"undecided\" (within U of it), \"not graded\", \"not decided\" when the face inspected is simulated (\"does not conform\" still where a measured gash spacing does not)"},
         in.grade == Grade::NotGraded || measured ? conformityName(in.conformity)
         : measuredFails                          ? conformityName(Conformity::DoesNotConform)
                                                  : kNotDecided);
  std::string warning;
  for (Check c : in.uncertaintyAboveTenth) warning += (warning.empty() ? "" : ", ") + std::string(checkName(c));
  v.text({"inspection.uncertaintyWarning", "", "the graded checks whose uncertainty U exceeds a tenth of the tolerance they are graded by (\"\" when none): their class rests on a measurement too coarse for it"},
         warning);
  v.text({"inspection.faceNotGraded", "", "why the face's checks (form, radial alignment, gash lead) have readings but no grade, before and after the correction (\"\" when they are graded): measured points the face the identified error grinds on the grid does not explain to twice the probe noise"},
         in.faceNotGraded);
}

// A correction at measuredPoints off the grid (docs/measured-points.md): per point [r, x, µm],
// and the measurement as the identified error explains it, on the grid.
void visitPointCorrection(const Correction& c, ResultVisitor& v) {
  constexpr const char* kWithPoints = "only with `measuredPoints` off the grid's positions";
  const int n = static_cast<int>(c.probes.size());
  Eigen::MatrixXd measured(n, 3), residual(n, 3);
  for (int k = 0; k < n; ++k) {
    measured.row(k) << c.probes[k].r, c.probes[k].x, c.before.normal(k, 0);
    residual.row(k) << c.probes[k].r, c.probes[k].x, c.after.normal(k, 0);
  }
  matrix(v, {"correction.pointMeasured", "mm, mm, µm", "per measured point [r, x, deviation], in the case's order", kWithPoints}, measured);
  matrix(v, {"correction.pointResidual", "mm, mm, µm", "per measured point [r, x, deviation after the pass on the identified machine]: re-simulated at the point with correction.axes and the identified error, plus the part no axis makes, noise and all (what the pass leaves is bounded by correction.predictedRmsHigh)", kWithPoints},
         residual);
  matrix(v, {"correction.measuredOnGrid", "µm", "on the grid: the face the identified error grinds with the axes run, re-simulated (the measurement as the axes explain it; what no axis makes is known only at the points)", kWithPoints},
         c.explainedOnGrid.normal);
}

// The rake-face inspection (docs/inspection.md), then the one predicted after the correction.
void visitInspection(const Evaluation& e, ResultVisitor& v, bool every) {
  const Inspection& in = e.inspection;
  const bool helical = e.job.setup.face.helical();
  const bool gashes = e.indexCorrection.has_value();
  const ToleranceTable& table = e.job.inspection.table();
  v.text({"inspection.source", "", "the face inspected: \"gashTopographies\" (the worst of the case's per-gash grids), \"measured\" (the case's grid), \"measuredPoints\" (the case's points) or \"simulated\" (the axes run)"},
         e.gashFaces ? "gashTopographies" : sourceName(inspectedFace(e).source));
  std::string band = "outside the table's module bands";
  if (in.band) {
    std::ostringstream b;
    b << "over " << table.moduleEdges[*in.band] << " to " << table.moduleEdges[*in.band + 1] << " mm";
    band = b.str();
  }
  v.text({"inspection.moduleBand", "", "the normal-module band of the tolerance table the checks are graded in"}, band);
  v.number({"inspection.moduleBandIndex", "", "that band's place in the tolerance table: band b holds the normal modules over moduleBands[b] up to and including moduleBands[b + 1]; -1 outside the table"},
           in.band ? *in.band : -1);
  v.number({"inspection.uncertainty", "µm", "the measurement's expanded uncertainty U95 of a reading (the case's inspection.uncertainty, 2 µm when not given)"},
           in.uncertainty.deviation);
  v.number({"inspection.cuttingFaceForm", "µm", "cutting-face form deviation: spread of the normal deviation about its straight line fitted root to tip, largest over the axial lines"},
           in.face.cuttingFaceForm);
  v.number({"inspection.radialAlignment", "µm", "radial alignment (form and position of the cutting face) as DIN 3968 measures it: in the plane square to the hob axis, an indicator run along the nominal face line (the radial line on a zero-rake hob, else the line at the rake offset e) turned about the hob axis through the face's tip point, zeroed at the tip (the grid's outermost row) and run down to the root; its reading of largest magnitude, signed (plus = the face stands out of the line, excess material), largest over the axial lines"},
           in.face.radialAlignment);
  v.number({"inspection.rakeAngle", "arc-min", "the rake error as an angle at the tip (the grid's outermost row): how far the face's rake angle differs from the nominal, inspection.rakeOffset over sqrt(r_tip^2 - e^2) (plus = hook, a positive rake error; minus = drag)"},
           in.face.rakeAngle * kDegPerRad * 60);
  v.number({"inspection.rakeOffset", "mm", "the same as a rake offset: how far the face line lies moved into the tooth, parallel to itself (plus = hook, material taken off; minus = drag), mean over the axial lines"},
           in.face.rakeOffset);
  if (in.face.gashLead || every)
    v.number({"inspection.gashLead", "µm per 100 mm", "gash lead deviation: slope of the deviation along the hob axis, largest magnitude over the radial lines, signed", kHelicalOnly},
             in.face.gashLead.value_or(0));
  if (gashes || every) {
    static const GashSpacing kNoSpacing;
    static const IndexCorrection kNoIndex;
    const GashSpacing& sp = in.spacing ? *in.spacing : kNoSpacing;
    const IndexCorrection& ic = e.indexCorrection ? *e.indexCorrection : kNoIndex;
    v.number({"inspection.adjacentSpacing", "µm", "single pitch deviation of the cutting faces f_tN (DIN 3968 item 8) at the pitch radius: largest magnitude, signed", kWithGashes},
             sp.adjacentLargest);
    v.number({"inspection.pitchJump", "µm", "pitch jump f_uN (DIN 3968 item 9): the difference between two consecutive single pitch deviations, largest magnitude, signed", kWithGashes},
             sp.pitchJumpLargest);
    v.number({"inspection.cumulativeSpacing", "µm", "cumulative spread of the cutting faces: largest minus smallest gash deviation (information; no table row grades it)", kWithGashes},
             sp.cumulative);
    numbers(v, {"inspection.spacing.adjacent", "µm", "per gash k: gash k+1's deviation minus gash k's (the last: gash 1's minus gash z's)", kWithGashes},
            sp.adjacent);
    numbers(v, {"inspection.spacing.pitchJump", "µm", "per pitch k: its single pitch deviation minus pitch k-1's (pitch 1's minus pitch z's)", kWithGashes},
            sp.pitchJump);
    std::vector<double> micro, degrees;
    for (double a : ic.angle) micro.push_back(a * 1e6);
    for (double a : ic.rounded) degrees.push_back(a * kDegPerRad);
    numbers(v, {"inspection.indexCorrection", "µrad", "per gash: the change of its A-axis index position that brings its face to the mean of all", kWithGashes},
            micro);
    numbers(v, {"inspection.indexCorrectionDeg", "deg", "the same in degrees, rounded to the A axis's resolution (correction.resolution.A)", kWithGashes},
            degrees);
  }
  if (e.gashFaces || every) {
    static const GashFaces kNoFaces;
    const GashFaces& g = e.gashFaces ? *e.gashFaces : kNoFaces;
    std::vector<double> form, alignment, lead;
    for (const FaceChecks& f : g.faces) {
      form.push_back(f.cuttingFaceForm);
      alignment.push_back(f.radialAlignment);
      lead.push_back(f.gashLead.value_or(0));
    }
    numbers(v, {"inspection.perGash.deviation", "µm", "per gash: its mean deviation at the pitch radius (the straight line fitted over the radius to the deviations averaged along the gash)", kWithGashTopographies},
            g.deviations);
    numbers(v, {"inspection.perGash.cuttingFaceForm", "µm", "per gash: its cutting-face form deviation", kWithGashTopographies}, form);
    numbers(v, {"inspection.perGash.radialAlignment", "µm", "per gash: its radial alignment deviation", kWithGashTopographies}, alignment);
    if (helical || every)
      numbers(v, {"inspection.perGash.gashLead", "µm per 100 mm", "per gash: its gash lead deviation (helical gash only)", kWithGashTopographies}, lead);
  }
  const bool simulatedFace = !e.gashFaces && inspectedFace(e).source == FaceSource::Simulated;
  verdict(v, in, "inspection.", "", true, !simulatedFace);
  // The face's checks left ungraded for their face (Inspection::faceNotGraded), then those the
  // table has no tolerance for.
  std::string faceChecks, notGraded;
  for (const CheckResult& c : in.checks) {
    if (c.grade != Grade::NotGraded) continue;
    const bool face = !in.faceNotGraded.empty() && c.check != Check::AdjacentSpacing && c.check != Check::PitchJump &&
                      !c.tolerances.empty();
    std::string& list = face ? faceChecks : notGraded;
    list += (list.empty() ? "" : ", ") + std::string(checkWords(c.check));
  }
  if (!notGraded.empty())
    notGraded = "Not graded: " + notGraded + " (the tolerance table has no value for " +
                (in.band ? "the module band " + band : std::string("this module: it is outside the table's module bands")) +
                "). Enter the hob maker's tolerances in the tolerance table; the case keeps them.";
  if (!faceChecks.empty())
    notGraded = "Not graded: " + faceChecks + ": " + in.faceNotGraded + "." + (notGraded.empty() ? "" : " " + notGraded);
  v.text({"inspection.notGraded", "", "the checks without a tolerance in the module band and what to enter (\"\" when every check is graded)"},
         notGraded);
  // DIN 3968's spacing checks need the gashes measured: without them the class rests on the face's.
  const std::string notMeasured =
      gashes ? std::string()
             : std::string("Not measured: ") + checkWords(Check::AdjacentSpacing) + " and " + checkWords(Check::PitchJump) +
                   " (the case gives no gash deviations or per-gash topographies), so the class rests on the face's "
                   "checks alone. Enter one deviation per gash at the pitch radius to check the gashes' spacing.";
  v.text({"inspection.notMeasured", "", "the checks the case measures nothing for, so that the class does not rest on them, and what to enter (\"\" when none): the single pitch and the pitch jump without gash deviations or per-gash topographies"},
         notMeasured);
  const bool ownTable = e.job.inspection.ownTable.has_value();
  for (Check c : kChecks) {
    const CheckResult* r = in.find(c);
    if (!r && !every) continue;
    static const CheckResult kNoCheck;
    const CheckResult& cr = r ? *r : kNoCheck;
    const std::string base = std::string("inspection.checks.") + checkName(c) + ".";
    const std::string value = base + "value", grade = base + "grade", classes = base + "classes", tolerances = base + "tolerances";
    v.number({value.c_str(), checkUnit(c), "the check's value, as the field inspection.<check> gives it", checkWhen(c)}, cr.value);
    v.text({grade.c_str(), "", "its grade: \"AA\" .. \"D\", \"outside D\" (\"outside B\" where the table stops at B) or \"not graded\" (the table has no tolerance for the module)", checkWhen(c)},
           gradeText(cr.grade, cr.loosest));
    const std::string conformity = base + "conformity", proven = base + "provenGrade", confidence = base + "confidence",
                      source = base + "source", uncertainty = base + "uncertainty";
    // A face check on a simulated face decides nothing; measured gash deviations do.
    const bool decided = !simulatedFace || c == Check::AdjacentSpacing || c == Check::PitchJump;
    v.text({conformity.c_str(), "", "ISO 14253-1, to the class graded (to the loosest class when outside it): \"conforms\", \"does not conform\", \"undecided\" (within U of the limit), \"not graded\", or \"not decided\" (a face check on a simulated face)", checkWhen(c)},
           cr.grade == Grade::NotGraded || decided ? conformityName(cr.conformity) : kNotDecided);
    v.text({proven.c_str(), "", "the tightest class whose tolerance less U holds the value: the class the measurement proves (\"none\", \"not graded\", \"not decided\": a face check on a simulated face)", checkWhen(c)},
           cr.grade == Grade::NotGraded ? std::string("not graded") : !decided ? std::string(kNotDecided) : provenText(cr.proven));
    v.text({confidence.c_str(), "", "where the tolerance the grade rests on comes from: \"printed\" (in the source named), \"series\" (filled from the series the source prints for other rows; not confirmed) or \"entered\" (the case's own table); \"\" when not graded", checkWhen(c)},
           cr.grade == Grade::NotGraded ? "" : confidenceName(cr.confidence));
    const std::string printed = ownTable ? "the case's own table (inspection.tolerances)" : defaultToleranceSource(c);
    const std::string series = ownTable ? "" : defaultSeriesSource(c);
    v.text({source.c_str(), "", "the source of the table's values for the check (and of its series values, after \"; \"); \"\" when the table has none", checkWhen(c)},
           series.empty() ? printed : printed + "; " + series);
    v.number({uncertainty.c_str(), checkUnit(c), "U in the check's unit: inspection.uncertainty, for the gash lead scaled from the axial length measured to 100 mm", checkWhen(c)},
             cr.uncertainty);
    std::vector<std::string> names;
    for (ToleranceClass k : cr.classes) names.push_back(className(k));
    v.texts({classes.c_str(), "", "the classes with a tolerance in the module band, tightest first", checkWhen(c)}, names);
    numbers(v, {tolerances.c_str(), checkUnit(c), "their tolerances (a ± tolerance as its magnitude), one per class", checkWhen(c)},
            cr.tolerances);
  }
  if (!e.inspectionAfter && !every) return;
  static const Inspection kNoInspection;
  const Inspection& after = e.inspectionAfter ? *e.inspectionAfter : kNoInspection;
  v.number({"inspection.after.cuttingFaceForm", "µm", "cutting-face form deviation after the correction on the identified machine (of correction.residual, or the face as it is without a face correction)", kWithEitherCorrection},
           after.face.cuttingFaceForm);
  v.number({"inspection.after.radialAlignment", "µm", "radial alignment deviation after the correction on the identified machine", kWithEitherCorrection},
           after.face.radialAlignment);
  if (helical || every)
    v.number({"inspection.after.gashLead", "µm per 100 mm", "gash lead deviation after the correction on the identified machine (helical gash only)", kWithEitherCorrection},
             after.face.gashLead.value_or(0));
  if (gashes || every) {
    static const GashSpacing kNoSpacing;
    const GashSpacing& sp = after.spacing ? *after.spacing : kNoSpacing;
    v.number({"inspection.after.adjacentSpacing", "µm", "single pitch deviation predicted after running inspection.indexCorrectionDeg", kWithGashes}, sp.adjacentLargest);
    v.number({"inspection.after.pitchJump", "µm", "pitch jump predicted after running inspection.indexCorrectionDeg", kWithGashes}, sp.pitchJumpLargest);
    v.number({"inspection.after.cumulativeSpacing", "µm", "cumulative spread predicted after running inspection.indexCorrectionDeg", kWithGashes}, sp.cumulative);
  }
  verdict(v, after, "inspection.after.", kWithEitherCorrection, false);
  for (Check c : kChecks) {
    const CheckResult* r = after.find(c);
    if (!r && !every) continue;
    const std::string grade = std::string("inspection.after.checks.") + checkName(c) + ".grade";
    v.text({grade.c_str(), "", "the check's grade after the correction, of the face on the identified machine and the gashes after the index correction", kWithEitherCorrection},
           r ? gradeText(r->grade, r->loosest) : gradeName(Grade::NotGraded));
  }
}

// The effect on the gear (docs/gear-effect.md): the reason always, the figures with the
// hob's relief. Per flank: the headline figures, then along the hob per tooth, then the profiles.
void visitGearEffect(const Evaluation& e, ResultVisitor& v, bool every) {
  constexpr const char* kWithRelief = "only with the hob's relief (hob.gashes and hob.relief, or hob.sideReliefAngle)";
  constexpr double kArcMinPerRad = kDegPerRad * 60;
  v.text({"gearEffect.reason", "", "why there is no gear effect (no relief in the case, or the grid holds no whole tooth); \"\" when there is one"},
         e.gearEffect ? "" : e.gearEffectReason);
  if (!e.gearEffect && !every) return;
  static const GearEffect kNone;
  const GearEffect& g = e.gearEffect ? *e.gearEffect : kNone;
  v.text({"gearEffect.source", "", "the rake face the edges lie on: \"measured\", \"measuredPoints\" or \"simulated\" (as inspection.source)", kWithRelief},
         sourceName(inspectedFace(e).source));
  v.number({"gearEffect.reliefPerRadian", "mm/rad", "k = K z / 2 pi: the radial drop of the relieved profile per radian behind the rake face", kWithRelief},
           g.reliefPerRadian);
  v.number({"gearEffect.sideReliefAngle", "deg", "the side relief angle at the pitch radius, atan(k sin(alpha_n) / r_p)", kWithRelief},
           g.sideReliefAngle * kDegPerRad);
  v.number({"gearEffect.activeFrom", "mm", "the hob radius where the evaluated active profile starts (it generates the gear's tip)", kWithRelief}, g.rFrom);
  v.number({"gearEffect.activeTo", "mm", "the hob radius where it ends (it generates the gear's root side)", kWithRelief}, g.rTo);
  struct FlankFields {
    const char *slope, *angle, *form, *scatter, *alongSlope, *alongAngle, *alongForm, *profile;
  };
  static const FlankFields kLeft{"gearEffect.left.profileSlope", "gearEffect.left.pressureAngleError", "gearEffect.left.profileForm",
                                 "gearEffect.left.slopeScatter", "gearEffect.alongHob.left.profileSlope",
                                 "gearEffect.alongHob.left.pressureAngleError", "gearEffect.alongHob.left.profileForm",
                                 "gearEffect.profile.left"};
  static const FlankFields kRight{"gearEffect.right.profileSlope", "gearEffect.right.pressureAngleError", "gearEffect.right.profileForm",
                                  "gearEffect.right.slopeScatter", "gearEffect.alongHob.right.profileSlope",
                                  "gearEffect.alongHob.right.pressureAngleError", "gearEffect.alongHob.right.profileForm",
                                  "gearEffect.profile.right"};
  for (const bool left : {true, false}) {
    const FlankFields& f = left ? kLeft : kRight;
    const ProfileFigures& p = left ? g.left : g.right;
    v.number({f.slope, "µm", "profile slope deviation fH_alpha on the gear flank cut by the hob's left (or right) flank: largest magnitude over the teeth, signed (plus = more material toward the gear's tip)", kWithRelief, "profile slope deviation fHα (largest over the teeth)"},
             p.slope);
    v.number({f.angle, "arc-min", "the pressure-angle error of that tooth's edge: -fH_alpha over the evaluated profile length (plus = larger pressure angle)", kWithRelief, "pressure-angle error of that tooth"},
             p.pressureAngle * kArcMinPerRad);
    v.number({f.form, "µm", "profile form deviation ff_alpha: width of the band about the least-squares profile line, largest over the teeth", kWithRelief, "profile form deviation ffα (largest)"}, p.form);
    v.number({f.scatter, "µm", "scatter of fH_alpha along the hob: largest minus smallest over the teeth", kWithRelief, "scatter of fHα along the hob"},
             left ? g.leftScatter : g.rightScatter);
  }
  // The rake error in the gear's terms (docs/inspection.md, "Rake error"): the model on a face that
  // carries a rake error alone, per degree of hook, and for the rake error inspection.rakeAngle reads.
  if (e.pressureAnglePerRake || every) {
    const double perRake = e.pressureAnglePerRake.value_or(0);
    v.number({"gearEffect.pressureAnglePerDegreeOfRake", "arc-min per deg", "the gear's pressure-angle change per degree of hook at the tip (drag: the opposite sign), mean of the two flanks, from this model on a face that carries a rake error alone (plus = larger pressure angle)", kWithRelief},
             perRake * 60);
    v.number({"gearEffect.rakeErrorPressureAngle", "arc-min", "the pressure-angle change the rake error alone gives the gear: gearEffect.pressureAnglePerDegreeOfRake times inspection.rakeAngle (first order)", kWithRelief},
             perRake * e.inspection.face.rakeAngle * kArcMinPerRad);
  }
  std::vector<double> x;
  for (const ToothEdges& t : g.teeth) x.push_back(t.x);
  numbers(v, {"gearEffect.alongHob.x", "mm", "the axial positions of the teeth evaluated (tooth centres, one axial pitch pi m_n apart)", kWithRelief}, x);
  const std::size_t n = g.height.size();
  for (const bool left : {true, false}) {
    const FlankFields& f = left ? kLeft : kRight;
    std::vector<double> slope, angle, form, profile;
    for (const ToothEdges& t : g.teeth) {
      const ProfileFigures& p = left ? t.left : t.right;
      slope.push_back(p.slope);
      angle.push_back(p.pressureAngle * kArcMinPerRad);
      form.push_back(p.form);
      const std::vector<double>& row = left ? t.leftProfile : t.rightProfile;
      profile.insert(profile.end(), row.begin(), row.end());
    }
    numbers(v, {f.alongSlope, "µm", "per tooth of gearEffect.alongHob.x: fH_alpha of the flank", kWithRelief}, slope);
    numbers(v, {f.alongAngle, "arc-min", "per tooth: the pressure-angle error", kWithRelief}, angle);
    numbers(v, {f.alongForm, "µm", "per tooth: ff_alpha", kWithRelief}, form);
    if (left)
      numbers(v, {"gearEffect.profile.height", "mm", "heights on the gear tooth from its reference line, root (-) to tip (+), where the profiles are given", kWithRelief},
              g.height);
    v.matrix({f.profile, "µm", "per tooth (rows, as gearEffect.alongHob.x), the gear's profile deviation at gearEffect.profile.height (plus = more material)", kWithRelief},
             profile.data(), static_cast<int>(g.teeth.size()), static_cast<int>(n));
  }
}

// Wheel offsets are computed in mm and shown in µm.
std::vector<double> micrometres(const std::vector<double>& mm) {
  std::vector<double> um;
  for (double x : mm) um.push_back(x * kMicrometresPerMm);
  return um;
}

// The dressed or measured wheel (docs/case-format.md §The wheel's profile): present only when the
// case gives wheel.profileOffset or wheel.measuredProfile.
void visitWheelOffset(const Evaluation& e, ResultVisitor& v) {
  constexpr const char* kWithOffset = "only with wheel.profileOffset or wheel.measuredProfile";
  const WheelSurface& wheel = e.job.setup.wheel;
  if (!wheel.hasOffset() && !v.listsEveryField()) return;
  const DressedProfile& d = e.dressedProfile;
  numbers(v, {"wheelProfile.offset", "µm", "the wheel's profile offset at each point (+ = more wheel, less material)", kWithOffset},
          micrometres(d.offset));
  numbers(v, {"wheelProfile.dressedR", "mm", "wheel radius of the dressed (or measured) wheel's profile", kWithOffset}, d.dressedR);
  numbers(v, {"wheelProfile.dressedZ", "mm", "axial position of the dressed (or measured) wheel's profile", kWithOffset}, d.dressedZ);
  static const CubicSpline kNone;
  const CubicSpline& spline = wheel.offset ? *wheel.offset : kNone;
  numbers(v, {"wheelOffset.R", "mm", "the offset's spline points: conjugate wheel radius (for a measured wheel, the projected points)", kWithOffset},
          spline.x());
  numbers(v, {"wheelOffset.offset", "µm", "the offset at wheelOffset.R", kWithOffset}, micrometres(spline.y()));
  const WheelOffsetSensitivity& S = e.offsetSensitivities;
  v.matrices({"wheelOffset.sensitivities", "µm per µm", "per point of wheelOffset.R: the normal deviation of a 1 µm change of its offset",
              kWithOffset}, S.normal.data(), static_cast<int>(S.normal.cols()), e.sensitivities.rows, e.sensitivities.cols);
  eigenNumbers(v, {"wheelOffset.thickness", "µm per µm", "per point of wheelOffset.R: the thickness change of a 1 µm change", kWithOffset},
               S.thickness);
}

// The wheel-profile correction (docs/method.md §Wheel-profile correction): present only with
// `correction.wheel: true`.
void visitWheelCorrection(const Evaluation& e, ResultVisitor& v) {
  constexpr const char* kWithWheel = "only with `measured` and `correction.wheel`";
  if (!e.wheelCorrection && !v.listsEveryField()) return;
  static const WheelCorrection kNoWheel;
  const WheelCorrection& w = e.wheelCorrection ? *e.wheelCorrection : kNoWheel;
  numbers(v, {"correction.wheelProfileOffset.R", "mm", "the dressing's spline points: conjugate wheel radius, over the radii the grid is ground with", kWithWheel, "dressing point R"},
          w.knots.R);
  numbers(v, {"correction.wheelProfileOffset.offset", "µm", "what to dress in addition to the current offset at those points, a not-a-knot cubic spline (+ = more wheel, less material)", kWithWheel, "dressing (+ = more wheel)"},
          w.offset);
  numbers(v, {"correction.dresserPath.R", "mm", "the corrected axial wheel profile for the dresser: the current profile plus the dressing along its normal, at the wheelProfile points", kWithWheel, "dresser path R"},
          w.dresser.dressedR);
  numbers(v, {"correction.dresserPath.Z", "mm", "its axial positions", kWithWheel, "dresser path Z"}, w.dresser.dressedZ);
  numbers(v, {"correction.dresserPath.offset", "µm", "the wheel's offset after the dressing at the wheelProfile points: the current offset plus the proposed spline (+ = more wheel)", kWithWheel, "offset after dressing (+ = more wheel)"},
          micrometres(w.dresser.offset));
  matrix(v, {"correction.removedByAxes", "µm", "the part of the measured face the axes remove (in the span of the directions they take)", kWithWheel},
         w.removedByAxes);
  matrix(v, {"correction.removedByWheel", "µm", "the part the wheel's dressing removes: the shape the axes cannot make", kWithWheel},
         w.removedByWheel);
  v.number({"correction.axesShare", "", "share of the measured sum of squares the axes remove, 0..1", kWithWheel, "share the axis moves remove"}, w.axesShare);
  v.number({"correction.wheelShare", "", "share of the measured sum of squares the wheel removes, 0..1 (with axesShare and uncorrectableShare: 1)", kWithWheel, "share the wheel removes"},
           w.wheelShare);
}

}  // namespace

const char* fieldKindName(FieldKind kind) {
  switch (kind) {
    case FieldKind::Number: return "number";
    case FieldKind::Count: return "integer";
    case FieldKind::Flag: return "boolean";
    case FieldKind::Text: return "string";
    case FieldKind::Texts: return "strings";
    case FieldKind::Numbers: return "numbers";
    case FieldKind::Matrix: return "matrix";
    case FieldKind::Matrices: return "matrices";
    case FieldKind::Axes: return "axes";
  }
  return "";
}

const char* axisUnit(Axis axis) { return isRotary(axis) ? "rad" : "mm"; }
const char* motionUnit(GashKind gash) { return gash == GashKind::Helical ? "rad" : "mm"; }

void visitResult(const Evaluation& e, ResultVisitor& v) {
  const SharpeningJob& job = e.job;
  const SharpeningSetup& s = job.setup;
  const ToothFace& face = s.face;
  const bool every = v.listsEveryField();

  v.number({"setup.tilt", "deg", "eta, the tilt of the wheel head (the manual axis psi_c)"}, s.universal.tilt * kDegPerRad);
  v.number({"setup.settingAngle", "deg", "gamma_m used"}, s.universal.settingAngle.coefficient(0) * kDegPerRad);
  v.number({"setup.centerDistance", "mm", "E_t used"}, s.universal.centerDistance.coefficient(0));
  v.number({"setup.screwParameter", "mm/rad", "P_t = L_c / 2 pi (1, in mm/mm, for a straight gash)"},
           s.universal.screwParameter());
  v.flag({"setup.settingAngleDerived", "", "true when gamma_m was derived (the gash helix angle, signed by hand)"},
         job.settingAngleDerived);
  v.flag({"setup.centerDistanceDerived", "", "true when E_t is from the boundary equation (wheel rim at the gash root)"},
         job.centerDistanceDerived);
  v.number({"setup.rakeAngle", "deg", "gamma_c, the rake angle at the pitch radius", "", "rake angle γc"}, face.rakeAngle() * kDegPerRad);
  v.text({"setup.gash", "", "\"helical\" or \"straight\""}, face.helical() ? "helical" : "straight");
  v.text({"setup.hand", "", "\"right\" or \"left\""}, face.hand() == Hand::Left ? "left" : "right");
  if (face.helical() || every) {
    v.number({"setup.gashLead", "mm", "L_c, the gash lead", kHelicalOnly, "lead Lc"}, face.lead());
    v.number({"setup.gashHelixAngle", "deg", "the gash helix angle at the pitch diameter", kHelicalOnly, "helix angle βc"},
             face.helixAngle() * kDegPerRad);
  }
  v.number({"setup.rootRadius", "mm", "radius of the gash root"}, job.rootRadius);
  v.number({"setup.outerRadius", "mm", "the hob's outer radius"}, job.outerRadius);
  v.text({"setup.motionUnit", "", "unit of the motion parameter: \"rad\" (phi_1, helical) or \"mm\" (s, straight)"},
         motionUnit(face.gash));

  v.axes({"axes", kCoefficientUnit, "the nominal axis polynomials X .. B, a0 .. an (Eq. 9, Tab. 2 left)"}, job.nominalAxes);
  v.axes({"runAxes", kCoefficientUnit, "the polynomials simulated: case.axes, or the nominal ones"}, job.runAxes);

  numbers(v, {"wheelProfile.r", "mm", "tooth-face radius, root to tip (limits().wheelProfilePoints points)"},
          e.job.wheelProfile.r);
  numbers(v, {"wheelProfile.beta", kMotionUnit, "contact coordinate on the face: beta* (rad), x* for a straight gash (mm)"},
          e.job.wheelProfile.w);
  numbers(v, {"wheelProfile.R", "mm", "wheel radius"}, e.job.wheelProfile.R);
  numbers(v, {"wheelProfile.Z", "mm", "axial position on the wheel"}, e.job.wheelProfile.Z);
  v.number({"wheelProfile.turnRadius", "mm", "the face radius where the conjugate profile turns back (the edge of the wheel's envelope); the outer radius when it reaches the tip", "", "profile turns back at"},
           job.setup.wheelEdge ? job.setup.wheelEdge->turnRadius : job.outerRadius);
  v.text({"wheelProfile.edge", "", "the band of the face past the edge of the wheel's envelope, in words; \"\" when the conjugate profile reaches the tip"},
         job.setup.wheelEdge ? wheelEdgeText(*job.setup.wheelEdge) : "");
  visitWheelOffset(e, v);

  const MotionRange motion = motionRange(e.groundFace);
  v.number({"motion.min", kMotionUnit, "lowest motion parameter over the grid (at most 0)"}, motion.min);
  v.number({"motion.max", kMotionUnit, "highest motion parameter over the grid (at least 0)"}, motion.max);

  const Topography& t = e.topography;
  numbers(v, {"topography.r", "mm", "grid radii, root to tip"}, t.grid.r);
  numbers(v, {"topography.x", "mm", "grid axial positions, along the gash"}, t.grid.x);
  matrix(v, {"topography.normal", "µm", "normal deviation for the axes run (for the nominal axes where correction.linearisedAtNominal: the axes run alone grind no face the wheel envelops); plus = excess material"}, t.normal);
  matrix(v, {"topography.circular", "µm", "the same along the circle about the hob axis, µm of arc at the mean radius"},
         t.circular);
  v.number({"topography.thickness", "µm", "thickness error at the mean point", "", "thickness error"}, t.thickness);
  v.number({"topography.sse", "µm²", "sum of squares of the normal deviation", "", "sum of squares"}, t.sse);
  v.number({"topography.max", "µm", "largest absolute normal deviation", "", "largest |deviation|"}, t.max);
  v.number({"topography.rms", "µm", "root mean square of the normal deviation: comparable between grids of any density", "", "rms"}, t.rms);
  v.number({"topography.peakToValley", "µm", "largest minus smallest normal deviation", "", "peak-to-valley"}, t.peakToValley);

  const SensitivityMatrix& S = e.sensitivities;
  v.texts({"sensitivities.coefficients", "", "\"X a0\" .. \"B an\", axis by axis"}, names(S.coefficients));
  // Column j of the (rows * cols) x q matrix is coefficient j's topography in row-major order.
  v.matrices({"sensitivities.normal", "µm per unit", "per coefficient: the normal deviation of a unit change (Eqs. 13-16)"},
             S.normal.data(), static_cast<int>(S.normal.cols()), S.rows, S.cols);
  eigenNumbers(v, {"sensitivities.thickness", "µm per unit", "per coefficient: the thickness change of a unit change"},
               S.thickness);

  if (e.correction || every) {
    static const Correction kNone;
    const Correction& c = e.correction ? *e.correction : kNone;
    const double probeNoise = e.job.correction.probeNoise;
    v.text({"correction.method", "", "\"nonlinear\" (identify the machine error, run nominal - error) or \"linear\" (Eq. 17 once)",
            kWithMeasured}, c.method == CorrectionMethod::Linear ? "linear" : "nonlinear");
    v.text({"correction.status", "", "\"converged\" (the misfit within the probe noise), \"aboveNoise\" (a tolerance met, the misfit above the noise), \"notConverged\" (iterations ran out), \"stalled\" or \"failed\"",
            kWithMeasured}, statusName(c.summary.status));
    v.text({"correction.statusReason", "", "a sentence: which tolerance was met, or why the solve stopped", kWithMeasured},
           c.summary.reason);
    v.flag({"correction.usable", "", "the proposal may be used (every status but \"failed\")", kWithMeasured},
           c.summary.IsSolutionUsable());
    v.flag({"correction.runKept", "", "the correction found would leave a worse face than the one measured (re-simulated), so the run axes are proposed unchanged",
            kWithMeasured}, c.runKept);
    v.count({"correction.iterations", "", "solver iterations (Jacobian evaluations); 1 for the linear step", kWithMeasured},
            c.summary.iterations);
    v.number({"correction.probeNoise", "µm", "the probe noise sigma the correction assumed", kWithMeasured}, probeNoise);
    v.axes({"correction.axes", kCoefficientUnit, "the exact proposal, the axes to run next: nominal minus the identified error (Tab. 2 right)",
            kWithMeasured}, c.axes);
    // The digits are the option's (machine_resolution.h), written once.
    static const std::string kRounded = "correction.axes as a control keeps polynomial coefficients: each coefficient to " +
                                        std::to_string(MachineResolution{}.coefficientDigits) +
                                        " significant digits in mm or deg per (deg or mm)^k (docs/conventions.md, Machine resolution); "
                                        "the NC programs written re-expand the polynomials in blocks with their own digits and state "
                                        "their own deviation from correction.axes (docs/nc-programs.md)";
    v.axes({"correction.roundedAxes", kCoefficientUnit, kRounded.c_str(), kWithMeasured}, c.roundedAxes);
    v.texts({"correction.coefficients", "", "the coefficients left free (not locked)", kWithMeasured}, names(c.coefficients));
    eigenNumbers(v, {"correction.change", "coefficient units", "the changes of correction.coefficients, in order: correction.axes minus the axes run", kWithMeasured}, c.change);
    // One figure per axis: µm-type units for X, Y, Z and µrad-type ones for A, B (docs/method.md, "Correction").
    auto perAxis = [&](const char* const names[], const char* linear, const char* rotary, const char* what,
                       const std::array<double, kAxisCount>& values, const char* label = "") {
      for (Axis a : kAxes) {
        const int i = static_cast<int>(a);
        v.number({names[i], isRotary(a) ? rotary : linear, what, kWithMeasured, label}, values[i]);
      }
    };
    perAxis(kIdentified, "µm", "µrad", "the identified machine error of the axis (actual minus commanded): largest over the motion range the face measured spans (a grid's: motion.min to motion.max; measured points may span less than the axes run), signed; where correction.identifiedAxes is not \"alone\" a share of a combination the face does not split, not a finding about the axis",
            c.identifiedErrorSize);
    perAxis(kChange, "µm", "µrad", "the change proposed for the axis, correction.axes minus the axes run: largest over the motion range the face measured spans (a grid's: motion.min to motion.max; measured points may span less than the axes run), signed",
            c.axisChangeSize);
    perAxis(kChangeOverFace, "µm", "µrad", "the change proposed for the axis over the motion range the program runs (the grid's: motion.min to motion.max), signed: correction.axisChange where the face was measured on the grid, and where the grid's figure is not larger by more than half the axis's resolution step; at measured points that span less, the change the program makes beyond them, where no probe saw the face",
            c.axisChangeOverFace);
    perAxis(kUncertainty, "µm", "µrad", "the precision demand times the probe noise: the standard deviation the identified error and the change would have from the probe noise were every direction the face shows among those sought taken (the identifiable space; every coefficient where the face was sought over every coefficient), largest over the motion range the face measured spans (a grid's: motion.min to motion.max; measured points may span less than the axes run): correction.precision.changePerNoise times correction.probeNoise. Not the spread of this proposal over measurements: the identification takes only the directions the data hold above the noise, and on random hobs this figure is mostly far above that spread and below half of it for under 1 % of the axes (docs/conventions.md)",
            c.uncertainty);
    perAxis(kFacePerError, "µm per µm", "µm per µrad", "precision demand: face deviation per unit of a constant error of the axis, largest over the grid",
            c.facePerAxisError, "face per unit of axis error, largest over the grid");
    perAxis(kChangePerNoise, "µm per µm", "µrad per µm", "precision demand: standard deviation of the axis change per µm of probe noise were every direction the face shows among those sought taken (the identifiable space; every coefficient where the face was sought over every coefficient); not the spread of this proposal over measurements (correction.uncertainty)",
            c.changePerNoise, "axis change per µm of probe noise were every direction the face shows taken");
    // What the face identifies of each axis (identified_axes.h): alone, together or unseen; the
    // value read alone; the combinations in words.
    static const char* const kReading[] = {"correction.identifiedAxes.X", "correction.identifiedAxes.Y",
                                           "correction.identifiedAxes.Z", "correction.identifiedAxes.A",
                                           "correction.identifiedAxes.B"};
    static const char* const kAlone[] = {"correction.identifiedAlone.X", "correction.identifiedAlone.Y",
                                         "correction.identifiedAlone.Z", "correction.identifiedAlone.A",
                                         "correction.identifiedAlone.B"};
    static const char* const kAloneUncertainty[] = {
        "correction.identifiedAloneUncertainty.X", "correction.identifiedAloneUncertainty.Y",
        "correction.identifiedAloneUncertainty.Z", "correction.identifiedAloneUncertainty.A",
        "correction.identifiedAloneUncertainty.B"};
    static const char* const kAloneSecondOrder[] = {
        "correction.identifiedAloneSecondOrder.X", "correction.identifiedAloneSecondOrder.Y",
        "correction.identifiedAloneSecondOrder.Z", "correction.identifiedAloneSecondOrder.A",
        "correction.identifiedAloneSecondOrder.B"};
    std::array<double, kAxisCount> alone{}, aloneUncertainty{}, aloneSecondOrder{};
    for (Axis a : kAxes) {
      const int i = static_cast<int>(a);
      const AxisIdentification& x = c.identified.axes[i];
      v.text({kReading[i], "", "what the face tells of the axis's error: \"alone\" (told from the other axes', read in correction.identifiedAlone), \"together\" (not told from some other axes': see correction.identifiedCombinations), \"unseen\" (the face does not show it) or \"locked\"", kWithMeasured},
             readingName(x.reading));
      alone[i] = x.value;
      aloneUncertainty[i] = x.perNoise * probeNoise;
      aloneSecondOrder[i] = x.secondOrder;
    }
    perAxis(kAlone, "µm", "µrad", "the axis's error read on its own, its mean over the motion range the face measured spans (a grid's: motion.min to motion.max; measured points may span less than the axes run); 0 unless correction.identifiedAxes gives \"alone\"",
            alone);
    perAxis(kAloneUncertainty, "µm", "µrad", "standard uncertainty of correction.identifiedAlone from the probe noise; 0 unless \"alone\"",
            aloneUncertainty);
    perAxis(kAloneSecondOrder, "µm", "µrad", "how far the error's second-order face may move correction.identifiedAlone beyond its uncertainty (twice what the identified error's own second-order face moves it; read from the face measured at the axes run, else 0); 0 unless \"alone\"",
            aloneSecondOrder, "the error's second order may move it up to");
    v.texts({"correction.identifiedCombinations", "", "sentences: the axes the face does not tell apart, in what proportion they grind alike and what it shows of them (µm, µrad), then the axes it does not show", kWithMeasured},
            c.identified.sentences);
    // With measuredPoints off the grid the grid views are the re-simulated faces (docs/measured-points.md).
    const Topography& gridAfter = c.atProbes() ? c.afterOnGrid : c.after;
    const Topography& gridMeasured = c.atProbes() ? c.explainedOnGrid : c.before;
    matrix(v, {"correction.residual", "µm", "the face after the pass on the identified machine: re-simulated with correction.axes and the identified error, plus the part no axis makes, noise and all; off the grid, on measured points, the re-simulated face alone (what the pass leaves is bounded by correction.predictedRmsHigh)", kWithMeasured}, gridAfter.normal);
    matrix(v, {"correction.residualCircular", "µm", "the same along the circle about the hob axis", kWithMeasured},
           gridAfter.circular);
    matrix(v, {"correction.measuredCircular", "µm", "the measured deviation along the circle about the hob axis",
               kWithMeasured}, gridMeasured.circular);
    v.number({"correction.sseBefore", "µm²", "sum of squares, measured", kWithMeasured, "sum of squares"}, c.before.sse);
    v.number({"correction.sseAfter", "µm²", "sum of squares of the face after the pass on the identified machine (re-simulated)", kWithMeasured, "sum of squares"}, c.after.sse);
    v.number({"correction.maxBefore", "µm", "largest absolute deviation, measured", kWithMeasured, "largest |deviation|"}, c.before.max);
    v.number({"correction.maxAfter", "µm", "largest absolute deviation after the pass on the identified machine", kWithMeasured, "largest |deviation|"}, c.after.max);
    v.number({"correction.rmsBefore", "µm", "root mean square, measured", kWithMeasured, "rms"}, c.before.rms);
    v.number({"correction.rmsAfter", "µm", "root mean square after the pass on the identified machine, this measurement's misfit kept, noise and all (what the pass leaves is bounded by correction.predictedRmsHigh, which leaves that noise out and can be lower)", kWithMeasured, "rms"}, c.after.rms);
    v.number({"correction.predictedRms", "µm", "the face the exact axes leave on the probe grid if the identified error is all of the machine's, rms: the misfit left less its expected probe noise (the pass can leave more, up to the bound)", kWithMeasured},
             c.predictedRms);
    v.number({"correction.predictedRmsHigh", "µm", "at most this rms on the probe grid: the misfit, the probe noise through the identified directions and the error the face cannot show (assumed no larger than the one it shows); a bound that can be exceeded: on each of 30 random campaign seeds the face a pass left lay within it in 93 to 97 % of the noise-free and 98 to 100 % of the noisy passes (docs/validation.md)", kWithMeasured},
             c.predictedRmsHigh);
    v.text({"correction.boundCondition", "", "what correction.predictedRmsHigh assumes, in the verdict's words (\"if the error the face cannot show is no larger than the one it shows\"); \"\" where it assumes nothing", kWithMeasured},
           predictionCondition(c));
    v.flag({"correction.mayStayUnground", "", "the change is uncertain and, with some of the errors the face cannot show, part of the face would stay unground (the wheel would not reach it, or may stop enveloping it near a point): the verdict says where", kWithMeasured},
           c.mayStayUnground());
    v.flag({"correction.stop", "", "the measured face is within the probe noise: another pass would only move noise", kWithMeasured},
           c.stop);
    v.flag({"correction.linearisedAtNominal", "", "the axes run alone grind no face the wheel envelops: the correction was linearised at the nominal axes, from the face measured", kWithMeasured},
           c.linearisedAtNominal);
    v.count({"correction.passesJoined", "", "the earlier passes (the case's passes measured on the grid) whose faces the identified machine error explains together with this one; 0: identified from this face alone", kWithMeasured},
            c.passesJoined);
    v.flag({"correction.signReversed", "", "from the last pass measured on the grid (or at the same points) to this one the faces measured moved against the change the axes' change makes as this calculator signs deviations: the measuring machine's sign and the calculator's disagree, and the verdict leads with \"Check the sign:\" (unless it says stop: the face is within the probe noise and grinding ends)", kWithMeasured},
           c.signReversed());
    v.number({"correction.peakToValleyBefore", "µm", "largest minus smallest deviation, measured", kWithMeasured, "peak-to-valley"},
             c.before.peakToValley);
    v.number({"correction.peakToValleyAfter", "µm", "largest minus smallest deviation after the pass on the identified machine", kWithMeasured, "peak-to-valley"},
             c.after.peakToValley);
    v.number({"correction.thicknessBefore", "µm", "thickness error at the mean point, measured", kWithMeasured, "thickness error"},
             c.before.thickness);
    v.number({"correction.thicknessAfter", "µm", "thickness error after the pass on the identified machine", kWithMeasured, "thickness error"}, c.after.thickness);
    // The pass history's first prediction, read as the measurement is (correction.h); not where the
    // axes run alone grind no face the wheel envelops (the face it was taken from is the nominal axes').
    if (!c.linearisedAtNominal || every) {
      v.number({"correction.rmsSimulated", "µm", "root mean square of the face the axes run grind with no machine error, at the measured points and read as the measurement is", kWithSimulatedRun, "rms"}, c.simulated.rms);
      v.number({"correction.sseSimulated", "µm²", "sum of squares of the face the axes run grind with no machine error, at the measured points and read as the measurement is", kWithSimulatedRun, "sum of squares"}, c.simulated.sse);
      v.number({"correction.maxSimulated", "µm", "largest absolute deviation of the face the axes run grind with no machine error, at the measured points and read as the measurement is", kWithSimulatedRun, "largest |deviation|"}, c.simulated.max);
      v.number({"correction.thicknessSimulated", "µm", "thickness error of the face the axes run grind with no machine error, at the measured points and read as the measurement is (interpolated at the grid's centre, or at the probe nearest the mean point, as correction.thicknessBefore; topography.thickness is the simulated face's own value at the mean point)", kWithSimulatedRun, "thickness error"}, c.simulated.thickness);
    }
    v.number({"correction.sseRounded", "µm²", "sum of squares with correction.roundedAxes on the identified machine (re-simulated)", kWithMeasured, "sum of squares"},
             c.afterRounded.sse);
    v.number({"correction.maxRounded", "µm", "largest absolute deviation with correction.roundedAxes on the identified machine", kWithMeasured, "largest |deviation|"},
             c.afterRounded.max);
    v.number({"correction.thicknessRounded", "µm", "thickness error with correction.roundedAxes on the identified machine", kWithMeasured, "thickness error"},
             c.afterRounded.thickness);
    v.number({"correction.rmsRounded", "µm", "root mean square with correction.roundedAxes on the identified machine (re-simulated)", kWithMeasured, "rms"},
             c.afterRounded.rms);
    v.number({"correction.resolutionFloor", "µm", "the pass's floor, rms on the probe grid: the face rms that quantising each axis position to correction.resolution causes; each position's error uniform in +-step/2 (sd step/sqrt 12), independent between axes, through the face's sensitivity to a constant change of the axis", kWithMeasured},
             c.resolutionFloor);
    eigenNumbers(v, {"correction.singularValues", "", "nonlinear: of the identifiable directions in µm of face per machine step; linear: of the column-scaled matrix; largest first", kWithMeasured},
                 c.singularValues);
    std::vector<double> used;
    for (size_t i = 0; i < c.directionsUsed.size(); ++i)
      if (c.directionsUsed[i]) used.push_back(static_cast<double>(i + 1));
    if (c.method == CorrectionMethod::Linear)
      for (int i = 0; i < c.rank; ++i) used.push_back(i + 1);
    numbers(v, {"correction.usedDirections", "", "which of correction.singularValues the correction uses, 1-based", kWithMeasured}, used);
    v.count({"correction.rank", "", "singular directions used in the correction", kWithMeasured}, c.rank);
    v.count({"correction.amplifyingDropped", "", "directions left out because they would need wild axis moves for little gain (would amplify)",
             kWithMeasured}, c.amplifyingDropped);
    v.count({"correction.withinNoise", "", "directions left out because the measurement shows them only within the probe noise (nonlinear)",
             kWithMeasured}, c.withinNoise);
    std::vector<std::string> unobservable;
    for (const UnobservableCombination& u : c.unobservable) unobservable.push_back(u.description);
    v.texts({"correction.unobservable", "", "sentences: coefficient combinations the grid cannot see to first order: left out of the error and the change, or, where the sentence says so, sought all the same", kWithMeasured},
            unobservable);
    v.number({"correction.uncorrectableShare", "", "share of the measured sum of squares that stays after the pass on the identified machine, 0..1",
              kWithMeasured}, c.uncorrectableShare);
    v.text({"correction.verdict", "", "one sentence for the engineer", kWithMeasured}, c.verdict);
    if (c.atProbes() || every) visitPointCorrection(c, v);
    visitWheelCorrection(e, v);
  }
  visitInspection(e, v, every);
  visitGearEffect(e, v, every);
}

std::string firstNonFinite(const Evaluation& e) {
  FiniteCheck check;
  visitResult(e, check);
  return check.path;
}

std::vector<FieldDescription> resultFields() {
  FieldList list;
  visitResult(Evaluation{}, list);
  return list.fields;
}

Outcome<Evaluation> evaluateCase(const std::string& caseText) {
  auto in = parseCase(caseText);
  if (!in) return in.error();
  auto job = resolveJob(*in);
  if (!job) return job.error();
  auto e = evaluate(*job);
  if (!e) return e.error();
  // No NaN may reach a table or a plot: a value that is not finite is the calculator's fault.
  FiniteCheck check;
  visitResult(*e, check);
  if (!check.path.empty())
    return Error{"", "The calculation gave " + check.path + " = " + nonFiniteName(check.value) +
                         ", which is not a finite number. This is a fault of the calculator, not of the case; "
                         "please report the case.",
                 ErrorCode::Internal};
  return std::move(e).value();
}

std::string resultJson(const Evaluation& e, int indent) {
  JsonWriter w;
  visitResult(e, w);
  return w.root.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace hobsharp
