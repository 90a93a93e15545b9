// The embind layer: a case (JSON text) in, the typed evaluation out as a JS object whose arrays
// are Float64Arrays copied out of wasm memory. Failures come back as {ok: false, field, message};
// wasm/pre.js turns them into thrown Errors. No C++ exception crosses into JS.
#include <exception>
#include <string>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/emscripten.h>
#include <emscripten/val.h>

#include "case_json.h"
#include "evaluation.h"

namespace hobsharp {
namespace {

using emscripten::val;
constexpr double kDeg = 180.0 / M_PI;

val f64(const double* data, size_t n) { return val(emscripten::typed_memory_view(n, data)).call<val>("slice"); }
val f64(const std::vector<double>& v) { return f64(v.data(), v.size()); }
val f64(const Eigen::VectorXd& v) { return f64(v.data(), static_cast<size_t>(v.size())); }

// Row-major: rows root to tip, each row along the gash.
val rowMajor(const Eigen::MatrixXd& m) {
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> r = m;
  return f64(r.data(), static_cast<size_t>(r.size()));
}

val axesOf(const AxisPolynomials& a) {
  val o = val::object();
  for (Axis x : kAxes) o.set(axisName(x), f64(a[x].a));
  return o;
}

val names(const std::vector<Coefficient>& c) {
  val a = val::array();
  for (const Coefficient& k : c) a.call<void>("push", k.name());
  return a;
}

val topographyOf(const Topography& t) {
  val o = val::object();
  o.set("r", f64(t.grid.r));
  o.set("x", f64(t.grid.x));
  o.set("rows", t.grid.rows());
  o.set("cols", t.grid.cols());
  o.set("normal", rowMajor(t.normal));
  o.set("circular", rowMajor(t.circular));
  o.set("thickness", t.thickness);
  o.set("sse", t.sse);
  o.set("max", t.max);
  return o;
}

val setupOf(const SharpeningJob& job) {
  const SharpeningSetup& s = job.setup;
  val o = val::object();
  o.set("tilt", s.universal.tilt * kDeg);
  o.set("settingAngle", s.universal.settingAngle.coefficient(0) * kDeg);
  o.set("centerDistance", s.universal.centerDistance.coefficient(0));
  o.set("screwParameter", s.universal.screwParameter());
  o.set("settingAngleDerived", job.settingAngleDerived);
  o.set("centerDistanceDerived", job.centerDistanceDerived);
  o.set("rakeAngle", s.face.rakeAngle() * kDeg);
  o.set("gash", std::string(s.face.helical() ? "helical" : "straight"));
  o.set("hand", std::string(s.face.hand() == Hand::Left ? "left" : "right"));
  if (s.face.helical()) {
    o.set("gashLead", 2 * M_PI * std::abs(s.face.screwParameter));
    o.set("gashHelixAngle", std::atan(s.face.pitchRadius / std::abs(s.face.screwParameter)) * kDeg);
  }
  o.set("rootRadius", job.rootRadius);
  o.set("outerRadius", job.outerRadius);
  o.set("motionUnit", std::string(s.face.helical() ? "rad" : "mm"));
  return o;
}

val correctionOf(const Correction& c) {
  val o = val::object();
  o.set("axes", axesOf(c.axes));
  o.set("coefficients", names(c.coefficients));
  o.set("change", f64(c.change));
  o.set("measured", topographyOf(c.before));
  o.set("predicted", topographyOf(c.after));
  o.set("sseBefore", c.before.sse);
  o.set("sseAfter", c.after.sse);
  o.set("thicknessBefore", c.before.thickness);
  o.set("thicknessAfter", c.after.thickness);
  o.set("singularValues", f64(c.singularValues));
  o.set("rank", c.rank);
  o.set("amplifyingDropped", c.amplifyingDropped);
  val u = val::array();
  for (const UnobservableCombination& k : c.unobservable) u.call<void>("push", k.description);
  o.set("unobservable", u);
  o.set("uncorrectableShare", c.uncorrectableShare);
  o.set("verdict", c.verdict);
  return o;
}

val resultOf(const Evaluation& e) {
  val o = val::object();
  o.set("ok", true);
  o.set("setup", setupOf(e.job));
  o.set("axes", axesOf(e.job.nominalAxes));
  o.set("runAxes", axesOf(e.job.runAxes));
  val profile = val::object();
  profile.set("r", f64(e.wheelProfile.r));
  profile.set("beta", f64(e.wheelProfile.w));
  profile.set("R", f64(e.wheelProfile.R));
  profile.set("Z", f64(e.wheelProfile.Z));
  o.set("wheelProfile", profile);
  double lo = 0, hi = 0;
  for (const EnvelopePoint& p : e.groundFace.envelope) lo = std::min(lo, p.phi), hi = std::max(hi, p.phi);
  val motion = val::object();
  motion.set("min", lo);
  motion.set("max", hi);
  o.set("motion", motion);
  o.set("topography", topographyOf(e.topography));
  val s = val::object();
  s.set("coefficients", names(e.sensitivities.coefficients));
  s.set("rows", e.sensitivities.rows);
  s.set("cols", e.sensitivities.cols);
  // Coefficient by coefficient (the matrix is column-major), each a row-major rows x cols
  // topography, µm per unit.
  const Eigen::MatrixXd& normal = e.sensitivities.normal;
  s.set("normal", f64(normal.data(), static_cast<size_t>(normal.size())));
  s.set("thickness", f64(Eigen::VectorXd(e.sensitivities.thickness.transpose())));
  o.set("sensitivities", s);
  if (e.correction) o.set("correction", correctionOf(*e.correction));
  return o;
}

val failure(const Error& error) {
  val o = val::object();
  o.set("ok", false);
  o.set("field", error.field);
  o.set("message", error.message);
  return o;
}

val evaluateJson(const std::string& text) {
  try {
    auto in = parseCase(text);
    if (!in) return failure(in.error());
    auto job = resolveJob(*in);
    if (!job) return failure(job.error());
    auto e = evaluate(*job);
    if (!e) return failure(e.error());
    return resultOf(*e);
  } catch (const std::exception& ex) {
    return failure(Error{"", std::string("The calculation failed: ") + ex.what()});
  } catch (...) {
    return failure(Error{"", "The calculation failed for an unknown reason."});
  }
}

// Benchmark hooks (tests/benchmark-wasm.mjs): the same C++ work as tests/benchmark.cpp, timed
// inside the module so that no JS marshaling is counted. Milliseconds per run, or -1 on bad input.
template <class Work>
double timeRuns(const std::string& text, int runs, Work work) {
  auto in = parseCase(text);
  if (!in) return -1;
  auto job = resolveJob(*in);
  if (!job) return -1;
  if (!work(*job)) return -1;  // warm-up
  const double start = emscripten_get_now();
  for (int i = 0; i < runs; ++i) work(*job);
  return (emscripten_get_now() - start) / runs;
}

double timeCorrectionCycle(const std::string& text, int runs) {
  return timeRuns(text, runs, [](const SharpeningJob& job) { return evaluate(job).ok(); });
}

double timeTopography(const std::string& text, int runs) {
  return timeRuns(text, runs, [](const SharpeningJob& job) {
    auto f = simulateGroundFace(job.setup, job.runAxes, job.grid, Sensitivities::Skip);
    return f.ok() && topographyOf(*f).max >= 0;
  });
}

}  // namespace
}  // namespace hobsharp

EMSCRIPTEN_BINDINGS(hobsharp) {
  emscripten::function("evaluateJson", &hobsharp::evaluateJson);
  emscripten::function("timeCorrectionCycle", &hobsharp::timeCorrectionCycle);
  emscripten::function("timeTopography", &hobsharp::timeTopography);
}
