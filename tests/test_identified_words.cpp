// What the engineer reads about the machine (issue 20, item 5; identified_axes.h): the identified
// error by what the face can tell apart, and an uncertainty that is the spread the probe noise gives.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "face_vectors.h"
#include "identification_cases.h"
#include "identified_axes.h"
#include "machine_error.h"
#include "sensitivity_matrix.h"
#include "structural_null_space.h"
#include "result_model.h"

namespace hobsharp::test {
namespace {

// The correction of the face ground with nominal + error, measured with probe noise (seed).
Correction corrected(const SharpeningJob& job, const AxisPolynomials& error, const CorrectionOptions& o, unsigned seed) {
  const Eigen::MatrixXd measured = topographyFor(job, withMachineError(job.nominalAxes, error)).normal +
                                   probeNoise(job.grid.rows(), job.grid.cols(), o.probeNoise, seed);
  auto c = correctMeasuredFace(job.setup, job.nominalAxes, job.nominalAxes, groundFaceOf(job, job.nominalAxes), measured, o);
  EXPECT_TRUE(c.ok()) << (c.ok() ? "" : c.error().message);
  return c.value();
}

AxisPolynomials yOffset(const SharpeningJob& job, double mm) {
  AxisPolynomials e = times(job.nominalAxes, 0.0);
  e[Axis::Y].a[0] = mm;
  return e;
}

bool names(const std::string& sentence, Axis a) {
  const std::string n = axisName(a);
  return sentence.find(n + ",") != std::string::npos || sentence.find(n + " ") != std::string::npos ||
         sentence.find(n + ":") != std::string::npos;
}

// Three coefficients an axis, the sensitivities of 40 random points (µm per unit), each
// coefficient's machine step 1e-4: a face with nothing of the hob in it.
struct RandomSensitivities {
  std::vector<Coefficient> cs;
  Eigen::MatrixXd S;
  Eigen::VectorXd step;
};
RandomSensitivities randomSensitivities(unsigned seed) {
  RandomSensitivities r;
  for (Axis a : kAxes)
    for (int k = 0; k <= 2; ++k) r.cs.push_back(Coefficient{a, k});
  const int q = static_cast<int>(r.cs.size());
  std::srand(seed);
  r.S = Eigen::MatrixXd::Random(40, q) * 100;
  r.step = Eigen::VectorXd::Constant(q, 1e-4);
  return r;
}

// The face the job's hob is ground with a random error in the identifiable space (sum of squares
// 100 µm², seed errorSeed), measured with the options' probe noise (seed noiseSeed).
Eigen::MatrixXd measuredWithError(const SharpeningJob& job, const CorrectionOptions& o, unsigned errorSeed,
                                  unsigned noiseSeed) {
  return topographyFor(job, withMachineError(job.nominalAxes, inSpanError(job, 100, errorSeed))).normal +
         probeNoise(job.grid.rows(), job.grid.cols(), o.probeNoise, noiseSeed);
}

// A face of the job's hob measured with an in-span error and 0.5 µm of probe noise, at the nominal
// axes, and the machine error identified from it (empty, with a failure, if it is refused).
struct IdentifiedFace {
  CorrectionOptions o;
  Eigen::MatrixXd measured;
  GroundFace face;
  MachineErrorEstimate m;
};
std::optional<IdentifiedFace> identifiedFace(const SharpeningJob& job, unsigned errorSeed, unsigned noiseSeed) {
  IdentifiedFace f;
  f.o = job.correction;
  f.o.probeNoise = 0.5;
  f.measured = measuredWithError(job, f.o, errorSeed, noiseSeed);
  f.face = groundFaceOf(job, job.nominalAxes);
  auto est = identifyMachineError(job.setup, job.nominalAxes, f.face, f.measured, f.o);
  EXPECT_TRUE(est.ok()) << (est.ok() ? "" : est.error().message);
  if (!est.ok()) return std::nullopt;
  f.m = std::move(est).value();
  return f;
}

// (a) An injected Y a0 of +8 µm alone: the words name Y with what it is confounded with, Y is not
// read on its own, and no axis is read on its own with a value that was never injected.
void yAloneIsNamed(const char* hob, const SharpeningJob& job, double sigma) {
  SCOPED_TRACE(std::string(hob) + ", sigma " + std::to_string(sigma));
  CorrectionOptions o = job.correction;
  o.probeNoise = sigma;
  const Correction c = corrected(job, yOffset(job, 0.008), o, 1);
  const IdentifiedAxes& id = c.identified;
  const int Y = static_cast<int>(Axis::Y);
  EXPECT_NE(id.axes[Y].reading, AxisReading::Alone);
  const bool inCombination = std::any_of(id.combinations.begin(), id.combinations.end(), [](const AxisCombination& k) {
    return std::find(k.axes.begin(), k.axes.end(), Axis::Y) != k.axes.end();
  });
  const bool unseen = std::find(id.unseen.begin(), id.unseen.end(), Axis::Y) != id.unseen.end();
  EXPECT_TRUE(inCombination || unseen);
  const bool named = std::any_of(id.sentences.begin(), id.sentences.end(), [](const std::string& s) { return names(s, Axis::Y); });
  EXPECT_TRUE(named);
  for (const std::string& s : id.sentences) std::printf("[ words    ] %s: %s\n", hob, s.c_str());
  for (Axis a : kAxes) {
    const AxisIdentification& x = id.axes[static_cast<int>(a)];
    if (x.reading != AxisReading::Alone) continue;
    // Never injected: within 4 standard uncertainties of 0.
    EXPECT_LE(std::abs(x.value), 4 * x.perNoise * sigma + 1e-9) << axisName(a) << " read alone at " << x.value;
  }
}

TEST(IdentifiedWords, InjectedYIsNamedWithWhatItIsConfoundedWith) {
  yAloneIsNamed("paper (Tab. 1)", jobOf(paperCase()), 0.5);
  yAloneIsNamed("paper (Tab. 1)", jobOf(paperCase()), 0.05);
  yAloneIsNamed("straight gash", jobOf(straightGashCase()), 0.5);
  yAloneIsNamed("straight gash, module 4", jobOf(straightModule4Case()), 0.5);
}

// On the paper's hob Y is read together with the axes it grinds alike; with little noise the face
// shows +8 µm of Y-equivalent (what Y alone grinds), to within 4 standard uncertainties.
TEST(IdentifiedWords, PaperHobShowsTheYEquivalent) {
  const SharpeningJob job = jobOf(paperCase());
  CorrectionOptions o = job.correction;
  o.probeNoise = 0.05;
  const Correction c = corrected(job, yOffset(job, 0.008), o, 1);
  ASSERT_EQ(c.identified.combinations.size(), 1u);
  const AxisCombination& k = c.identified.combinations.front();
  const size_t y = static_cast<size_t>(std::find(k.axes.begin(), k.axes.end(), Axis::Y) - k.axes.begin());
  ASSERT_LT(y, k.axes.size()) << k.sentence;
  EXPECT_GE(k.axes.size(), 2u);
  EXPECT_GE(k.alike, o.reading.alikeShare);
  EXPECT_TRUE(k.aloneListed[y]) << "Y alone grinds the face shown as well as any: " << k.sentence;
  EXPECT_NEAR(k.aloneValue[y], 8.0, 4 * k.alonePerNoise[y] * o.probeNoise) << k.sentence;
  EXPECT_NE(k.sentence.find(std::string(axisName(k.axes.front())) + "-equivalent"), std::string::npos) << k.sentence;
  if (y > 0) {
    EXPECT_NE(k.sentence.find("Y alone with +"), std::string::npos) << k.sentence;
  }
  // On a helical gash X and A are never read alone (an axial shift of a helicoid is a turn of it).
  EXPECT_NE(c.identified.axes[static_cast<int>(Axis::X)].reading, AxisReading::Alone);
  EXPECT_NE(c.identified.axes[static_cast<int>(Axis::A)].reading, AxisReading::Alone);
}

// On a straight gash the face does not show X, Y and B at all: one sentence says so.
TEST(IdentifiedWords, StraightGashSaysWhatItDoesNotShow) {
  const SharpeningJob job = jobOf(straightGashCase());
  const Correction c = corrected(job, yOffset(job, 0.008), job.correction, 1);
  for (Axis a : {Axis::X, Axis::Y, Axis::B})
    EXPECT_EQ(c.identified.axes[static_cast<int>(a)].reading, AxisReading::Unseen) << axisName(a);
  ASSERT_FALSE(c.identified.sentences.empty());
  EXPECT_EQ(c.identified.sentences.back().rfind("X, Y and B: the face does not show their errors at all", 0), 0u)
      << c.identified.sentences.back();
}

// The axes a straight gash's face does not show are run as nominal: a run 20 µm off on X and Y is
// changed back, and the unseen axes' sentence says so (the change stood in the table with nothing to
// say where it came from); run on nominal, the sentence has nothing to add.
TEST(IdentifiedWords, UnseenAxesTakenBackToNominalAreSaidSo) {
  for (bool offset : {true, false}) {
    SCOPED_TRACE(offset ? "run off nominal" : "run nominal");
    CaseInput in = straightGashCase();
    const SharpeningJob job = jobOf(in);
    AxisPolynomials run = job.nominalAxes;
    if (offset) run[Axis::X].a[0] += 0.02, run[Axis::Y].a[0] += 0.02;
    in.axes = run;
    AxisPolynomials error = job.nominalAxes;
    for (Axis a : kAxes)
      for (double& c : error[a].a) c = 0;
    error[Axis::Z].a[0] = 0.005;
    in.measured = topographyFor(job, withMachineError(run, error)).normal;
    auto e = evaluate(jobOf(in));
    ASSERT_TRUE(e.ok() && e->correction);
    const Correction& c = *e->correction;
    ASSERT_FALSE(c.identified.sentences.empty());
    const std::string& last = c.identified.sentences.back();
    EXPECT_EQ(last.rfind("X, Y and B: the face does not show their errors at all", 0), 0u) << last;
    const std::string back = "The change proposed there (X \u221220 µm and Y \u221220 µm) only takes the run back to the nominal axes";
    EXPECT_EQ(last.find(back) != std::string::npos, offset) << last;
    for (Axis a : {Axis::X, Axis::Y}) EXPECT_NEAR(c.axisChangeSize[static_cast<int>(a)], offset ? -20.0 : 0.0, 1e-6) << axisName(a);
  }
}

// (b) The uncertainty is the spread: over 30 seeds of fresh probe noise (same hob, same true error)
// the standard deviation of each value read alone is 0.7 to 1.4 times the uncertainty given with it;
// and the uncertainty of the identified error is the change per µm of noise times sigma, exactly.
TEST(IdentifiedWords, UncertaintyIsTheSpreadOverThirtySeeds) {
  SharpeningJob job = jobOf(straightModule4Case());
  job.correction.lockedAxes = {Axis::A};  // the A axis held: the face reads Z on its own
  AxisPolynomials error = yOffset(job, 0.008);
  error[Axis::Z].a[0] = -0.003;
  for (int lockFrom : {2, 99}) {
    CorrectionOptions o = job.correction;
    for (Axis a : kAxes)
      for (int k = lockFrom; k <= job.nominalAxes.degree(); ++k) o.locked.push_back(Coefficient{a, k});
    SCOPED_TRACE("coefficients of degree " + std::to_string(lockFrom) + " and up locked");
    constexpr int kSeeds = 30;
    std::array<std::vector<double>, kAxisCount> values;
    std::array<double, kAxisCount> reported{};
    for (unsigned seed = 1; seed <= kSeeds; ++seed) {
      const Correction c = corrected(job, error, o, seed);
      for (int i = 0; i < kAxisCount; ++i) {
        EXPECT_EQ(c.uncertainty[i], c.changePerNoise[i] * o.probeNoise);
        const AxisIdentification& x = c.identified.axes[i];
        if (x.reading != AxisReading::Alone) continue;
        values[i].push_back(x.value);
        reported[i] += x.perNoise * o.probeNoise;
      }
    }
    EXPECT_EQ(values[static_cast<int>(Axis::Z)].size(), static_cast<size_t>(kSeeds)) << "Z read alone in every seed";
    for (int i = 0; i < kAxisCount; ++i) {
      const std::vector<double>& v = values[i];
      if (v.empty()) continue;
      EXPECT_EQ(v.size(), static_cast<size_t>(kSeeds)) << axisName(kAxes[i]) << " read alone in some seeds only";
      double mean = 0, sq = 0;
      for (double x : v) mean += x / v.size();
      for (double x : v) sq += (x - mean) * (x - mean);
      const double spread = std::sqrt(sq / (v.size() - 1)), given = reported[i] / v.size();
      std::printf("[ figures  ] %s read alone over %zu seeds: mean %+.4f, spread %.4f, uncertainty given %.4f: %.2f\n",
                  axisName(kAxes[i]), v.size(), mean, spread, given, spread / given);
      EXPECT_GE(spread / given, 0.7) << axisName(kAxes[i]);
      EXPECT_LE(spread / given, 1.4) << axisName(kAxes[i]);
    }
    double mean = 0;
    for (double x : values[static_cast<int>(Axis::Z)]) mean += x / kSeeds;
    EXPECT_NEAR(mean, -3.0, 0.1) << "Z's mean over the seeds";
  }
}

// What a combination shows is calibrated too: on the paper's hob, +8 µm on Y over 30 seeds, what
// the face shows of Y's combination as Y alone would grind it (a linear fit, so its spread is the
// noise's; the axis the combination is read as does not follow the noise).
TEST(IdentifiedWords, CombinationValueIsCalibratedOverThirtySeeds) {
  const SharpeningJob job = jobOf(paperCase());
  for (double sigma : {0.5, 0.05}) {
    SCOPED_TRACE("sigma " + std::to_string(sigma));
    CorrectionOptions o = job.correction;
    o.probeNoise = sigma;
    constexpr int kSeeds = 30;
    std::vector<double> values;
    double given = 0;
    for (unsigned seed = 1; seed <= kSeeds; ++seed) {
      const Correction c = corrected(job, yOffset(job, 0.008), o, seed);
      ASSERT_EQ(c.identified.combinations.size(), 1u);
      const AxisCombination& k = c.identified.combinations.front();
      const size_t y = static_cast<size_t>(std::find(k.axes.begin(), k.axes.end(), Axis::Y) - k.axes.begin());
      ASSERT_LT(y, k.axes.size()) << k.sentence;
      if (seed == 1) std::printf("[ words    ] sigma %.2f: %s\n", sigma, k.sentence.c_str());
      EXPECT_TRUE(k.aloneListed[y]) << k.sentence;
      values.push_back(k.aloneValue[y]);
      given += k.alonePerNoise[y] * sigma / kSeeds;
    }
    double mean = 0, sq = 0;
    for (double x : values) mean += x / kSeeds;
    for (double x : values) sq += (x - mean) * (x - mean);
    const double spread = std::sqrt(sq / (kSeeds - 1));
    std::printf("[ figures  ] sigma %.2f: Y alone over %d seeds: mean %+.3f, spread %.3f, uncertainty given %.3f: %.2f\n",
                sigma, kSeeds, mean, spread, given, spread / given);
    EXPECT_GE(spread / given, 0.7);
    EXPECT_LE(spread / given, 1.4);
    EXPECT_NEAR(mean, 8.0, 3 * given);
  }
}

// The identified error's spread (correction.changePerNoise) is taken at the identified error,
// the values read at the axes run (measured_face_correction.cpp): the two are one formula,
// axisSpreadPerNoise equals identifiedAxes' spreadPerNoise for the same sensitivities.
TEST(IdentifiedWords, AxisSpreadIsIdentifiedAxesSpread) {
  const auto [cs, S, step] = randomSensitivities(7);
  const int q = static_cast<int>(cs.size());
  const CorrectionOptions o;
  const IdentifiedAxes id = identifiedAxes(cs, step, S, Eigen::MatrixXd(), Eigen::VectorXd::Random(40), -2, 3, 0.5, o);
  const std::array<double, kAxisCount> spread = axisSpreadPerNoise(cs, step, S, Eigen::MatrixXd(), -2, 3);
  for (int i = 0; i < kAxisCount; ++i) {
    EXPECT_GT(spread[i], 0) << axisName(kAxes[i]);
    EXPECT_NEAR(spread[i], id.spreadPerNoise[i], 1e-12 * spread[i]) << axisName(kAxes[i]);
  }
  // A column the face does not show at all adds nothing; one outside the identifiable space is
  // left out of both.
  Eigen::MatrixXd basis = Eigen::MatrixXd::Identity(q, q);
  basis.row(0).setZero();
  const std::array<double, kAxisCount> without = axisSpreadPerNoise(cs, step, S, Eigen::MatrixXd(), -2, 3, basis);
  const IdentifiedAxes idWithout =
      identifiedAxes(cs, step, S, Eigen::MatrixXd(), Eigen::VectorXd::Random(40), -2, 3, 0.5, o, basis);
  for (int i = 0; i < kAxisCount; ++i) EXPECT_NEAR(without[i], idWithout.spreadPerNoise[i], 1e-12 * without[i]);
}

// The identified error's spread is over the directions sought: a direction outside the
// identifiable space, which the face may show weakly away from the nominal axes (a helical gash's
// X with A), adds nothing, and the sensitivities along it do not matter.
TEST(IdentifiedWords, AxisSpreadIsOverTheDirectionsSought) {
  const auto [cs, S, step] = randomSensitivities(11);
  const int q = static_cast<int>(cs.size());
  // The space: every direction but v, a mix of X's and A's constants.
  Eigen::VectorXd v = Eigen::VectorXd::Zero(q);
  v(0) = 0.6, v(9) = -0.8;
  const Eigen::MatrixXd basis = Eigen::JacobiSVD<Eigen::MatrixXd>(Eigen::MatrixXd::Identity(q, q) - v * v.transpose(),
                                                                  Eigen::ComputeFullU).matrixU().leftCols(q - 1);
  const std::array<double, kAxisCount> sought = axisSpreadPerNoise(cs, step, S, Eigen::MatrixXd(), -2, 3, basis);
  // S along v shown weakly (1e-6 of its norm): nothing changes over the space.
  const Eigen::MatrixXd weak = S * (basis * basis.transpose()) + 1e-6 * (S * v) * v.transpose();
  const std::array<double, kAxisCount> weakly = axisSpreadPerNoise(cs, step, weak, Eigen::MatrixXd(), -2, 3, basis);
  // Over every coefficient, v is sought too, and X and A spread more (a direction added).
  const std::array<double, kAxisCount> every = axisSpreadPerNoise(cs, step, weak, Eigen::MatrixXd(), -2, 3);
  for (int i = 0; i < kAxisCount; ++i) {
    EXPECT_GT(sought[i], 0) << axisName(kAxes[i]);
    EXPECT_NEAR(weakly[i], sought[i], 1e-9 * sought[i]) << axisName(kAxes[i]);
  }
  EXPECT_GT(every[static_cast<int>(Axis::X)], 100 * sought[static_cast<int>(Axis::X)]);
  EXPECT_GT(every[static_cast<int>(Axis::A)], 100 * sought[static_cast<int>(Axis::A)]);
}

// The identification decomposes the face's sensitivities at the identified error when it decides
// its directions there; the spread taken from that decomposition is the one the sensitivities give
// (computed again, to rounding on the weakest directions), on a helical and a straight gash, and
// it is the correction's changePerNoise.
TEST(IdentifiedWords, AxisSpreadFromTheIdentificationsDecomposition) {
  for (const CaseInput& in : {paperCase(), straightModule4Case()}) {
    const SharpeningJob job = jobOf(in);
    SCOPED_TRACE(job.setup.face.helical() ? "helical gash" : "straight gash");
    const auto f = identifiedFace(job, 5, 3);
    ASSERT_TRUE(f);
    const auto& [o, measured, face, m] = *f;
    const int q = static_cast<int>(m.space.coefficients.size());
    ASSERT_EQ(m.atSolution.directions.rows(), q) << "no decomposition at the identified error";
    ASSERT_EQ(m.atSolution.singularValues.size(), m.atSolution.directions.cols());
    // Orthonormal in machine steps.
    EXPECT_LT((m.atSolution.directions.transpose() * m.atSolution.directions -
               Eigen::MatrixXd::Identity(m.atSolution.directions.cols(), m.atSolution.directions.cols())).norm(), 1e-12);
    const MotionRange range = motionRange(face);
    const auto reused = axisSpreadPerNoise(m.space.coefficients, m.space.step, m.atSolution, range.min, range.max);
    const auto again = axisSpreadPerNoise(m.space.coefficients, m.space.step, m.jacobian, m.nuisance, range.min,
                                          range.max, m.space.basis);
    auto c = correctMeasuredFace(job.setup, job.nominalAxes, job.nominalAxes, face, measured, o);
    ASSERT_TRUE(c.ok()) << c.error().message;
    std::printf("[ figures  ] %s: change per um of noise X %.4g um, Y %.4g um, Z %.4g um, A %.4g urad, B %.4g urad\n",
                job.setup.face.helical() ? "helical" : "straight", reused[0], reused[1], reused[2], reused[3], reused[4]);
    // (A straight gash's X, Y and B are outside the space: 0 both ways.)
    EXPECT_GT(reused[static_cast<int>(Axis::Z)], 0);
    EXPECT_GT(reused[static_cast<int>(Axis::A)], 0);
    for (int i = 0; i < kAxisCount; ++i) {
      EXPECT_NEAR(reused[i], again[i], 1e-6 * again[i]) << axisName(kAxes[i]);
      EXPECT_EQ(c->changePerNoise[i], reused[i]) << axisName(kAxes[i]);
    }
  }
}

// What is read at the run rests on the decomposition the identification made there (its first
// decision, MachineErrorEstimate::atRun) instead of a second one of the same sensitivities: the
// same readings, values, uncertainties and sentences as with the sensitivities decomposed again.
TEST(IdentifiedWords, ReadingAtTheRunFromTheIdentificationsDecomposition) {
  for (const CaseInput& in : {paperCase(), straightModule4Case(), leftHandRakeCase()}) {
    const SharpeningJob job = jobOf(in);
    for (unsigned seed : {3u, 4u}) {
      SCOPED_TRACE(std::string(job.setup.face.helical() ? "helical gash" : "straight gash") + ", seed " +
                   std::to_string(seed));
      const auto f = identifiedFace(job, seed, seed);
      ASSERT_TRUE(f);
      const auto& [o, measured, face, m] = *f;
      ASSERT_EQ(m.atRun.directions.rows(), static_cast<int>(m.space.coefficients.size()));
      const MotionRange range = motionRange(face);
      const Eigen::MatrixXd S = sensitivityMatrix(face, m.space.coefficients).normal;
      const Eigen::VectorXd data = flat(measured) - faceNormal(face);
      const IdentifiedAxes again = identifiedAxes(m.space.coefficients, m.space.step, S, Eigen::MatrixXd(), data,
                                                  range.min, range.max, o.probeNoise, o, m.space.basis);
      const IdentifiedAxes made = identifiedAxes(m.space.coefficients, m.space.step, S, Eigen::MatrixXd(), data,
                                                 range.min, range.max, o.probeNoise, o, m.space.basis, &m.atRun);
      EXPECT_EQ(made.sentences, again.sentences);
      EXPECT_EQ(made.unseen, again.unseen);
      for (int i = 0; i < kAxisCount; ++i) {
        SCOPED_TRACE(axisName(kAxes[i]));
        EXPECT_EQ(made.axes[i].reading, again.axes[i].reading);
        EXPECT_NEAR(made.axes[i].value, again.axes[i].value, 1e-9 * (1 + std::abs(again.axes[i].value)));
        EXPECT_NEAR(made.axes[i].perNoise, again.axes[i].perNoise, 1e-9 * (1 + again.axes[i].perNoise));
      }
      ASSERT_EQ(made.combinations.size(), again.combinations.size());
      for (size_t k = 0; k < made.combinations.size(); ++k) {
        EXPECT_EQ(made.combinations[k].axes, again.combinations[k].axes);
        EXPECT_NEAR(made.combinations[k].value, again.combinations[k].value, 1e-9 * (1 + std::abs(again.combinations[k].value)));
        EXPECT_NEAR(made.combinations[k].perNoise, again.combinations[k].perNoise, 1e-9 * (1 + again.combinations[k].perNoise));
      }
    }
  }
}

// The second-order part is read by the same linear reading as the data: given the data itself, each
// value's second-order figure is twice the value (kSecondOrderMargin); given nothing, none.
TEST(IdentifiedWords, SecondOrderIsTheSameReadingOfTheSecondOrderPart) {
  const SharpeningJob job = jobOf(paperCase());
  CorrectionOptions o = job.correction;
  o.probeNoise = 0.5;
  const Eigen::MatrixXd measured = measuredWithError(job, o, 5, 3);
  const GroundFace face = groundFaceOf(job, job.nominalAxes);
  const IdentifiableSpace space = identifiableSpace(job.setup.face, job.nominalAxes.degree(), o, 1);
  const MotionRange range = motionRange(face);
  const Eigen::MatrixXd S = sensitivityMatrix(face, space.coefficients).normal;
  const Eigen::VectorXd data = flat(measured) - faceNormal(face);
  const IdentifiedAxes plain = identifiedAxes(space.coefficients, space.step, S, Eigen::MatrixXd(), data, range.min,
                                              range.max, o.probeNoise, o, space.basis);
  const IdentifiedAxes same = identifiedAxes(space.coefficients, space.step, S, Eigen::MatrixXd(), data, range.min,
                                             range.max, o.probeNoise, o, space.basis, nullptr, &data);
  ASSERT_FALSE(plain.combinations.empty());
  for (size_t k = 0; k < plain.combinations.size(); ++k) {
    EXPECT_EQ(plain.combinations[k].secondOrder, 0.0);
    EXPECT_NEAR(same.combinations[k].value, plain.combinations[k].value, 1e-9 * (1 + std::abs(plain.combinations[k].value)));
    EXPECT_NEAR(same.combinations[k].secondOrder, 2 * std::abs(same.combinations[k].value),
                1e-9 * (1 + std::abs(same.combinations[k].value)));
    for (size_t m = 0; m < same.combinations[k].aloneValue.size(); ++m)
      EXPECT_NEAR(same.combinations[k].aloneSecondOrder[m], 2 * std::abs(same.combinations[k].aloneValue[m]),
                  1e-9 * (1 + std::abs(same.combinations[k].aloneValue[m])));
  }
  // Where it is larger than the uncertainty, the sentence says it.
  bool said = false;
  for (const std::string& t : same.sentences) said = said || t.find("second order may move it up to") != std::string::npos;
  EXPECT_TRUE(said);
  for (const std::string& t : plain.sentences) EXPECT_EQ(t.find("second order"), std::string::npos) << t;
}

// The second-order part the correction reads is what the identified error's face holds beyond its
// first order: the face at E less the run face less S E, at the run face's points in their order.
TEST(IdentifiedWords, SecondOrderPartIsTheIdentifiedFaceBeyondItsFirstOrder) {
  const SharpeningJob job = jobOf(paperCase());
  const auto f = identifiedFace(job, 5, 3);
  ASSERT_TRUE(f);
  const auto& [o, measured, face, m] = *f;
  ASSERT_FALSE(m.structuralFreed());
  const MotionRange range = motionRange(face);
  const Eigen::MatrixXd S = sensitivityMatrix(face, m.space.coefficients).normal;
  const Eigen::VectorXd data = flat(measured) - faceNormal(face);
  const Eigen::VectorXd second = flat(m.explained) - faceNormal(face) - S * m.coefficientError;
  const IdentifiedAxes expected = identifiedAxes(m.space.coefficients, m.space.step, S, Eigen::MatrixXd(), data, range.min,
                                                 range.max, o.probeNoise, o, m.space.basis, &m.atRun, &second);
  auto c = correctMeasuredFace(job.setup, job.nominalAxes, job.nominalAxes, face, measured, o);
  ASSERT_TRUE(c.ok()) << c.error().message;
  const IdentifiedAxes& got = c->identified;
  ASSERT_EQ(got.combinations.size(), expected.combinations.size());
  bool some = false;
  for (size_t k = 0; k < got.combinations.size(); ++k) {
    some = some || got.combinations[k].secondOrder > 0;
    EXPECT_NEAR(got.combinations[k].secondOrder, expected.combinations[k].secondOrder,
                1e-9 * (1 + expected.combinations[k].secondOrder));
    EXPECT_LT(got.combinations[k].secondOrder, std::abs(got.combinations[k].value)) << "a shift, not the value";
  }
  EXPECT_TRUE(some);
  for (int i = 0; i < kAxisCount; ++i)
    EXPECT_NEAR(got.axes[i].secondOrder, expected.axes[i].secondOrder, 1e-9 * (1 + expected.axes[i].secondOrder));
}

// The fields reach the result: per axis its reading and value, and the sentences.
TEST(IdentifiedWords, ResultFieldsHoldTheWords) {
  std::vector<std::string> paths;
  for (const FieldDescription& f : resultFields()) paths.push_back(f.path);
  for (const char* p : {"correction.identifiedAxes.Y", "correction.identifiedAlone.B",
                        "correction.identifiedAloneUncertainty.Z", "correction.identifiedCombinations",
                        "correction.identifiedError.Y", "correction.uncertainty.Y", "correction.precision.changePerNoise.Y"})
    EXPECT_NE(std::find(paths.begin(), paths.end(), p), paths.end()) << p;
  CaseInput in = paperCase();
  const SharpeningJob job = jobOf(in);
  in.measured = topographyFor(job, withMachineError(job.nominalAxes, yOffset(job, 0.008))).normal +
                probeNoise(job.grid.rows(), job.grid.cols(), 0.5, 1);
  auto e = evaluate(jobOf(in));
  ASSERT_TRUE(e.ok());
  const std::string json = resultJson(*e);
  EXPECT_NE(json.find("\"identifiedAxes\":{\"X\":\"together\""), std::string::npos) << json.substr(0, 200);
  EXPECT_NE(json.find("-equivalent"), std::string::npos);
  EXPECT_NE(json.find("Y-equivalent"), std::string::npos);
}

}  // namespace
}  // namespace hobsharp::test
