// ./hobsharp.sh validate [--scenarios N] [--seed S] [--out DIR]: the validation campaign
// (docs/validation.md). Runs N random scenarios (default 600) on every core, prints the table and
// writes DIR/validation.json and DIR/validation.md (the table the docs show). With --index I, runs
// scenario I of the seed alone and prints its record (the campaign JSON's outcome) to standard
// output, writing nothing: how a scenario the docs quote is reproduced.
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "calibration.h"
#include "case_file.h"
#include "campaign.h"

using namespace hobsharp::validation;

int main(int argc, char** argv) {
  int count = 600;  // 100 per class
  std::uint64_t seed = 20261125;
  std::string out = "build/validation";
  int index = -1;
  bool calibration = false;
  bool signReversed = false;  // every face measured with the other sign (run_scenario.h)
  std::string cases;  // --cases DIR: with --index, each pass's case file written there
  int hobs = CalibrationOptions{}.hobs;
  double errorScale = 1;
  bool offsetsOnly = false;
  int bootstrap = 0;  // --bootstrap B: with --calibration, B draws of each hob's first measurement
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--scenarios" && hasValue) count = std::atoi(argv[++i]);
    else if (a == "--seed" && hasValue) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--out" && hasValue) out = argv[++i];
    else if (a == "--index" && hasValue) index = std::atoi(argv[++i]);
    else if (a == "--calibration") calibration = true;
    else if (a == "--sign-reversed") signReversed = true;
    else if (a == "--cases" && hasValue) cases = argv[++i];
    else if (a == "--hobs" && hasValue) hobs = std::atoi(argv[++i]);
    else if (a == "--error-scale" && hasValue) errorScale = std::atof(argv[++i]);
    else if (a == "--offsets-only") offsetsOnly = true;
    else if (a == "--bootstrap" && hasValue) bootstrap = std::atoi(argv[++i]);
    else if (a == "--threads" && hasValue) threads = static_cast<unsigned>(std::max(1, std::atoi(argv[++i])));
    else {
      std::cerr << "usage: validate [--scenarios N] [--seed S] [--out DIR] [--threads T] [--sign-reversed] [--index I [--cases DIR]]\n"
                   "       validate --calibration [--hobs H] [--error-scale K] [--offsets-only] [--bootstrap B] [--seed S] [--out DIR] [--threads T]\n";
      return 2;
    }
  }
  if (count < 1) {
    std::cerr << "validate: --scenarios must be at least 1\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  if (calibration) {
    CalibrationOptions o;
    o.seed = seed;
    o.hobs = std::max(1, hobs);
    if (errorScale > 0) o.errorScale = errorScale;
    o.offsetsOnly = offsetsOnly;
    o.bootstrapDraws = std::max(0, bootstrap);
    const Calibration c = runCalibration(o, threads);
    std::cout << calibrationText(c);
    std::filesystem::create_directories(out);
    std::ofstream(out + "/calibration.json") << toJson(c).dump(1) << "\n";
    std::cout << "\nWritten: " << out << "/calibration.json\n";
    return 0;
  }
  if (index >= 0) {
    auto s = makeScenario(seed, index);
    if (!s) {
      std::cerr << "validate: scenario " << index << " of seed " << seed << ": " << s.error().message << "\n";
      return 1;
    }
    std::vector<hobsharp::CaseInput> passCases;
    std::vector<ScenarioOutcome> one{runScenario(*s, cases.empty() ? nullptr : &passCases, signReversed)};
    if (!cases.empty()) {
      std::filesystem::create_directories(cases);
      for (size_t k = 0; k < passCases.size(); ++k) {
        const std::string file = cases + "/seed-" + std::to_string(seed) + "-scenario-" + std::to_string(index) +
                                 "-pass-" + std::to_string(k + 1) + ".json";
        std::ofstream(file) << caseFile(passCases[k]).dump(1) << "\n";
        std::cerr << "Written: " << file << "\n";
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << toJson(summarise(seed, std::move(one), seconds))["outcomes"][0].dump(1) << "\n";
    return 0;
  }
  std::vector<ScenarioOutcome> outcomes(static_cast<size_t>(count));
  std::atomic<int> next{0}, done{0};
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (int i = next++; i < count; i = next++) {
        auto s = makeScenario(seed, i);
        if (s) {
          outcomes[static_cast<size_t>(i)] = runScenario(*s, nullptr, signReversed);
        } else {
          ScenarioOutcome o;
          o.scenario.index = i;
          o.scenario.spec = specOf(static_cast<ScenarioClass>(i % kScenarioClasses));
          o.judged = false;
          o.message = s.error().message;
          outcomes[static_cast<size_t>(i)] = o;
        }
        const int d = ++done;
        if (d % 20 == 0 || d == count) std::cerr << "  " << d << " of " << count << " scenarios\n";
      }
    });
  for (std::thread& t : pool) t.join();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Campaign c = summarise(seed, std::move(outcomes), seconds);
  std::cout << tableText(c);
  std::filesystem::create_directories(out);
  std::ofstream(out + "/validation.json") << toJson(c).dump(1) << "\n";
  std::ofstream(out + "/validation.md") << markdownTable(c);
  std::cout << "\nWritten: " << out << "/validation.json, " << out << "/validation.md\n";
  return 0;
}
