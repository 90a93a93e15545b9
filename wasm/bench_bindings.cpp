// Benchmark hooks, linked only into the benchmark module hobsharp-bench.js (never into the page's
// module): the same C++ work as tests/benchmark.cpp, timed inside the module so that no JS
// marshaling is counted (tests/benchmark-wasm.mjs). Milliseconds per run, or -1 on bad input.
#include <string>
#include <utility>

#include <emscripten/bind.h>
#include <emscripten/emscripten.h>

#include "case_json.h"
#include "evaluation.h"

namespace hobsharp {
namespace {

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

// The rake-face inspection alone (inspectEvaluation), on the case evaluated once beforehand.
double timeInspection(const std::string& text, int runs) {
  auto in = parseCase(text);
  if (!in) return -1;
  auto job = resolveJob(*in);
  if (!job) return -1;
  auto e = evaluate(*job);
  if (!e) return -1;
  Evaluation evaluated = std::move(e).value();
  inspectEvaluation(evaluated);  // warm-up
  const double start = emscripten_get_now();
  for (int i = 0; i < runs; ++i) inspectEvaluation(evaluated);
  return (emscripten_get_now() - start) / runs;
}

// The inspection and the gear effect (inspectEvaluation, gearEvaluation), on the case evaluated once.
double timeInspectionAndGearEffect(const std::string& text, int runs) {
  auto in = parseCase(text);
  if (!in) return -1;
  auto job = resolveJob(*in);
  if (!job) return -1;
  auto e = evaluate(*job);
  if (!e || !e->gearEffect) return -1;
  Evaluation evaluated = std::move(e).value();
  const double start = emscripten_get_now();
  for (int i = 0; i < runs; ++i) {
    inspectEvaluation(evaluated);
    gearEvaluation(evaluated);
  }
  return (emscripten_get_now() - start) / runs;
}

}  // namespace
}  // namespace hobsharp

EMSCRIPTEN_BINDINGS(hobsharp_bench) {
  emscripten::function("timeCorrectionCycle", &hobsharp::timeCorrectionCycle);
  emscripten::function("timeTopography", &hobsharp::timeTopography);
  emscripten::function("timeInspection", &hobsharp::timeInspection);
  emscripten::function("timeInspectionAndGearEffect", &hobsharp::timeInspectionAndGearEffect);
}
