#include "calibration.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>
#include <thread>
#include <tuple>
#include <utility>

#include "evaluation.h"
#include "face_vectors.h"
#include "sensitivity_matrix.h"
#include "machine_resolution.h"
#include "number_text.h"
#include "ground_face.h"
#include "scenario.h"
#include "sharpening_job.h"
#include "topography.h"

namespace hobsharp::validation {
namespace {

const char* unitOf(Axis a) { return a == Axis::A || a == Axis::B ? "µrad" : "µm"; }

// The scenario index of hob h: the noisy class (10 µm rms), index mod 6 = 4.
int scenarioIndex(int h) { return kScenarioClasses * h + static_cast<int>(ScenarioClass::Noisy); }

std::string axesText(const std::vector<Axis>& axes) {
  std::string s;
  for (Axis a : axes) s += (s.empty() ? "" : ", ") + std::string(axisName(a));
  return s;
}

// Where an axis curve is sampled for its spread over the measurements: this many points over the
// motion range, ends included.
constexpr int kCurveSamples = 7;

// The mean of xs and their standard deviation (n - 1); xs has at least 2 values.
std::pair<double, double> meanAndSpread(const std::vector<double>& xs) {
  const double n = static_cast<double>(xs.size());
  double mean = 0, ss = 0;
  for (double x : xs) mean += x / n;
  for (double x : xs) ss += (x - mean) * (x - mean);
  return {mean, std::sqrt(ss / (n - 1))};
}

// The root mean square of xs.
double rms(const std::vector<double>& xs) {
  double s = 0;
  for (double x : xs) s += x * x;
  return xs.empty() ? 0.0 : std::sqrt(s / static_cast<double>(xs.size()));
}

// The value at share p of values sorted ascending (nearest rank).
double quantile(const std::vector<double>& sorted, double p) {
  return sorted[static_cast<size_t>(std::lround(p * static_cast<double>(sorted.size() - 1)))];
}

struct Sample {
  std::string unit;
  std::vector<double> values, given, secondOrder;
};

// The values one evaluation reads, each with its standard uncertainty (µm or µrad).
void collect(const IdentifiedAxes& id, double sigma, std::map<std::string, Sample>& into) {
  const auto add = [&](const std::string& what, const char* unit, double value, double perNoise, double secondOrder) {
    Sample& s = into[what];
    s.unit = unit;
    s.values.push_back(value);
    s.given.push_back(perNoise * sigma);
    s.secondOrder.push_back(secondOrder);
  };
  for (Axis a : kAxes) {
    const AxisIdentification& r = id.axes[static_cast<size_t>(a)];
    if (r.reading == AxisReading::Alone)
      add(std::string(axisName(a)) + " alone", unitOf(a), r.value, r.perNoise, r.secondOrder);
  }
  for (const AxisCombination& c : id.combinations) {
    if (c.axes.empty()) continue;
    const std::string group = axesText(c.axes);
    add(std::string(axisName(c.axes[0])) + "-equivalent of " + group, unitOf(c.axes[0]), c.value, c.perNoise,
        c.secondOrder);
    // The other members' values alone, where the sentence gives them.
    for (size_t m = 1; m < c.axes.size() && m < c.aloneListed.size(); ++m)
      if (c.aloneListed[m])
        add(std::string(axisName(c.axes[m])) + " alone of " + group, unitOf(c.axes[m]), c.aloneValue[m],
            c.alonePerNoise[m], m < c.aloneSecondOrder.size() ? c.aloneSecondOrder[m] : 0.0);
  }
}

}  // namespace

int Calibration::withTruth() const {
  return static_cast<int>(std::count_if(values.begin(), values.end(), [](const CalibratedValue& v) { return v.hasTruth; }));
}

int Calibration::nearTruth() const {
  return static_cast<int>(std::count_if(values.begin(), values.end(), [&](const CalibratedValue& v) {
    return v.hasTruth && v.miss() <= options.truthWithin;
  }));
}

int Calibration::nearTruthStated() const {
  return static_cast<int>(std::count_if(values.begin(), values.end(),
                                        [&](const CalibratedValue& v) { return v.withinStated(options.truthWithin); }));
}

int Calibration::draws() const {
  int n = 0;
  for (const CalibratedValue& v : values) n += v.hasTruth ? v.read : 0;
  return n;
}

int Calibration::drawsNearTruth() const {
  int n = 0;
  for (const CalibratedValue& v : values) n += v.hasTruth ? v.drawsNearTruth : 0;
  return n;
}

int Calibration::axisSpreadsWithin() const {
  return static_cast<int>(std::count_if(axisSpreads.begin(), axisSpreads.end(), [&](const AxisSpread& a) {
    return a.ratio() >= options.low && a.ratio() <= options.high;
  }));
}

int Calibration::figureOver(double factor) const {
  return static_cast<int>(std::count_if(axisSpreads.begin(), axisSpreads.end(),
                                        [&](const AxisSpread& a) { return a.figureOver(factor); }));
}

int Calibration::figureUnder(double share) const {
  return static_cast<int>(std::count_if(axisSpreads.begin(), axisSpreads.end(),
                                        [&](const AxisSpread& a) { return a.figureUnder(share); }));
}

int Calibration::bootstrapMoved() const {
  return static_cast<int>(
      std::count_if(axisSpreads.begin(), axisSpreads.end(), [](const AxisSpread& a) { return a.bootstrap > 0; }));
}

int Calibration::bootstrapWithin() const {
  return static_cast<int>(std::count_if(axisSpreads.begin(), axisSpreads.end(), [&](const AxisSpread& a) {
    return a.bootstrap > 0 && a.bootstrapRatio() >= options.low && a.bootstrapRatio() <= options.high;
  }));
}

int Calibration::bootstrapUnder(double factor) const {
  return static_cast<int>(std::count_if(axisSpreads.begin(), axisSpreads.end(),
                                        [&](const AxisSpread& a) { return a.bootstrapRatio() > factor; }));
}

int Calibration::within() const {
  return static_cast<int>(std::count_if(values.begin(), values.end(), [&](const CalibratedValue& v) {
    return v.ratio() >= options.low && v.ratio() <= options.high;
  }));
}

Calibration runCalibration(const CalibrationOptions& o, unsigned threads) {
  const auto start = std::chrono::steady_clock::now();
  Calibration out;
  out.options = o;
  std::mutex lock;
  std::atomic<int> next{0};
  const auto one = [&](int h) {
    const int index = scenarioIndex(h);
    auto s = makeScenario(o.seed, index);
    AxisPolynomials error;
    if (s) {
      error = s->error;
      for (Axis a : kAxes)
        for (size_t k = 0; k < error[a].a.size(); ++k) error[a].a[k] *= k > 0 && o.offsetsOnly ? 0.0 : o.errorScale;
    }
    auto job = s ? resolveJob(s->input) : Outcome<SharpeningJob>(s.error());
    auto ground = job ? simulateGroundFace(job->setup, plusError(job->nominalAxes, error), job->grid,
                                           Sensitivities::Skip)
                      : Outcome<GroundFace>(job.error());
    auto nominal = ground ? simulateGroundFace(job->setup, job->nominalAxes, job->grid, Sensitivities::Compute)
                          : Outcome<GroundFace>(ground.error());
    if (!ground || !nominal) {
      std::lock_guard<std::mutex> g(lock);
      ++out.hobsFailed;
      return;
    }
    const Eigen::MatrixXd face = topographyOf(*ground).normal;
    std::mt19937_64 noise(o.seed * 0xD1B54A32D192ED03ull + static_cast<std::uint64_t>(index) + 11);
    std::normal_distribution<double> gauss(0, 1);
    std::map<std::string, Sample> samples, truths;
    {
      // The true error's face to first order: the nominal face plus its sensitivities times the
      // error's coefficients; read without noise (the probe noise declared as in the measurements).
      std::vector<Coefficient> cs;
      std::vector<double> e;
      for (Axis a : kAxes)
        for (size_t k = 0; k < error[a].a.size(); ++k) cs.push_back(Coefficient{a, static_cast<int>(k)}), e.push_back(error[a].a[k]);
      const Eigen::MatrixXd S = sensitivityMatrix(*nominal, cs).normal;
      CaseInput c = s->input;
      c.axes = job->nominalAxes;
      c.measured = topographyOf(*nominal).normal +
                   gridOf(S * Eigen::Map<const Eigen::VectorXd>(e.data(), static_cast<Eigen::Index>(e.size())),
                          static_cast<int>(face.rows()), static_cast<int>(face.cols()));
      c.correction.probeNoise = o.sigma;
      auto j = resolveJob(c);
      auto t = j ? evaluate(*j) : Outcome<Evaluation>(j.error());
      if (t && t->correction) collect(t->correction->identified, o.sigma, truths);
    }
    int evaluations = 0, refused = 0;
    // Per measurement, each axis's identified error at the curve's samples and correction.uncertainty,
    // over the run face's motion range, as the correction's own figures.
    const MotionRange range = motionRange(*nominal);
    std::array<std::array<std::vector<double>, kCurveSamples>, kAxisCount> curves;
    std::array<std::vector<double>, kAxisCount> uncertainties;
    // Each axis's identified error at the curve's samples, in display units.
    const auto sampleCurves = [&](const AxisPolynomials& identified, auto& into) {
      for (Axis a : kAxes)
        for (int t = 0; t < kCurveSamples; ++t)
          into[static_cast<size_t>(a)][static_cast<size_t>(t)].push_back(
              identified[a].at(range.min + (range.max - range.min) * t / (kCurveSamples - 1)).value * displayFactor(a));
    };
    // `groundNormal` (µm) measured with fresh noise from `rng` after the nominal axes, evaluated as the page does.
    const auto measure = [&](const Eigen::MatrixXd& groundNormal, std::mt19937_64& rng) {
      CaseInput c = s->input;
      c.axes = job->nominalAxes;
      Eigen::MatrixXd measured = groundNormal;
      for (int i = 0; i < measured.size(); ++i) measured.data()[i] += o.sigma * gauss(rng);
      c.measured = measured;
      c.correction.probeNoise = o.sigma;
      auto j = resolveJob(c);
      return j ? evaluate(*j) : Outcome<Evaluation>(j.error());
    };
    std::optional<AxisPolynomials> first;  // the first measurement's identified error, for the bootstrap
    for (int k = 0; k < o.measurements; ++k) {
      ++evaluations;
      auto e = measure(face, noise);
      if (!e || !e->correction) {
        ++refused;
        continue;
      }
      collect(e->correction->identified, o.sigma, samples);
      sampleCurves(e->correction->identifiedError, curves);
      for (Axis a : kAxes) uncertainties[static_cast<size_t>(a)].push_back(e->correction->uncertainty[static_cast<size_t>(a)]);
      if (!first) first = e->correction->identifiedError;
    }
    // The bootstrap of the first measurement: the face its identified error grinds, measured again
    // with fresh noise and identified again (CalibrationOptions::bootstrapDraws).
    std::array<std::array<std::vector<double>, kCurveSamples>, kAxisCount> bootstrapCurves;
    const auto modelFace = first && o.bootstrapDraws > 0
                               ? simulateGroundFace(job->setup, plusError(job->nominalAxes, *first), job->grid,
                                                    Sensitivities::Skip)
                               : Outcome<GroundFace>(Error{});
    if (modelFace) {
      const Eigen::MatrixXd base = topographyOf(*modelFace).normal;
      std::mt19937_64 again(o.seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(index) + 29);
      for (int b = 0; b < o.bootstrapDraws; ++b) {
        auto e = measure(base, again);
        if (e && e->correction) sampleCurves(e->correction->identifiedError, bootstrapCurves);
      }
    }
    std::vector<AxisSpread> spreads;
    for (Axis axis : kAxes) {
      const size_t i = static_cast<size_t>(axis);
      if (uncertainties[i].size() < 3) break;
      AxisSpread a;
      a.hob = index, a.axis = axisName(axis), a.unit = unitOf(axis);
      for (const std::vector<double>& atSample : curves[i]) a.spread = std::max(a.spread, meanAndSpread(atSample).second);
      a.given = rms(uncertainties[i]);
      if (bootstrapCurves[i][0].size() >= 3)
        for (const std::vector<double>& atSample : bootstrapCurves[i])
          a.bootstrap = std::max(a.bootstrap, meanAndSpread(atSample).second);
      if (a.spread > 0) spreads.push_back(a);  // an axis the identification never moves is not judged
    }
    std::vector<CalibratedValue> judged, rare;
    int unstable = 0;
    for (const auto& [what, sample] : samples) {
      const int n = static_cast<int>(sample.values.size());
      if (n < 3 || n < o.leastShareRead * o.measurements) {
        ++unstable;
        CalibratedValue u;
        u.hob = index, u.what = what, u.unit = sample.unit, u.read = n;
        rare.push_back(u);
        continue;
      }
      CalibratedValue v;
      v.hob = index;
      v.what = what;
      v.unit = sample.unit;
      v.read = n;
      std::tie(v.mean, v.spread) = meanAndSpread(sample.values);
      v.given = rms(sample.given);
      const auto t = truths.find(what);
      v.hasTruth = t != truths.end();
      v.truth = v.hasTruth ? t->second.values.front() : 0.0;
      for (int i = 0; i < n; ++i) {
        const double so = sample.secondOrder[static_cast<size_t>(i)];
        v.secondOrder += so / n;
        if (v.hasTruth && std::abs(sample.values[static_cast<size_t>(i)] - v.truth) <=
                              o.truthWithin * sample.given[static_cast<size_t>(i)] + so)
          ++v.drawsNearTruth;
      }
      judged.push_back(v);
    }
    std::lock_guard<std::mutex> g(lock);
    ++out.hobsRun;
    out.evaluations += evaluations;
    out.refused += refused;
    out.unstable += unstable;
    out.values.insert(out.values.end(), judged.begin(), judged.end());
    out.unstableValues.insert(out.unstableValues.end(), rare.begin(), rare.end());
    out.axisSpreads.insert(out.axisSpreads.end(), spreads.begin(), spreads.end());
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(1u, threads); ++t)
    pool.emplace_back([&] {
      for (int h = next++; h < o.hobs; h = next++) one(o.firstHob + h);
    });
  for (std::thread& t : pool) t.join();
  std::sort(out.axisSpreads.begin(), out.axisSpreads.end(),
            [](const AxisSpread& a, const AxisSpread& b) { return a.hob != b.hob ? a.hob < b.hob : a.axis < b.axis; });
  std::sort(out.values.begin(), out.values.end(),
            [](const CalibratedValue& a, const CalibratedValue& b) { return a.hob != b.hob ? a.hob < b.hob : a.what < b.what; });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

nlohmann::json toJson(const Calibration& c) {
  nlohmann::json j;
  j["seed"] = c.options.seed;
  j["hobs"] = c.options.hobs;
  j["measurements"] = c.options.measurements;
  j["sigma"] = c.options.sigma;
  j["unit"] = "ratio: spread over the measurements / standard uncertainty given";
  j["asked"] = {c.options.low, c.options.high};
  j["hobsRun"] = c.hobsRun;
  j["hobsFailed"] = c.hobsFailed;
  j["evaluations"] = c.evaluations;
  j["refused"] = c.refused;
  j["unstable"] = c.unstable;
  j["within"] = c.within();
  j["judged"] = c.values.size();
  j["errorScale"] = c.options.errorScale;
  j["truthWithin"] = c.options.truthWithin;
  j["withTruth"] = c.withTruth();
  j["nearTruth"] = c.nearTruth();
  j["nearTruthStated"] = c.nearTruthStated();
  j["draws"] = c.draws();
  j["drawsNearTruth"] = c.drawsNearTruth();
  j["seconds"] = c.seconds;
  for (const CalibratedValue& v : c.unstableValues)
    j["unstableValues"].push_back({{"hob", v.hob}, {"what", v.what}, {"read", v.read}});
  for (const CalibratedValue& v : c.values)
    j["values"].push_back({{"hob", v.hob}, {"what", v.what}, {"unit", v.unit}, {"read", v.read}, {"mean", v.mean},
                           {"spread", v.spread}, {"given", v.given}, {"ratio", v.ratio()}});
  for (size_t i = 0; i < c.values.size(); ++i)
    if (c.values[i].hasTruth) {
      j["values"][i]["truth"] = c.values[i].truth;
      j["values"][i]["miss"] = c.values[i].miss();
      j["values"][i]["secondOrder"] = c.values[i].secondOrder;
      j["values"][i]["drawsNearTruth"] = c.values[i].drawsNearTruth;
    }
  for (const AxisSpread& a : c.axisSpreads)
    j["axisSpreads"].push_back({{"hob", a.hob}, {"axis", a.axis}, {"unit", a.unit}, {"spread", a.spread},
                                {"given", a.given}, {"ratio", a.ratio()}});
  if (c.options.bootstrapDraws > 0) {
    j["bootstrapDraws"] = c.options.bootstrapDraws;
    for (size_t i = 0; i < c.axisSpreads.size(); ++i) {
      j["axisSpreads"][i]["bootstrap"] = c.axisSpreads[i].bootstrap;
      j["axisSpreads"][i]["bootstrapRatio"] = c.axisSpreads[i].bootstrapRatio();
    }
  }
  j["axisSpreadsWithin"] = c.axisSpreadsWithin();
  j["axisFigureTenTimesOrMore"] = c.figureOver(10);
  j["axisFigureBelowHalf"] = c.figureUnder(0.5);
  return j;
}

std::string calibrationText(const Calibration& c) {
  std::ostringstream s;
  s.precision(3);
  const int n = static_cast<int>(c.values.size());
  s << "Calibration of the values read (seed " << c.options.seed << ", " << c.hobsRun << " random hobs of the noisy class, "
    << (c.options.errorScale != 1 ? "error times " + numberText(c.options.errorScale, 3) + ", " : std::string())
    << c.options.measurements << " measurements each, probe noise " << c.options.sigma << " µm; " << c.evaluations
    << " evaluations, " << c.refused << " refused; " << c.hobsFailed << " hobs not run)\n";
  s << "  " << c.within() << " of " << n << " values read ("
    << (n > 0 ? 100.0 * c.within() / n : 0.0) << " %) have a spread " << c.options.low << " to " << c.options.high
    << " times the uncertainty given; " << c.unstable << " more were read in fewer than "
    << static_cast<int>(std::ceil(c.options.leastShareRead * c.options.measurements)) << " of the measurements\n";
  s << "  " << c.nearTruth() << " of " << c.withTruth() << " values read from the true error's first-order face too lie, on average "
    << "over the measurements, within " << c.options.truthWithin << " uncertainties of that; "
    << c.nearTruthStated() << " within " << c.options.truthWithin
    << " uncertainties plus the second-order figure stated with them (of their measurements, "
    << c.drawsNearTruth() << " of " << c.draws() << ")\n";
  std::vector<double> r;
  for (const CalibratedValue& v : c.values) r.push_back(v.ratio());
  std::sort(r.begin(), r.end());
  if (!r.empty()) {
    s << "  ratio: lowest " << r.front() << ", 5th " << quantile(r, 0.05) << ", median " << quantile(r, 0.5) << ", 95th "
      << quantile(r, 0.95) << ", highest " << r.back() << "\n";
  }
  if (!c.axisSpreads.empty()) {
    std::vector<double> a;
    for (const AxisSpread& x : c.axisSpreads) a.push_back(x.ratio());
    std::sort(a.begin(), a.end());
    s << "  correction.uncertainty against the identified error's spread over the measurements, " << a.size()
      << " axes moved: " << c.axisSpreadsWithin() << " within " << c.options.low << " to " << c.options.high << ", "
      << c.figureOver(10) << " more than 10 times the spread, " << c.figureUnder(0.5)
      << " less than half of it; ratio (spread / given) lowest " << a.front() << ", median " << quantile(a, 0.5)
      << ", highest " << a.back() << "\n";
    if (c.options.bootstrapDraws > 0) {
      // The bootstrap's spread against the spread over the measurements.
      std::vector<double> b;
      for (const AxisSpread& x : c.axisSpreads)
        if (x.bootstrap > 0) b.push_back(x.bootstrapRatio());
      std::sort(b.begin(), b.end());
      s << "  a bootstrap of each hob's first measurement (" << c.options.bootstrapDraws
        << " draws) against the identified error's spread over the measurements, " << c.axisSpreads.size()
        << " axes moved: " << c.bootstrapWithin() << " within " << c.options.low << " to " << c.options.high << ", "
        << c.bootstrapUnder(2) << " spread more than twice the bootstrap's figure, "
        << c.axisSpreads.size() - static_cast<size_t>(c.bootstrapMoved()) << " never moved by the bootstrap";
      if (!b.empty()) s << "; ratio (spread / bootstrap) lowest " << b.front() << ", median " << quantile(b, 0.5) << ", 90th "
                        << quantile(b, 0.9) << ", highest " << b.back();
      s << "\n";
    }
    for (const AxisSpread& x : c.axisSpreads)
      if (x.figureUnder(0.5))
        s << "  uncertainty below the spread: scenario " << x.hob << ", " << x.axis << ": spread " << x.spread << " "
          << x.unit << ", given " << x.given << " " << x.unit << " (ratio " << x.ratio() << ")\n";
  }
  for (const CalibratedValue& v : c.values)
    if (v.ratio() < c.options.low || v.ratio() > c.options.high)
      s << "  outside: scenario " << v.hob << ", " << v.what << ": spread " << v.spread << " " << v.unit << ", given "
        << v.given << " " << v.unit << " (ratio " << v.ratio() << ", read " << v.read << " times, mean " << v.mean
        << " " << v.unit << ")\n";
  for (const CalibratedValue& v : c.values)
    if (v.hasTruth && v.miss() > c.options.truthWithin)
      s << "  far from the truth: scenario " << v.hob << ", " << v.what << ": mean " << v.mean << " " << v.unit
        << ", true " << v.truth << " " << v.unit << ", given " << v.given << " " << v.unit << " (" << v.miss()
        << " uncertainties), second order up to " << v.secondOrder << " " << v.unit
        << (v.withinStated(c.options.truthWithin) ? "" : ": BEYOND IT") << "\n";
  return s.str();
}

}  // namespace hobsharp::validation
