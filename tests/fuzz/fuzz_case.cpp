// libFuzzer target for the case reader: bytes in, read + resolve + evaluate, as the page and the
// command line do with a case file (docs/case-format.md). Built only with -DHOBSHARP_FUZZ=ON
// (clang, -fsanitize=fuzzer,address,undefined); ./hobsharp.sh test runs it for about a minute.
// A finding is any crash or sanitizer report, or a broken promise of the reader:
//   - every refusal names a field, and its message starts with "<field>: " or names the field in
//     the engineer's words (issue 22: a measured point or grid, a pass's, a gash's topography, the
//     wheel file, counted from 1) without its path; it is short and valid UTF-8 (the page shows
//     it; embind hands it to JS as UTF-8);
//   - an accepted case gives finite numbers everywhere the page shows them.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "case_json.h"
#include "evaluation.h"

namespace {

using namespace hobsharp;

constexpr int kMaxEvaluatedGridPoints = 32 * 32;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_case: %s\n", what.c_str());
  std::abort();
}

bool validUtf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += n;
  }
  return true;
}

// The message starts with its field, or with the field in words (and then without its path).
bool namesItsField(const Error& e) {
  if (e.message.rfind(e.field + ": ", 0) == 0) return true;
  for (const char* words : {"Measured point", "Measured grid", "Pass ", "Gash ", "Wheel file"})
    if (e.message.rfind(words, 0) == 0) return e.message.find(e.field) == std::string::npos;
  return false;
}

void checkRefusal(const Error& e) {
  if (e.field.empty()) finding("a refusal names no field: " + e.message);
  if (!namesItsField(e)) finding("the message names its field neither by its path nor in words: " + e.message);
  if (e.message.size() > 4096) finding("a message of " + std::to_string(e.message.size()) + " bytes");
  if (!validUtf8(e.message)) finding("a message that is not UTF-8: " + e.message);
}

void finite(double v, const char* what) {
  if (!std::isfinite(v)) finding(std::string("an accepted case gives a non-finite ") + what);
}
template <class Values>
void finiteAll(const Values& values, const char* what) {
  for (double v : values) finite(v, what);
}
void finiteMatrix(const Eigen::MatrixXd& m, const char* what) {
  if (!m.allFinite()) finding(std::string("an accepted case gives a non-finite ") + what);
}
void finiteAxes(const AxisPolynomials& axes, const char* what) {
  for (Axis a : kAxes) finiteAll(axes[a].a, what);
}
void finiteTopography(const Topography& t, const char* what) {
  finiteAll(t.grid.r, what);
  finiteAll(t.grid.x, what);
  finiteMatrix(t.normal, what);
  finiteMatrix(t.circular, what);
  finite(t.thickness, what);
  finite(t.sse, what);
  finite(t.max, what);
}

// Everything the result carries to a table or a plot.
void checkResult(const Evaluation& e) {
  finiteAxes(e.job.nominalAxes, "nominal axis coefficient");
  finiteAxes(e.job.runAxes, "run axis coefficient");
  finite(e.job.rootRadius, "root radius");
  finite(e.job.wheelRadius, "wheel radius");
  finiteAll(e.job.wheelProfile.r, "wheel profile r");
  finiteAll(e.job.wheelProfile.w, "wheel profile contact coordinate");
  finiteAll(e.job.wheelProfile.R, "wheel profile R");
  finiteAll(e.job.wheelProfile.Z, "wheel profile Z");
  for (const EnvelopePoint& p : e.groundFace.envelope) finite(p.phi, "motion parameter");
  finiteTopography(e.topography, "topography");
  finiteMatrix(e.sensitivities.normal, "sensitivity");
  finiteMatrix(e.sensitivities.thickness, "thickness sensitivity");
  if (e.correction) {
    const Correction& c = *e.correction;
    finiteAxes(c.axes, "corrected axis coefficient");
    finiteMatrix(c.change, "coefficient change");
    finiteTopography(c.before, "measured topography");
    finiteTopography(c.after, "predicted residual");
    finiteMatrix(c.singularValues, "singular value");
    finite(c.uncorrectableShare, "uncorrectable share");
    for (const UnobservableCombination& u : c.unobservable) finiteAll(u.amounts, "unobservable combination");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto in = parseCase(text);
  if (!in) return checkRefusal(in.error()), 0;
  auto job = resolveJob(*in);
  if (!job) return checkRefusal(job.error()), 0;
  // A grid over 32 x 32 points runs the same per-point code, only longer (201 x 201 takes ~20 s
  // under the sanitizers, and would end the run as a timeout): read and resolved, not evaluated.
  if (job->grid.rows() * job->grid.cols() > kMaxEvaluatedGridPoints) return 0;
  auto e = evaluate(*job);
  if (!e) return checkRefusal(e.error()), 0;
  checkResult(*e);
  return 0;
}
