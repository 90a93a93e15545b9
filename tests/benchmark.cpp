// The benchmark command: the paper's correction cycle (and on 51 x 26 at degree 6, and with the wheel-profile correction), its rake-face inspection, the sensitivity matrix by the implicit
// function theorem against the paper's central differences, and a dense topography.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

#include <benchmark/benchmark.h>

#include "case_json.h"
#include "evaluation.h"
#include "wheel_input.h"
#include <fstream>
#include <sstream>

namespace hobsharp {
namespace {

std::string paperCaseText() {
  std::ifstream f(std::string(HOBSHARP_TEST_DATA) + "/tab1.json");
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

CaseInput paperInput(int radial, int axial, int degree = 4) {
  CaseInput in = parseCase(paperCaseText()).value();
  in.grid.radial = radial;
  in.grid.axial = axial;
  in.degree = degree;
  return in;
}

SharpeningJob paperJob(int radial, int axial, int degree = 4) { return resolveJob(paperInput(radial, axial, degree)).value(); }

// A machine error of the paper's size, measured on the grid.
Eigen::MatrixXd measuredFor(const SharpeningJob& job) {
  AxisPolynomials e = job.nominalAxes;
  e[Axis::Y].a[0] += 0.01;
  e[Axis::Z].a[0] -= 0.01;
  e[Axis::Z].a[1] += 0.003;
  e[Axis::A].a[0] += 0.0002;
  e[Axis::B].a[2] += 0.001;
  return topographyOf(simulateGroundFace(job.setup, e, job.grid).value()).normal;
}

// Profile + topography + sensitivity (25 coefficients) + the default correction (nonlinear
// identification of the machine error, rounded axes, re-simulated faces), for Tab. 1 on 9 x 5.
void CorrectionCycle(benchmark::State& state) {
  SharpeningJob job = paperJob(5, 9);
  job.measured = MeasuredFace::onGrid(measuredFor(job));
  for (auto _ : state) {
    auto e = evaluate(job);
    if (!e) state.SkipWithError(e.error().message.c_str());
    benchmark::DoNotOptimize(e);
  }
}

// The same on a 51 x 26 grid (51 along the gash, 26 radially) with degree-6 axes (35 coefficients).
void CorrectionCycle51x26Degree6(benchmark::State& state) {
  SharpeningJob job = paperJob(26, 51, 6);
  job.measured = MeasuredFace::onGrid(measuredFor(job));
  for (auto _ : state) {
    auto e = evaluate(job);
    if (!e) state.SkipWithError(e.error().message.c_str());
    benchmark::DoNotOptimize(e);
  }
}

void SensitivityAnalytic(benchmark::State& state) {
  const SharpeningJob job = paperJob(5, 9);
  const std::vector<Coefficient> all = allCoefficients(4);
  for (auto _ : state) {
    const GroundFace f = simulateGroundFace(job.setup, job.nominalAxes, job.grid).value();
    benchmark::DoNotOptimize(sensitivityMatrix(f, all));
  }
}

// The paper's method: 2 x 25 + 1 full topographies.
void SensitivityCentralDifferences(benchmark::State& state) {
  const SharpeningJob job = paperJob(5, 9);
  const std::vector<Coefficient> all = allCoefficients(4);
  for (auto _ : state) {
    Eigen::MatrixXd S(job.grid.size(), static_cast<int>(all.size()));
    const Topography base = topographyOf(simulateGroundFace(job.setup, job.nominalAxes, job.grid).value());
    benchmark::DoNotOptimize(base);
    for (size_t j = 0; j < all.size(); ++j) {
      const double h = 1e-5;
      AxisPolynomials plus = job.nominalAxes, minus = job.nominalAxes;
      plus[all[j].axis].a[all[j].degree] += h;
      minus[all[j].axis].a[all[j].degree] -= h;
      const Eigen::MatrixXd d = topographyOf(simulateGroundFace(job.setup, plus, job.grid).value()).normal -
                                topographyOf(simulateGroundFace(job.setup, minus, job.grid).value()).normal;
      S.col(static_cast<int>(j)) = Eigen::Map<const Eigen::VectorXd>(d.data(), d.size()) / (2 * h);
    }
    benchmark::DoNotOptimize(S);
  }
}

// A dense 101 x 101 topography of a ground face with a machine error.
void DenseTopography101(benchmark::State& state) {
  const SharpeningJob job = paperJob(101, 101);
  AxisPolynomials e = job.nominalAxes;
  e[Axis::Z].a[0] -= 0.01;
  e[Axis::B].a[2] += 0.001;
  for (auto _ : state) {
    auto f = simulateGroundFace(job.setup, e, job.grid, Sensitivities::Skip);
    if (!f) state.SkipWithError(f.error().message.c_str());
    benchmark::DoNotOptimize(topographyOf(f.value()));
  }
}

// The rake-face inspection of the paper's case (docs/inspection.md): the measured face's
// checks, 12 gashes' spacing and indexing correction, the class verdict, and the same after the correction.
void InspectionPaperCase(benchmark::State& state) {
  CaseInput in = paperInput(5, 9);
  in.inspection.gashDeviations = {0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1};
  SharpeningJob job = resolveJob(in).value();
  job.measured = MeasuredFace::onGrid(measuredFor(job));
  auto evaluated = evaluate(job);
  if (!evaluated) {
    state.SkipWithError(evaluated.error().message.c_str());
    return;
  }
  Evaluation e = std::move(evaluated).value();
  for (auto _ : state) {
    inspectEvaluation(e);
    benchmark::DoNotOptimize(e.inspection);
  }
}

// Reading and correcting a 2,000-point measurement (docs/measured-points.md): the points CSV
// tests/data/points-2000.csv read (a plain reader here: the page's and the CLI's reader is
// wasm/lib/points-csv.js, timed in the wasm benchmark), the job resolved, and evaluated: the
// face simulated at the points, the default correction, the grid views re-simulated.
std::vector<MeasuredPoint> readPointsCsv(const std::string& text) {
  std::vector<MeasuredPoint> out;
  const char* p = text.c_str();
  p = std::strchr(p, '\n');  // the header
  while (p && *++p) {
    char* end = nullptr;
    MeasuredPoint m;
    m.r = std::strtod(p, &end);
    m.x = std::strtod(end + 1, &end);
    m.deviation = std::strtod(end + 1, &end);
    out.push_back(m);
    p = std::strchr(end, '\n');
  }
  return out;
}

void CorrectPoints2000(benchmark::State& state) {
  std::ifstream f(std::string(HOBSHARP_TEST_DATA) + "/points-2000.csv");
  std::stringstream s;
  s << f.rdbuf();
  const std::string csv = s.str();
  const CaseInput paper = parseCase(paperCaseText()).value();
  for (auto _ : state) {
    CaseInput in = paper;
    in.measuredPoints = readPointsCsv(csv);
    auto job = resolveJob(in);
    if (!job) { state.SkipWithError(job.error().message.c_str()); break; }
    auto e = evaluate(*job);
    if (!e) { state.SkipWithError(e.error().message.c_str()); break; }
    benchmark::DoNotOptimize(e);
  }
}

// The wheel-profile correction (docs/method.md §Wheel-profile correction): the cycle of CorrectionCycle
// with `correction.wheel` on, the measured face ground by a wheel 10 µm out of profile (a
// second-degree shape along the radius) with the benchmark's machine error.
void WheelCorrectionCycle(benchmark::State& state) {
  SharpeningJob job = paperJob(5, 9);
  CaseInput worn = paperInput(5, 9);
  const ContactRange range = wheelContactRange(job.setup, job.rootRadius, job.outerRadius).value();
  worn.wheelProfileOffset = WheelPointsInput{};
  for (int k = 0; k <= 8; ++k) {
    const double z = k / 4.0 - 1;  // -1 .. 1 over the contact range
    worn.wheelProfileOffset->R.push_back(range.min + (range.max - range.min) * k / 8);
    worn.wheelProfileOffset->values.push_back(10 * z * z - 5);
  }
  job.measured = MeasuredFace::onGrid(measuredFor(resolveJob(worn).value()));
  job.correction.wheel = true;
  for (auto _ : state) {
    auto e = evaluate(job);
    if (!e) state.SkipWithError(e.error().message.c_str());
    benchmark::DoNotOptimize(e);
  }
}

// The inspection and the gear effect of the paper's case (docs/gear-effect.md): the
// above, then the cutting edges of 5 teeth x 2 flanks x 21 radii on the measured face, with a
// relief of 4.5 mm over 12 gashes.
void InspectionAndGearEffectPaperCase(benchmark::State& state) {
  CaseInput in = paperInput(5, 9);
  in.inspection.gashDeviations = {0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1};
  in.hob.relief.gashes = 12;
  in.hob.relief.relief = 4.5;
  SharpeningJob job = resolveJob(in).value();
  job.measured = MeasuredFace::onGrid(measuredFor(job));
  auto evaluated = evaluate(job);
  if (!evaluated || !evaluated->gearEffect) {
    state.SkipWithError(evaluated ? evaluated->gearEffectReason.c_str() : evaluated.error().message.c_str());
    return;
  }
  Evaluation e = std::move(evaluated).value();
  for (auto _ : state) {
    inspectEvaluation(e);
    gearEvaluation(e);
    benchmark::DoNotOptimize(e.gearEffect);
  }
}

BENCHMARK(CorrectionCycle)->Unit(benchmark::kMicrosecond);
BENCHMARK(CorrectPoints2000)->Unit(benchmark::kMillisecond);
BENCHMARK(WheelCorrectionCycle)->Unit(benchmark::kMicrosecond);
BENCHMARK(InspectionPaperCase)->Unit(benchmark::kMicrosecond);
BENCHMARK(InspectionAndGearEffectPaperCase)->Unit(benchmark::kMicrosecond);
BENCHMARK(CorrectionCycle51x26Degree6)->Unit(benchmark::kMillisecond);
BENCHMARK(SensitivityAnalytic)->Unit(benchmark::kMicrosecond);
BENCHMARK(SensitivityCentralDifferences)->Unit(benchmark::kMicrosecond);
BENCHMARK(DenseTopography101)->Unit(benchmark::kMillisecond);

// Keeps each benchmark's time per iteration for the ratio printed at the end.
class Recorder : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> seconds;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && !r.error_occurred)
        seconds[r.benchmark_name()] = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace
}  // namespace hobsharp

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  hobsharp::Recorder recorder;
  benchmark::RunSpecifiedBenchmarks(&recorder);
  auto& s = recorder.seconds;
  if (s.count("SensitivityAnalytic") && s.count("SensitivityCentralDifferences"))
    std::printf("\nsensitivity matrix, central differences / analytic: %.1fx (target >= 20x)\n",
                s["SensitivityCentralDifferences"] / s["SensitivityAnalytic"]);
  if (s.count("CorrectionCycle"))
    std::printf("correction cycle: %.3f ms (target < 1 ms)\n", 1e3 * s["CorrectionCycle"]);
  if (s.count("WheelCorrectionCycle"))
    std::printf("correction cycle with the wheel (correction.wheel): %.3f ms (target <= 2 ms)\n", 1e3 * s["WheelCorrectionCycle"]);
  if (s.count("CorrectionCycle51x26Degree6"))
    std::printf("correction cycle, 51 x 26, degree 6: %.2f ms (target < 50 ms)\n", 1e3 * s["CorrectionCycle51x26Degree6"]);
  if (s.count("CorrectPoints2000"))
    std::printf("reading and correcting 2,000 measured points: %.2f ms (target < 20 ms)\n", 1e3 * s["CorrectPoints2000"]);
  if (s.count("InspectionPaperCase"))
    std::printf("rake-face inspection of the paper case: %.4f ms (target < 5 ms)\n", 1e3 * s["InspectionPaperCase"]);
  if (s.count("InspectionAndGearEffectPaperCase"))
    std::printf("inspection and gear effect of the paper case: %.4f ms (target < 5 ms)\n",
                1e3 * s["InspectionAndGearEffectPaperCase"]);
  if (s.count("DenseTopography101"))
    std::printf("101 x 101 topography: %.2f ms (target < 15 ms)\n", 1e3 * s["DenseTopography101"]);
  benchmark::Shutdown();
  return 0;
}
