// The calibration of the values the page reads about the machine, on random hobs (issue 20, item
// 5; docs/validation.md, "The uncertainty of the values read"): over 30 fresh probe-noise draws of
// one random machine error, each value read (an axis alone, a combination's equivalent, a member's
// value alone) spreads 0.7 to 1.4 times the standard uncertainty given with it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "calibration.h"

namespace hobsharp::validation {
namespace {

double highestRatio(const Calibration& c) {
  double r = 0;
  for (const CalibratedValue& v : c.values) r = std::max(r, v.ratio());
  return r;
}

// The first 40 hobs of the default seed: at least 90 % of the values read are within 0.7 to 1.4
// (42 of 45 here: two values of one group of scenario 196 at 0.674, and one at 1.40), and none is
// outside 0.6 to 1.6. Thirty draws alone put a calibrated value's ratio outside 0.67 to 1.34 once
// in a hundred (the chi distribution with 29 degrees of freedom), so the band is not asked of every
// value; a value read from a wandering estimate was 7 to 60 times off (the test below).
// The default seed's first 40 hobs, calibrated once for the tests that judge them.
const Calibration& firstForty() {
  static const Calibration c = [] {
    CalibrationOptions o;
    o.hobs = 40;
    return runCalibration(o, 2);
  }();
  return c;
}

TEST(Calibration, ValuesReadSpreadAsTheirUncertaintySays) {
  const Calibration& c = firstForty();
  std::printf("%s", calibrationText(c).c_str());
  EXPECT_EQ(c.hobsRun, 40);
  EXPECT_EQ(c.refused, 0);
  ASSERT_GE(c.values.size(), 35u);
  EXPECT_GE(c.within(), 0.9 * static_cast<double>(c.values.size()));
  EXPECT_LT(highestRatio(c), 1.6);
  for (const CalibratedValue& v : c.values) EXPECT_GT(v.ratio(), 0.6) << "scenario " << v.hob << ", " << v.what;
  // Against the true error's first-order reading: within 3 uncertainties plus the second-order
  // figure stated with the value (42 of 45 within 3 uncertainties alone here; all with it).
  ASSERT_GE(c.withTruth(), 0.8 * static_cast<double>(c.values.size()));
  EXPECT_GE(c.nearTruthStated(), 0.95 * c.withTruth());
  EXPECT_GE(c.drawsNearTruth(), 0.95 * c.draws());
  // And it informs: where it is stated (larger than the uncertainty), its median over the actual
  // shift of the mean from the truth is at most 3 (1.8 on the 300 hobs of docs/validation.md).
  std::vector<double> over;
  for (const CalibratedValue& v : c.values)
    if (v.hasTruth && v.secondOrder > v.given) over.push_back(v.secondOrder / (std::abs(v.mean - v.truth) + 1e-12));
  std::printf("[ figures  ] second-order figure over the actual shift, %zu values:", over.size());
  std::sort(over.begin(), over.end());
  for (double r : over) std::printf(" %.2f", r);
  std::printf("\n");
  ASSERT_GE(over.size(), 5u);
  EXPECT_LE(over[over.size() / 2], 3.0);
}

// correction.uncertainty, per axis, is the precision demand times sigma, over every direction the
// face shows were each taken (docs/conventions.md, "What it is not"): not the spread of the
// proposal, and mostly far above it. It falls below half the identified error's spread over the
// draws for at most 3 % of the axes moved (2 of 140 here: scenario 214's Z and A, 3.0 times; 7 of
// 2,996 on the three seeds of the docs).
TEST(Calibration, PerAxisFigureIsRarelyBelowTheProposalsSpread) {
  const Calibration& c = firstForty();
  const CalibrationOptions& o = c.options;
  const double n = static_cast<double>(c.axisSpreads.size());
  std::printf("[ figures  ] %zu axes moved, %d within %.1f to %.1f, the figure 10 times the spread or more on %d, below half of it on %d\n",
              c.axisSpreads.size(), c.axisSpreadsWithin(), o.low, o.high, c.figureOver(10), c.figureUnder(0.5));
  ASSERT_GE(n, 100);
  EXPECT_LE(c.figureUnder(0.5), 0.03 * n);
  for (const AxisSpread& a : c.axisSpreads) EXPECT_TRUE(std::isfinite(a.ratio()) && a.given > 0) << a.hob << " " << a.axis;
}

// The values read stand for the true error's first-order reading (the same value read, noise-free,
// from the nominal face plus its sensitivities times the error). Where that first order is the
// face (a 2 µm rms error: the default error times 0.2), every mean over the 30 draws lies within
// 3 uncertainties of it: the truth is computed right and the reading carries the error. (At
// 10 µm rms 9 to 11 % do not, at 30 µm 39 %: the uncertainty holds the probe noise only, and
// each value states beside it how far the error's second order may move it, docs/validation.md
// "Against the true error".)
TEST(Calibration, ValuesReadFromASmallErrorLieAtTheTruth) {
  CalibrationOptions o;
  o.hobs = 20;
  o.errorScale = 0.2;
  const Calibration c = runCalibration(o, 2);
  std::printf("%s", calibrationText(c).c_str());
  // (A value read in the measurements may not be read from the truth's face: which member a group
  // is read as, and whether a member's value is listed, turn on the noise.)
  ASSERT_GE(c.values.size(), 10u);
  EXPECT_GE(c.withTruth(), 0.8 * static_cast<double>(c.values.size()));
  EXPECT_EQ(c.nearTruth(), c.withTruth());
  for (const CalibratedValue& v : c.values) {
    if (v.hasTruth) {
      EXPECT_LE(v.miss(), o.truthWithin) << "scenario " << v.hob << ", " << v.what;
    }
  }
}

// Why the result gives no per-axis spread of the proposal (docs/conventions.md, "What it is not"):
// a parametric bootstrap of one measurement (the face its identified error grinds, measured again
// with fresh noise and identified again) does not tell how the proposal spreads over measurements.
// The directions taken turn on the noise where the face shows them near it, and the bootstrap
// starts from an estimate that has taken some of them and not others. On the default seed's first
// 15 hobs, 20 draws each, 16 of 54 axes moved lie within 0.7 to 1.4 of it, and 19 spread more than
// twice its figure (a figure more certain than it is); with 30 draws on 300 hobs, 415 and 284 of
// 1,002 (docs/conventions.md). Should a change to the identification make the bootstrap
// calibrated, this fails, and the figure can be offered.
TEST(Calibration, ABootstrapOfOneMeasurementUnderstatesTheProposalsSpread) {
  CalibrationOptions o;
  o.hobs = 15;
  o.bootstrapDraws = 20;
  const Calibration c = runCalibration(o, 2);
  const double n = static_cast<double>(c.axisSpreads.size());
  std::printf("%s", calibrationText(c).c_str());
  ASSERT_GE(n, 40);
  EXPECT_GE(c.bootstrapMoved(), 0.9 * n);
  EXPECT_LE(c.bootstrapWithin(), 0.6 * n);
  EXPECT_GE(c.bootstrapUnder(2), 0.1 * n);
  for (const AxisSpread& a : c.axisSpreads) EXPECT_TRUE(std::isfinite(a.bootstrapRatio())) << a.hob << " " << a.axis;
}

// Two hobs whose values read spread tens of times their uncertainty before (docs/validation.md).
// Seed 11's scenario 274: on one draw of 30 the identification decided a ninth direction at its
// converged estimate and wandered 45 iterations along it, reading 22.35 where the others read 9.7
// to 9.9 µm (ratio 42.8); the converged estimate is now kept (identification.h). Seed 1001's
// scenario 1054: the values were read from the face linearised at the identified error, whose
// weakly seen directions move with the noise (ratio 55; with the fall-back alone 62.8, a seventh
// direction reading 20.0 where the others read -9.2 to -9.5 µm); they are now read from the
// measured change at the axes run.
TEST(Calibration, ValuesReadDoNotJumpWithTheDirectionsTaken) {
  for (auto [seed, hob] : {std::pair<std::uint64_t, int>{11, 45}, {1001, 175}}) {
    CalibrationOptions o;
    o.seed = seed;
    o.firstHob = hob;
    o.hobs = 1;
    const Calibration c = runCalibration(o, 2);
    std::printf("%s", calibrationText(c).c_str());
    ASSERT_FALSE(c.values.empty()) << "seed " << seed;
    for (const CalibratedValue& v : c.values) {
      EXPECT_GE(v.ratio(), o.low) << v.what;
      EXPECT_LE(v.ratio(), o.high) << v.what;
    }
  }
}

}  // namespace
}  // namespace hobsharp::validation
