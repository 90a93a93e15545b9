// The correction from the pass history (docs/method.md §Correction from the pass history): a second
// pass identifies the machine's error from its own face and the first pass's together. Checked on
// campaign scenarios of the default seed, each pass measured as the campaign measures it (the
// module as the machine, noise-free, judged on the probe grid).
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evaluation.h"
#include "face_vectors.h"
#include "ground_face.h"
#include "pass_history.h"
#include "machine_error.h"
#include "measured_points.h"
#include "run_scenario.h"
#include "scenario.h"
#include "sharpening_job.h"
#include "solve_report.h"
#include "topography.h"

namespace hobsharp::validation {
namespace {

constexpr std::uint64_t kSeed = 20261125;

struct Passes {
  Scenario s;
  SharpeningJob job;
  AxisPolynomials firstRun, secondRun;
  Eigen::MatrixXd firstMeasured, secondMeasured;
};

// The face `axes` grind on the machine (with its error), on the probe grid: µm, and its rms.
Eigen::MatrixXd groundOnMachine(const Passes& p, const AxisPolynomials& axes) {
  auto f = simulateGroundFace(p.job.setup, plusError(axes, p.s.error), p.job.grid, Sensitivities::Skip);
  EXPECT_TRUE(f.ok());
  return f ? topographyOf(*f).normal : Eigen::MatrixXd();
}
double rms(const Eigen::MatrixXd& m) { return std::sqrt(m.squaredNorm() / static_cast<double>(m.size())); }

// Scenario `index`'s first pass into `p`: its case, the face the nominal axes grind on the machine
// measured (noise-free, sigma declared 0.01 µm).
CaseInput firstCase(Passes& p, int index, std::uint64_t seed = kSeed) {
  auto s = makeScenario(seed, index);
  EXPECT_TRUE(s.ok());
  p.s = *s;
  p.job = *resolveJob(p.s.input);
  p.firstRun = p.job.nominalAxes;
  p.firstMeasured = groundOnMachine(p, p.firstRun);
  CaseInput c = p.s.input;
  c.measured = p.firstMeasured;
  c.correction.probeNoise = 0.01;
  return c;
}

// Scenario `index`'s first pass (nominal axes, corrected from its face alone) and the face its
// proposal grinds: the second pass's measurement.
Passes twoPasses(int index, std::uint64_t seed = kSeed) {
  Passes p;
  const CaseInput c = firstCase(p, index, seed);
  auto e = evaluate(*resolveJob(c));
  EXPECT_TRUE(e.ok() && e->correction);
  p.secondRun = e->correction->axes;
  p.secondMeasured = groundOnMachine(p, p.secondRun);
  return p;
}

// The second pass's case: its run and face, with the first pass in `passes` or without it.
CaseInput secondCase(const Passes& p, bool withHistory, const Eigen::MatrixXd* firstMeasured = nullptr) {
  CaseInput c = p.s.input;
  c.axes = p.secondRun;
  c.measured = p.secondMeasured;
  c.correction.probeNoise = 0.01;
  if (withHistory) c.passes.push_back(PassInput{p.firstRun, firstMeasured ? *firstMeasured : p.firstMeasured, {}, {}});
  return c;
}

// Every combination one face does not show is named in c.unobservable with `words`.
void expectSoughtAllTheSame(const Correction& c, const std::string& words) {
  ASSERT_FALSE(c.unobservable.empty());
  for (const UnobservableCombination& u : c.unobservable) EXPECT_NE(u.description.find(words), std::string::npos) << u.description;
}

Correction corrected(const CaseInput& c) {
  auto job = resolveJob(c);
  if (!job) ADD_FAILURE() << job.error().message;
  auto e = evaluate(*job);
  EXPECT_TRUE(e.ok() && e->correction) << (e ? "" : e.error().message);
  return *e->correction;
}

// One face, the structural null space freed (machine_error.h). Scenario 182 (helical gash,
// 150 µm rms, noise-free): over the identifiable space (X against A left out) the first pass's
// identification stalls above the noise, and its proposal leaves 54 µm rms between the probe
// points; sought over every coefficient from there, one error explains the face to the noise, and
// the proposal leaves 6.9 µm.
TEST(PassHistory, AFaceAboveTheNoiseIsSoughtOverEveryCoefficient) {
  const Passes p = twoPasses(182);
  auto job = resolveJob(p.s.input);
  ASSERT_TRUE(job.ok());
  CorrectionOptions o = job->correction;
  o.probeNoise = 0.01;
  auto face = simulateGroundFace(job->setup, p.firstRun, job->grid);
  ASSERT_TRUE(face.ok());
  auto m = identifyMachineError(job->setup, p.firstRun, *face, p.firstMeasured, o);
  ASSERT_TRUE(m.ok());
  EXPECT_TRUE(m->structuralFreed());
  EXPECT_TRUE(m->space.structural.empty());
  EXPECT_EQ(m->summary.status, SolveStatus::Converged) << m->summary.reason;
  EXPECT_LE(m->summary.finalCost, noiseCeiling(face->size(), o.probeNoise));
  CaseInput c = p.s.input;
  c.measured = p.firstMeasured;
  c.correction.probeNoise = 0.01;
  const Correction k = corrected(c);
  // What the face does not show to first order is named, and said to be sought all the same.
  expectSoughtAllTheSame(k, "to first order; sought all the same, since this face is not explained to the probe noise "
                            "without it");
  const double left = rms(groundOnMachine(p, k.axes));
  EXPECT_LT(left, 10.0);
  // The bound (408 µm) is above the face measured (129 µm), and the verdict says so.
  EXPECT_GT(k.predictedRmsHigh, k.before.rms);
  EXPECT_NE(k.verdict.rfind("Uncertain: the face does not show enough", 0), std::string::npos) << k.verdict;
}

// Two starts for the search over every pass's face (machine_error.cpp). Scenario 446 (straight
// gash, 150 µm rms), second pass: started at the error the run compensates, the search ends above
// the noise, and the face's own estimate left 0.75 µm rms; started again at this face's own
// estimate it explains both faces, and the face left is below 0.1 µm (0.018 µm on the probe grid;
// the bound, 0.0062 µm, does not hold here: one of the campaign's noise-free passes outside it).
TEST(PassHistory, ASecondStartFromThisFacesEstimateJoinsTheFaces) {
  const Passes p = twoPasses(446);
  const Correction joined = corrected(secondCase(p, true));
  EXPECT_EQ(joined.passesJoined, 1) << joined.verdict;
  EXPECT_EQ(joined.summary.status, SolveStatus::Converged);
  EXPECT_LT(rms(groundOnMachine(p, joined.axes)), 0.1);
}

// A third start where the first two do not explain the faces: at the error the run compensates,
// with the trust region in machine steps (least_squares_options.h, StepScale::Parameters). Seed
// 99, scenario 344 (straight gash, 150 µm rms), second pass: both starts with the trust region
// scaled by the Jacobian's columns run along the directions one face barely shows to more than
// 300,000 machine steps from E0 (the error is 6,300 from it) and end above the noise, 0.21 µm rms
// left over both faces; the face's own estimate then left 0.61 µm between the probe points. With
// the steps in machine steps the search explains both faces (0.0005 µm rms left), and the pass
// leaves 0.007 µm.
TEST(PassHistory, AThirdStartInMachineStepsJoinsTheFaces) {
  const Passes p = twoPasses(344, 99);
  const Correction joined = corrected(secondCase(p, true));
  EXPECT_EQ(joined.passesJoined, 1) << joined.verdict;
  EXPECT_EQ(joined.summary.status, SolveStatus::Converged) << joined.summary.reason;
  EXPECT_LT(rms(groundOnMachine(p, joined.axes)), 0.1);
}

// The same, seed 20261125, scenario 518 (straight gash, 150 µm rms), second pass: the two starts
// end above the noise (25 and 16 µm rms left over both faces) and the face's own estimate left
// 17.7 µm between the probe points; the third explains both faces. The two faces do not show every
// direction (11 of 35 within the noise), so the pass leaves about 1 µm: better, not done.
TEST(PassHistory, AThirdStartJoinsFacesTheTwoDidNot) {
  const Passes p = twoPasses(518);
  const Correction k = corrected(secondCase(p, true));
  EXPECT_EQ(k.passesJoined, 1) << k.verdict;
  EXPECT_LT(rms(groundOnMachine(p, k.axes)), 2.0);
}

// A pass joined with the history and linearised at the nominal axes (its axes alone grind no face):
// the bound samples what this face alone does not show too (face_prediction.cpp). Seed 9005,
// scenario 164 (helical gash, 150 µm rms), second pass: one error explains both faces to the probe
// noise, yet the machine's own error is another one, and the proposal leaves 1.26 µm rms on the
// probe grid. The bound sampling only what the joined faces do not show was 0.00654 µm, with
// "Correctable" (an independent review, 2026-12-07); now it holds, and the verdict says "Uncertain".
TEST(PassHistory, AJoinedPassLinearisedAtTheNominalAxesBoundsWhatItsOwnFaceDoesNotShow) {
  const Passes p = twoPasses(164, 9005);
  const Correction k = corrected(secondCase(p, true));
  ASSERT_EQ(k.passesJoined, 1) << k.verdict;
  ASSERT_TRUE(k.linearisedAtNominal);
  const double left = rms(groundOnMachine(p, k.axes));
  EXPECT_GT(left, 1.0);
  EXPECT_LE(left, k.predictedRmsHigh);
  EXPECT_EQ(k.verdict.rfind("Uncertain:", 0), 0u) << k.verdict;
}

// A locked axis is not sought, so its error stays in both faces and no error over the free axes
// explains them together: the note names the lock first, then a change of the machine (an
// independent review, 2026-12-07: "has the machine or the setup changed?" alone, with nothing
// changed but the lock).
// Seed 4242, scenario 2, second pass, B locked.
TEST(PassHistory, ALockedAxisIsNamedWhereTheFacesAreNotJoined) {
  const Passes p = twoPasses(2, 4242);
  CaseInput c = secondCase(p, true);
  c.correction.lockedAxes = {Axis::B};
  const Correction k = corrected(c);
  EXPECT_EQ(k.passesJoined, 0);
  EXPECT_NE(k.verdict.find("No one error of the free coefficients (B locked) explains this face and the 1 earlier "
                           "pass's face to the probe noise"),
            std::string::npos)
      << k.verdict;
  EXPECT_NE(k.verdict.find("unlock B to seek one error over them all; if that does not join them, has the machine or "
                           "the setup changed?"),
            std::string::npos)
      << k.verdict;
}

// Where no start explains the faces, the note says how much the nearest left. Seed 3, scenario 578
// (straight gash, 150 µm rms), second pass: no start explains both faces; the nearest leaves 5.9 µm
// rms over them. (Seed 99's scenario 92 was this test's case, 0.2 µm rms left, 0.15 µm after two
// passes: since a first pass's search over every coefficient decides its directions on the whole
// error (machine_error.cpp), its first pass's face is explained to the noise (it stayed above it),
// and the second pass explains both faces and leaves 0.0017 µm.)
TEST(PassHistory, WhereNoStartJoinsTheFacesTheNoteQuotesTheNearest) {
  const Passes p = twoPasses(578, 3);
  const Correction k = corrected(secondCase(p, true));
  EXPECT_EQ(k.passesJoined, 0);
  EXPECT_NE(k.verdict.find("No one machine error explains this face and the 1 earlier pass's face to the probe noise "
                           "(5.9 µm rms left)"),
            std::string::npos)
      << k.verdict;
}

// The verdict's offer of the next pass (an "Uncertain:" verdict, here a bound above the face
// measured) only where a next pass uses this face: not for a face measured at the measuring
// machine's own points, which the pass history leaves out. Scenario 152 (straight gash, 150 µm
// rms), first pass, measured on the grid and at points 5 µm off each grid point: both bounds are
// above the face measured.
TEST(PassHistory, TheNextPassIsOfferedOnlyWhereItUsesThisFace) {
  Passes p;
  CaseInput c = firstCase(p, 152);
  const Correction grid = corrected(c);
  ASSERT_GT(grid.predictedRmsHigh, grid.before.rms);
  EXPECT_NE(grid.verdict.find("keep this pass in the case: a next pass measured on the grid seeks one error"),
            std::string::npos)
      << grid.verdict;
  // Off the grid points by 5e-3 mm inwards, beyond kGridTolerance, so that the case is read as
  // points (the face measured there differs by far less than the bound's margin).
  const FaceGrid& g = p.job.grid;
  std::vector<MeasuredPoint> points;
  for (int i = 0; i < g.rows(); ++i)
    for (int j = 0; j < g.cols(); ++j)
      points.push_back({g.r[i] + (i + 1 < g.rows() ? 5e-3 : -5e-3), g.x[j] + (j + 1 < g.cols() ? 5e-3 : -5e-3),
                        (*c.measured)(i, j)});
  c.measured.reset();
  c.measuredPoints = points;
  const Correction atPoints = corrected(c);
  ASSERT_GT(atPoints.predictedRmsHigh, atPoints.before.rms) << atPoints.verdict;
  EXPECT_NE(atPoints.verdict.rfind("Uncertain: the face does not show enough", 0), std::string::npos) << atPoints.verdict;
  EXPECT_EQ(atPoints.verdict.find("keep this pass in the case"), std::string::npos) << atPoints.verdict;
}

// The offer to keep this pass holds only where a next case would join it: not where an earlier pass
// in the case corrected the wheel (passHistory then leaves every pass out, and so would the next
// case's, which keeps that pass). Scenario 152's first face, with an earlier grid pass whose
// correction dressed the wheel.
TEST(PassHistory, NoOfferToKeepThePassWhereAnEarlierPassDressedTheWheel) {
  Passes p;
  CaseInput c = firstCase(p, 152);
  CorrectionInput dressed;
  dressed.wheel = true;
  c.passes.push_back(PassInput{p.job.nominalAxes, *c.measured, {}, dressed});
  ASSERT_TRUE(resolveJob(c)->history.empty());
  const Correction k = corrected(c);
  EXPECT_EQ(k.verdict.find("keep this pass in the case"), std::string::npos) << k.verdict;
}

// Scenario 206 (helical gash, 150 µm rms): from its own face alone, the second pass's estimate
// explains that face with a wrong error and its proposal grinds tens of µm; from both faces the
// error is found and the face left is below 0.1 µm rms.
TEST(PassHistory, TheFirstPasssFaceFindsTheErrorTheSecondFaceAloneCannot) {
  const Passes p = twoPasses(206);
  const Correction alone = corrected(secondCase(p, false));
  const Correction joined = corrected(secondCase(p, true));
  EXPECT_EQ(alone.passesJoined, 0);
  EXPECT_EQ(joined.passesJoined, 1);
  EXPECT_EQ(joined.summary.status, SolveStatus::Converged);
  EXPECT_NE(joined.verdict.find("identified from this face and the 1 earlier pass's face together"), std::string::npos)
      << joined.verdict;
  // X against A (a helical gash): left out from one face, sought over both.
  expectSoughtAllTheSame(joined, "on one face to first order; sought all the same over this face and the earlier "
                                 "passes' faces together");
  const double leftAlone = rms(groundOnMachine(p, alone.axes)), leftJoined = rms(groundOnMachine(p, joined.axes));
  EXPECT_GT(leftAlone, 1.0);
  EXPECT_LT(leftJoined, 0.1);
  EXPECT_LE(leftJoined, joined.predictedRmsHigh);
}

// The same second pass with a first face the machine's error did not grind (another error's):
// no one error explains both, so the face's own estimate stands and the verdict says why. The
// joined search ends with trial faces rejected and the residual still leaning on its directions
// (cosines 0.007 to 0.11, stalledGradientCosine): it stalled, and says so, rather than claim that
// the 17 µm left is a shape no one error makes.
TEST(PassHistory, AHistoryNoErrorExplainsIsNotJoined) {
  const Passes p = twoPasses(206);
  AxisPolynomials other = p.s.error;
  for (Axis a : kAxes)
    for (double& v : other[a].a) v *= 0.5;
  auto f = simulateGroundFace(p.job.setup, plusError(p.firstRun, other), p.job.grid, Sensitivities::Skip);
  ASSERT_TRUE(f.ok());
  const Eigen::MatrixXd notThisMachine = topographyOf(*f).normal;
  const Correction c = corrected(secondCase(p, true, &notThisMachine));
  const Correction alone = corrected(secondCase(p, false));
  EXPECT_EQ(c.passesJoined, 0);
  EXPECT_NE(c.verdict.find("The search for one machine error explaining this face and the 1 earlier pass's face stalled ("),
            std::string::npos)
      << c.verdict;
  EXPECT_NE(c.verdict.find("identified from this face alone (has the machine or the setup changed?)."), std::string::npos)
      << c.verdict;
  for (Axis a : kAxes)
    for (size_t k = 0; k < c.axes[a].a.size(); ++k) EXPECT_EQ(c.axes[a].a[k], alone.axes[a].a[k]);
}

// Where the wheel is corrected, a dressing may have changed the wheel between passes: the earlier
// faces were ground with another wheel, and the history is not used.
TEST(PassHistory, NotUsedWhereTheWheelMayHaveChanged) {
  const Passes p = twoPasses(206);
  CaseInput c = secondCase(p, true);
  EXPECT_EQ(resolveJob(c)->history.passes.size(), 1u);
  c.correction.wheel = true;
  EXPECT_TRUE(resolveJob(c)->history.empty());
  c.correction.wheel.reset();
  c.passes[0].correction = CorrectionInput{};
  c.passes[0].correction->wheel = true;
  EXPECT_TRUE(resolveJob(c)->history.empty());
  // A pass measured at the measuring machine's own points is not on the grid: not used either.
  c = secondCase(p, true);
  c.passes[0].measured.resize(0, 0);
  c.passes[0].measuredPoints = std::vector<MeasuredPoint>{};
  EXPECT_TRUE(passHistory(c.passes, p.job.nominalAxes, false).empty());
}


// The sentence that sets the history aside says that no one error explains the faces "to the probe
// noise" only when the solve ended above the noise. The campaign's scenario 62 (straight gash,
// 150 µm rms, noise-free, sigma 0.01 µm) with the search over every coefficient held to 2 steps:
// both starts (the error the run compensates, then this face's own estimate) run out, the first
// with 0.0035 µm rms left over both faces, within the noise; it is not kept, and the note says it
// did not converge. (Held to 50 steps before the second start, the first start ran out with
// 2.7e-05 µm rms left and the note said "No one machine error explains ... (has the machine or the
// setup changed?)"; now the second start converges within 5.)
TEST(PassHistory, AJointSolveOutOfStepsIsNotCalledAHistoryNoErrorExplains) {
  const Passes p = twoPasses(62);
  auto job = resolveJob(secondCase(p, true));
  ASSERT_TRUE(job.ok());
  CorrectionOptions o = job->correction;
  o.solver.maxIterationsEveryCoefficient = 2;
  auto face = simulateGroundFace(job->setup, p.secondRun, job->grid);
  ASSERT_TRUE(face.ok());
  auto m = identifyMachineError(job->setup, p.secondRun, *face, p.secondMeasured, o, &job->history);
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m->passesJoined, 0);
  EXPECT_EQ(m->historyNote.find("No one machine error explains"), std::string::npos) << m->historyNote;
  EXPECT_NE(m->historyNote.find("The search for one machine error explaining this face and the 1 earlier pass's face "
                                "did not converge in 2 iterations ("),
            std::string::npos)
      << m->historyNote;
}

// A second pass whose axes alone grind no face the wheel envelops (linearised at the nominal
// axes): identified from the nominal axes, the first pass's axes move as the run's do (by nominal
// - run; measured_face_correction.cpp). The campaign's scenario 110 (150 µm rms): joined, and the
// face left is below 0.1 µm. With the shift's sign turned, it is not joined and leaves 3.2 µm.
TEST(PassHistory, JoinedWhereTheRunIsLinearisedAtTheNominalAxes) {
  auto s = makeScenario(kSeed, 110);
  ASSERT_TRUE(s.ok());
  const ScenarioOutcome o = runScenario(*s);
  ASSERT_GE(o.passes.size(), 2u);
  EXPECT_TRUE(o.passes[1].linearisedAtNominal);
  EXPECT_EQ(o.passes[1].passesJoined, 1) << o.passes[1].verdict;
  EXPECT_LT(o.passes[1].denseRms, 0.1);
}

// What is read of each axis after a joined identification rests on every face, as the error does
// (review finding: it was read from this face's sensitivities alone, with nothing left out).
// Scenario 2 (straight gash, 150 µm rms), second pass: one straight-gash face cannot show X, Y
// or B; the two faces together do, weakly, so every axis is read with the others, none unseen,
// with the spread the faces give it. Per µm of probe noise, X 14,297 µm, Y 433,901 µm, Z 38 µm,
// A 340 µrad, B 22,869 µrad; read from this face's rows alone they were 400 to 40 times that
// (X 5.6e6 µm, Z 1,673 µm).
TEST(PassHistory, WhatIsReadOfTheAxesRestsOnEveryFace) {
  const Passes p = twoPasses(2);
  const Correction joined = corrected(secondCase(p, true));
  ASSERT_EQ(joined.passesJoined, 1);
  EXPECT_TRUE(joined.identified.unseen.empty());
  for (int i = 0; i < kAxisCount; ++i) {
    EXPECT_EQ(joined.identified.axes[i].reading, AxisReading::Together) << "XYZAB"[i];
    EXPECT_TRUE(std::isfinite(joined.changePerNoise[i]) && joined.changePerNoise[i] > 0) << "XYZAB"[i];
  }
  const std::array<double, kAxisCount> atMost{1e5, 4e6, 200, 3000, 2e5};  // µm or µrad per µm of noise
  for (int i = 0; i < kAxisCount; ++i) EXPECT_LT(joined.changePerNoise[i], atMost[i]) << "XYZAB"[i];
}


// The sign against the history (history_sign.h). A measuring machine that signs deviations the
// other way round: its first face is minus the one the machine grinds, the first pass's correction
// from it adds to the error, and the second face (minus the one that proposal grinds) moves against
// the change of the axes. The second pass says so before anything else; with the faces signed as
// the calculator signs them the same two passes agree with it. On the first scenarios of the
// small, medium and large classes (two of each), straight and helical gashes.
TEST(PassHistory, FacesSignedTheOtherWayRoundAreCaughtOnTheSecondPass) {
  int checked = 0;
  for (int index : {0, 1, 2, 6, 7, 8}) {
    SCOPED_TRACE("scenario " + std::to_string(index));
    Passes p;
    CaseInput first = firstCase(p, index);
    // As signed: the second pass agrees with the history.
    {
      const Passes same = twoPasses(index);
      const Correction k = corrected(secondCase(same, true));
      ASSERT_TRUE(k.historySign.has_value()) << k.verdict;
      EXPECT_FALSE(k.signReversed());
      EXPECT_GT(k.historySign->along, 0.8);
      EXPECT_LT(k.historySign->along, 1.2);
      EXPECT_EQ(k.verdict.find("Check the sign"), std::string::npos) << k.verdict;
    }
    // Signed the other way round.
    first.measured = -p.firstMeasured;
    auto e = evaluate(*resolveJob(first));
    ASSERT_TRUE(e.ok() && e->correction);
    EXPECT_FALSE(e->correction->historySign.has_value());  // a first pass has nothing to check against
    const AxisPolynomials secondRun = e->correction->axes;
    CaseInput second = p.s.input;
    second.axes = secondRun;
    second.measured = -groundOnMachine(p, secondRun);
    second.correction.probeNoise = 0.01;
    second.passes.push_back(PassInput{p.firstRun, -p.firstMeasured, {}, {}});
    auto f = evaluate(*resolveJob(second));
    ASSERT_TRUE(f.ok() && f->correction) << (f ? "" : f.error().message);
    const Correction& k = *f->correction;
    ASSERT_TRUE(k.historySign.has_value()) << k.verdict;
    EXPECT_TRUE(k.signReversed());
    EXPECT_LT(k.historySign->along, -0.8);
    EXPECT_GT(k.historySign->along, -1.2);
    EXPECT_EQ(k.verdict.rfind("Check the sign: from the last pass measured on the grid to this one", 0), 0u) << k.verdict;
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

// An earlier pass run with the same axes (as after a pass told to stop, which keeps them) gives the
// check nothing to read, even with its face of the opposite sign: no sign is claimed either way.
TEST(PassHistory, NoSignIsClaimedWhereTheAxesDidNotChange) {
  Passes p;
  CaseInput c = firstCase(p, 0);
  c.passes.push_back(PassInput{p.firstRun, -p.firstMeasured, {}, {}});
  const Correction k = corrected(c);
  EXPECT_FALSE(k.historySign.has_value());
  EXPECT_FALSE(k.signReversed());
}


// The same with the faces measured at the measuring machine's own points (here the centres of the
// grid's cells), which no identification joins: the sign is checked against the last pass
// measured at the same points. And with the linear method, which never joins the history, or an
// axis locked, which keeps the faces from being joined: faces signed as the calculator signs them
// are not called reversed (an independent review, 2026-12-07, found seed 1006's scenario 56 called
// reversed so before the cosine's test; history_sign.h).
// The face `axes` grind on the machine at the centres of the grid's cells (off the grid, so that
// they stay points), µm.
std::vector<MeasuredPoint> atCellCentres(const Passes& p, const AxisPolynomials& axes, double sign) {
  const FaceGrid& g = p.job.grid;
  ProbePoints probes;
  for (int i = 0; i + 1 < g.rows(); ++i)
    for (int j = 0; j + 1 < g.cols(); ++j) probes.push_back(ProbePoint{(g.r[i] + g.r[i + 1]) / 2, (g.x[j] + g.x[j + 1]) / 2});
  auto f = simulateGroundFace(p.job.setup, plusError(axes, p.s.error), probes, g, Sensitivities::Skip);
  EXPECT_TRUE(f.ok());
  std::vector<MeasuredPoint> out;
  if (!f) return out;
  const Eigen::VectorXd d = faceNormal(*f);
  for (size_t k = 0; k < probes.size(); ++k) out.push_back(MeasuredPoint{probes[k].r, probes[k].x, sign * d(static_cast<int>(k))});
  return out;
}

TEST(PassHistory, TheSignIsCheckedAtTheSamePointsToo) {
  for (int index : {1, 7}) {
    SCOPED_TRACE("scenario " + std::to_string(index));
    for (double sign : {1.0, -1.0}) {
      Passes p;
      CaseInput first = firstCase(p, index);
      first.measured.reset();
      first.measuredPoints = atCellCentres(p, p.firstRun, sign);
      auto e = evaluate(*resolveJob(first));
      ASSERT_TRUE(e.ok() && e->correction);
      CaseInput second = p.s.input;
      second.axes = e->correction->axes;
      second.measuredPoints = atCellCentres(p, *second.axes, sign);
      second.correction.probeNoise = 0.01;
      second.passes.push_back(PassInput{p.firstRun, Eigen::MatrixXd(), first.measuredPoints, {}});
      auto f = evaluate(*resolveJob(second));
      ASSERT_TRUE(f.ok() && f->correction) << (f ? "" : f.error().message);
      const Correction& k = *f->correction;
      ASSERT_TRUE(k.historySign.has_value()) << k.verdict;
      EXPECT_EQ(k.signReversed(), sign < 0) << k.verdict;
      EXPECT_EQ(k.verdict.rfind("Check the sign: from the last pass measured at these points", 0) == 0, sign < 0) << k.verdict;
      // Other points than the last pass's: nothing to check against.
      second.measuredPoints->pop_back();
      auto g = evaluate(*resolveJob(second));
      ASSERT_TRUE(g.ok() && g->correction);
      EXPECT_FALSE(g->correction->historySign.has_value());
    }
  }
}

TEST(PassHistory, FacesNotJoinedAreNotCalledReversedWhenSignedAsTheCalculatorSigns) {
  // Seed 1006's scenario 56 (150 µm, helical): its second pass's first-order change reads -4.4 along
  // the predicted one, at a cosine of -0.4.
  const Passes p = twoPasses(56, 1006);
  for (const char* variant : {"linear", "X locked", "B locked"}) {
    SCOPED_TRACE(variant);
    CaseInput c = secondCase(p, true);
    if (std::string(variant) == "linear") c.correction.method = "linear";
    else c.correction.lockedAxes = {std::string(variant) == "X locked" ? Axis::X : Axis::B};
    const Correction k = corrected(c);
    EXPECT_EQ(k.passesJoined, 0);
    ASSERT_TRUE(k.historySign.has_value());
    EXPECT_LT(k.historySign->along, -0.5);
    EXPECT_FALSE(k.signReversed()) << k.verdict;
  }
  // The linear method on faces signed the other way round is still caught.
  Passes q;
  CaseInput first = firstCase(q, 1);
  first.measured = -q.firstMeasured;
  first.correction.method = "linear";
  auto e = evaluate(*resolveJob(first));
  ASSERT_TRUE(e.ok() && e->correction);
  CaseInput second = q.s.input;
  second.axes = e->correction->axes;
  second.measured = -groundOnMachine(q, *second.axes);
  second.correction.probeNoise = 0.01;
  second.correction.method = "linear";
  second.passes.push_back(PassInput{q.firstRun, -q.firstMeasured, {}, {}});
  const Correction k = corrected(second);
  EXPECT_TRUE(k.signReversed()) << k.verdict;
}

}  // namespace
}  // namespace hobsharp::validation
