// The validation campaign's first 204 scenarios of its default seed (20261125; the default run,
// docs/validation.md, has 600) as a test: each target of issue 20 that the campaign meets is asserted at the share the issue asks
// for; each it does not yet meet is asserted at the share measured at this commit, so that a
// change that makes it worse fails. Natively the run takes about a second.
#include <cstdio>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "campaign.h"
#include "evaluation.h"
#include "face_vectors.h"
#include "ground_face.h"
#include "scenario.h"
#include "topography.h"
#include "sharpening_job.h"

namespace hobsharp::validation {
namespace {

constexpr std::uint64_t kSeed = 20261125;
constexpr int kScenarios = 204;

const Campaign& campaign() {
  static const Campaign c = [] {
    std::vector<ScenarioOutcome> outcomes;
    for (int i = 0; i < kScenarios; ++i) {
      auto s = makeScenario(kSeed, i);
      EXPECT_TRUE(s.ok()) << "scenario " << i << ": " << (s.ok() ? "" : s.error().message);
      if (s) outcomes.push_back(runScenario(*s));
    }
    return summarise(kSeed, std::move(outcomes), 0);
  }();
  return c;
}

// The default campaign's scenario `index`, run (an empty outcome, and a failure, if it cannot be
// made).
ScenarioOutcome outcomeOf(int index) {
  auto s = makeScenario(kSeed, index);
  EXPECT_TRUE(s.ok()) << "scenario " << index;
  return s ? runScenario(*s) : ScenarioOutcome{};
}

// A scenario of any seed, run as the campaign runs it, with each pass's case (the first at least).
struct RunWithCases {
  ScenarioOutcome outcome;
  std::vector<CaseInput> cases;
  bool hasFirstPass() const { return !outcome.passes.empty() && !cases.empty(); }
};
RunWithCases runWithCases(std::uint64_t seed, int index) {
  RunWithCases r;
  auto s = makeScenario(seed, index);
  EXPECT_TRUE(s.ok()) << "seed " << seed << ", scenario " << index;
  if (s) r.outcome = runScenario(*s, &r.cases);
  return r;
}

const ClassSummary& classOf(ScenarioClass k) { return campaign().classes[static_cast<int>(k)]; }

// One test, so that the campaign runs once per CTest run (each test is a process of its own).
TEST(Validation, CampaignTargets) {
  int judged = 0;
  for (const ScenarioOutcome& o : campaign().outcomes) judged += o.judged ? 1 : 0;
  EXPECT_EQ(static_cast<int>(campaign().outcomes.size()), kScenarios);
  EXPECT_GE(judged, kScenarios - 2);  // a random error may leave a judging grid the wheel cannot grind

  // Met: the shares.
  for (const Target& t : classOf(ScenarioClass::Small).targets) EXPECT_GE(t.share(), t.required) << t.what;
  for (const Target& t : classOf(ScenarioClass::Noisy).targets) EXPECT_GE(t.share(), t.required) << t.what;
  EXPECT_GE(campaign().bounds[0].share(), campaign().bounds[0].required) << campaign().bounds[0].what;
  EXPECT_GE(campaign().bounds[1].share(), campaign().bounds[1].required) << campaign().bounds[1].what;
  // The bound informs in 197/216 passes since the second passes are identified from the pass
  // history too (was 191/216, just under the 90 % asked).
  EXPECT_GE(campaign().bounds[2].share(), campaign().bounds[2].required) << campaign().bounds[2].what;

  for (const Target& t : classOf(ScenarioClass::Wheel).targets) EXPECT_GE(t.share(), t.required) << t.what;
  for (const Target& t : classOf(ScenarioClass::NoiseOnly).targets) EXPECT_GE(t.share(), t.required) << t.what;

  // Held at the share measured with g++ -O2 less one scenario (the sanitizer build's clang rounds
  // differently, and a scenario at a threshold may fall either way); not yet met
  // (docs/validation.md): 26/33 of the 95 %, and 29/33 with the rounded axes of its 90 %
  // (25/33 and 27/33 before a search over every coefficient decided its directions on the whole error).
  EXPECT_GE(classOf(ScenarioClass::Medium).targets[0].share(), 25.0 / 33 - 1e-9);
  EXPECT_GE(classOf(ScenarioClass::Medium).targets[1].share(), 28.0 / 33 - 1e-9);
  // Two passes at 150 µm, met: 33/34 here (16/34 before the second pass used the first pass's
  // face, 31/34 before a face above the noise was sought over every coefficient and the search over
  // the pass history got its second start); 93/99 on the whole run.
  for (const Target& t : classOf(ScenarioClass::Large).targets) EXPECT_GE(t.share(), t.required) << t.what;
  // No scenario of any class is refused by the calculator (issue 20: "no scenario is refused").
  // A proposal the machine does not grind in full is counted apart (ClassSummary::unground) and
  // misses its targets.
  for (const ClassSummary& s : campaign().classes) EXPECT_EQ(s.refused, 0) << classTitle(s.kind);
  std::printf("%s", tableText(campaign()).c_str());
}

// The second method for where the conjugate profile turns back (docs/method.md, "The edge of the
// wheel's envelope"): the chords of a profile 2001 points dense, root to tip; the first point
// after which a chord points against the first chord. Nothing when none does.
std::optional<double> denseTurn(const SharpeningJob& job) {
  const SharpeningSetup& q = job.setup;
  auto d = wheelProfile(q.face, q.universal, q.normalSign, evenRadii(job.rootRadius, job.outerRadius, 2001));
  EXPECT_TRUE(d.ok());
  if (!d) return std::nullopt;
  const double dR = d->R[1] - d->R[0], dZ = d->Z[1] - d->Z[0];
  for (size_t k = 1; k + 1 < d->r.size(); ++k)
    if ((d->R[k + 1] - d->R[k]) * dR + (d->Z[k + 1] - d->Z[k]) * dZ < 0) return d->r[k];
  return std::nullopt;
}

// Seed 2026's scenario 311: a hob whose conjugate wheel profile turns back 0.077 mm below the tip.
// The setup's wheelEdge (the meridian speed's sign on the 41 profile points, wheel_profile_turn.h)
// lies within one spacing of the dense chords' turn. Its first pass's trial faces with a wheel
// shape fail past the edge: the identification stalled, and says so, not that the shape left is
// one no axis nor wheel makes. Its second pass's case records the first pass's dressing, which
// cannot be simulated past the edge: refused, at the setup's tilt, saying why.
TEST(Validation, AWheelProfileThatTurnsBackBelowTheTipIsFoundAndSaid) {
  auto s = makeScenario(2026, 311);
  ASSERT_TRUE(s.ok());
  auto job = resolveJob(s->input);
  ASSERT_TRUE(job.ok()) << job.error().message;
  ASSERT_TRUE(job->setup.wheelEdge.has_value());
  const double turn = job->setup.wheelEdge->turnRadius, tip = job->outerRadius;
  EXPECT_EQ(job->setup.wheelEdge->outerRadius, tip);
  EXPECT_GT(turn, tip - 0.1);
  EXPECT_LT(turn, tip - 0.05);
  const auto dense = denseTurn(*job);
  ASSERT_TRUE(dense.has_value()) << "the dense profile runs one way to the tip";
  EXPECT_NEAR(*dense, turn, 1.5 * (tip - job->rootRadius) / 2000);

  const ScenarioOutcome o = runScenario(*s);
  ASSERT_EQ(o.passes.size(), 2u);
  EXPECT_EQ(o.passes[0].status, "stalled");
  EXPECT_NE(o.passes[0].verdict.find("faces the wheel cannot grind"), std::string::npos) << o.passes[0].verdict;
  EXPECT_TRUE(o.passes[1].refused);
  EXPECT_EQ(o.passes[1].message.rfind("Setup: a dressed wheel cannot be simulated near r = 23.992 mm", 0), 0u)
      << o.passes[1].message;
  EXPECT_NE(o.passes[1].message.find("The wheel cannot grind the top 0.077 mm of the face as designed"), std::string::npos)
      << o.passes[1].message;
  EXPECT_EQ(o.passes[1].message.find("Wheel file"), std::string::npos) << o.passes[1].message;
}

// The hobs of the default campaign's 600 scenarios: the setup's wheelEdge is found exactly where
// the dense chords turn back, within one of their spacings (scenarios 187, 196 and 426 turn, 196
// by 0.009 mm below the tip; the others reach it).
TEST(Validation, TheEdgeIsFoundWhereADenseProfileTurnsBack) {
  std::vector<int> turned;
  for (int i = 0; i < 600; ++i) {
    auto s = makeScenario(kSeed, i);
    ASSERT_TRUE(s.ok());
    auto job = resolveJob(s->input);
    ASSERT_TRUE(job.ok());
    const auto dense = denseTurn(*job);
    const auto& edge = job->setup.wheelEdge;
    EXPECT_EQ(edge.has_value(), dense.has_value()) << "scenario " << i;
    if (!edge || !dense) continue;
    turned.push_back(i);
    EXPECT_NEAR(edge->turnRadius, *dense, 1.5 * (job->outerRadius - job->rootRadius) / 2000) << "scenario " << i;
  }
  EXPECT_EQ(turned, (std::vector<int>{187, 196, 426}));
}

// Scenario 452 of the default seed (150 µm rms, two passes): after the first pass the axes it
// proposes, run alone, grind no face the wheel envelops; the machine, with its error, did grind
// one. The second pass is not refused: it is linearised at the nominal axes and corrects the face.
TEST(Validation, ASecondPassWhoseAxesAloneCannotBeSimulatedIsCorrected) {
  auto s = makeScenario(kSeed, 452);
  ASSERT_TRUE(s.ok());
  const ScenarioOutcome o = runScenario(*s);
  ASSERT_EQ(o.passes.size(), 2u);
  EXPECT_TRUE(o.passes[1].ground()) << o.passes[1].message;
  EXPECT_TRUE(o.passes[1].linearisedAtNominal);
  EXPECT_LT(o.passes[1].denseRms, 0.1);
  EXPECT_LE(o.passes[1].probeRms, o.passes[1].predictedRmsHigh);
}

// Scenario 182 (150 µm rms): over the identifiable space the first pass's identification stalls
// (54 µm rms left between the probe points); sought over every coefficient it converges
// (test_pass_history.cpp): with its directions decided on the whole error it does not (4 wild
// directions left out, 0.30 µm² left), and decided once more on the misfit left it does
// (machine_error.cpp). Neither pass is refused, and the second pass ends below 0.1 µm.
TEST(Validation, AStalledFirstPassIsSoughtOverEveryCoefficientNotRefused) {
  auto s = makeScenario(kSeed, 182);
  ASSERT_TRUE(s.ok());
  const ScenarioOutcome o = runScenario(*s);
  ASSERT_EQ(o.passes.size(), 2u);
  EXPECT_TRUE(o.passes[0].ground()) << o.passes[0].message;
  EXPECT_EQ(o.passes[0].status, "converged");
  EXPECT_LT(o.passes[0].denseRms, 0.2 * o.initialDenseRms);
  EXPECT_TRUE(o.passes[1].ground()) << o.passes[1].message;
  EXPECT_LT(o.passes[1].denseRms, 0.1);
}

// A bound above the face measured is said in words. Scenario 152 (straight gash, 150 µm rms):
// the first proposal's bound, 161 µm rms, is above the 137 µm measured, and with some of the
// sampled errors the face cannot show the wheel would not reach part of the face; the module, as
// the machine, cannot simulate the face the proposal grinds either. Scenario 0's proposal (3 µm
// rms) is bounded well below its face and says nothing of the kind.
TEST(Validation, ABoundAboveTheFaceMeasuredIsSaid) {
  const ScenarioOutcome o = outcomeOf(152);
  ASSERT_GE(o.passes.size(), 1u);
  const PassOutcome& p = o.passes[0];
  EXPECT_GT(p.predictedRmsHigh, p.measuredRms);
  // The verdict leads with it.
  EXPECT_EQ(p.verdict.rfind("Uncertain: the face does not show enough of the machine's error to say that this pass "
                            "improves it; the face measured",
                            0),
            0u)
      << p.verdict;
  EXPECT_NE(p.verdict.find("part of it would stay unground"), std::string::npos) << p.verdict;
  const ScenarioOutcome q = outcomeOf(0);
  ASSERT_GE(q.passes.size(), 1u);
  EXPECT_LT(q.passes[0].predictedRmsHigh, q.passes[0].measuredRms);
  EXPECT_EQ(q.passes[0].verdict.rfind("Correctable: ", 0), 0u) << q.passes[0].verdict;
}

// "The wheel would not reach part of the face" counts only sampled errors with which the face the
// pass grinds cannot be simulated. Scenario 452 (helical gash, 150 µm rms): the first proposal's
// bound is above the face measured, and 3 of its 6 sampled errors make the face measured one the
// module cannot simulate, none the face the pass grinds; the pass is ground (not refused). Those 3
// made the verdict say that part of the face would stay unground. (The fold check, which asks
// another question, warns here: a point near the root is within its margin; face_prediction.h.)
TEST(Validation, OnlyThePassFaceUngroundIsSaidToStayUnground) {
  const ScenarioOutcome o = outcomeOf(452);
  ASSERT_GE(o.passes.size(), 1u);
  const PassOutcome& p = o.passes[0];
  EXPECT_TRUE(p.ground()) << p.message;
  EXPECT_GT(p.predictedRmsHigh, p.measuredRms);
  EXPECT_NE(p.verdict.rfind("Uncertain: the face does not show enough", 0), std::string::npos) << p.verdict;
  EXPECT_EQ(p.verdict.find("the wheel would not reach part of the face"), std::string::npos) << p.verdict;
}

// A proposal judged on a grid that reaches past the edge of the wheel's envelope names the band in
// its verdict (wheel_profile_turn.h). Seed 7003's scenario 259 (30 µm class, helical gash; the
// conjugate profile turns back 0.27 mm below the tip): the true machine grinds the proposal
// everywhere but in that band (at the tip's probe row), and the verdict said "Correctable" with no word of it
// (docs/validation.md, "Three more seeds"); the fold check now makes it "Uncertain:" and names a
// point of the band's row (face_prediction.h). The same case on a grid that stops below the turn
// (the measured numbers unchanged) carries no such sentence: the band is off the face judged; and
// so with measured points, judged by the highest point.
TEST(Validation, AVerdictOnAFacePastTheWheelEdgeNamesTheBand) {
  const RunWithCases run = runWithCases(7003, 259);
  ASSERT_TRUE(run.hasFirstPass());
  const PassOutcome& p = run.outcome.passes[0];
  const std::vector<CaseInput>& cases = run.cases;
  EXPECT_TRUE(p.unground) << "the true machine leaves part of the band unground";
  // At the tip's probe row, in the band.
  EXPECT_NE(p.message.find("cannot be solved at the grid point r = 22.9534 mm"), std::string::npos) << p.message;
  const std::string band =
      "The top 0.27 mm of the face, above r = 22.6842 mm, lies past the edge of the wheel's envelope: the figures "
      "given for the face do not hold in that band, and the machine may leave part of it unground.";
  EXPECT_EQ(p.verdict.rfind("Uncertain: ", 0), 0u) << p.verdict;
  EXPECT_NE(p.verdict.find("the wheel may stop reaching the face near r = 23 mm"), std::string::npos) << p.verdict;
  EXPECT_NE(p.verdict.find(band), std::string::npos) << p.verdict;

  auto job = resolveJob(cases[0]);
  ASSERT_TRUE(job.ok()) << job.error().message;
  ASSERT_TRUE(job->setup.wheelEdge.has_value());
  const double turn = job->setup.wheelEdge->turnRadius;
  ASSERT_GT(job->grid.r.back(), turn);
  CaseInput below = cases[0];
  below.grid.rMax = turn - 0.01;
  auto lower = resolveJob(below);
  ASSERT_TRUE(lower.ok()) << lower.error().message;
  auto e = evaluate(*lower);
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->correction.has_value());
  EXPECT_FALSE(e->correction->keepsRun()) << e->correction->verdict;
  EXPECT_EQ(e->correction->verdict.find("past the edge"), std::string::npos) << e->correction->verdict;

  // The same measurement as a measuring machine's points just off the grid (measured_points.h):
  // judged by the highest point's radius, with the band's points and without them.
  const auto pointsCase = [&](bool withBand) {
    CaseInput c = cases[0];
    const Eigen::MatrixXd grid = *c.measured;
    c.measured.reset();
    std::vector<MeasuredPoint> points;
    for (int i = 0; i < grid.rows(); ++i)
      for (int j = 0; j < grid.cols(); ++j) {
        const double r = job->grid.r[static_cast<size_t>(i)] + (i == 0 ? 0.01 : -0.01), x = 0.99 * job->grid.x[static_cast<size_t>(j)];
        if (withBand || r < turn) points.push_back(MeasuredPoint{r, x, grid(i, j)});
      }
    c.measuredPoints = points;
    return c;
  };
  for (bool withBand : {true, false}) {
    auto pj = resolveJob(pointsCase(withBand));
    ASSERT_TRUE(pj.ok()) << pj.error().message;
    auto pe = evaluate(*pj);
    ASSERT_TRUE(pe.ok()) << pe.error().message;
    ASSERT_TRUE(pe->correction.has_value() && pe->correction->atProbes());
    EXPECT_FALSE(pe->correction->keepsRun()) << pe->correction->verdict;
    EXPECT_EQ(pe->correction->verdict.find(withBand ? band : "past the edge") != std::string::npos, withBand)
        << pe->correction->verdict;
  }
}

// A proposal with which some of the errors the face cannot show leave part of the face unground is
// "Uncertain" and says so, even where its bound lies below the face measured (correction.h,
// uncertain()). Seed 7005's scenario 344 (150 µm rms, straight gash): the bound is 106 of 149 µm,
// the bound's samples in the directions the face cannot show leave part of the face unground, and
// so does the true machine, at the hob's end. It said "Correctable" with no word of it before.
TEST(Validation, AProposalThatMayLeavePartUngroundIsUncertainWhateverItsBound) {
  const RunWithCases run = runWithCases(7005, 344);
  ASSERT_TRUE(run.hasFirstPass());
  const PassOutcome& p = run.outcome.passes[0];
  EXPECT_TRUE(p.unground) << "the true machine leaves part of the face unground";
  EXPECT_NE(p.message.find("x = 21.2737 mm"), std::string::npos) << "at the hob's end: " << p.message;
  EXPECT_LT(p.predictedRmsHigh, p.measuredRms) << "a bound below the face measured";
  EXPECT_EQ(p.verdict.rfind("Uncertain: ", 0), 0u) << p.verdict;
  EXPECT_NE(p.verdict.find("the wheel would not reach part of the face (part of it would stay unground)"), std::string::npos)
      << p.verdict;

  auto job = resolveJob(run.cases[0]);
  ASSERT_TRUE(job.ok()) << job.error().message;
  auto e = evaluate(*job);
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->correction.has_value());
  const Correction& c = *e->correction;
  EXPECT_GT(c.predictedUngrindable, 0);
  EXPECT_LE(c.predictedRmsHigh, c.before.rms);
  EXPECT_TRUE(c.uncertain());
  // The bound alone does not make it so: the same correction with every sample ground, and no point
  // near a fold, is not.
  Correction ground = c;
  ground.predictedUngrindable = 0;
  ground.predictedFoldAt.reset();
  EXPECT_FALSE(ground.uncertain());
}

// The fold check (face_prediction.h, fold_margin.h): seed 1013's scenario 325 (30 µm class). Its
// bound lay below the face measured, every sampled error ground the face, and the verdict said
// "Correctable"; the true machine does not grind the proposal at the probe point r = 17.673 mm,
// x = 27.7019 mm (the envelope's solution there meets another and both vanish). With an error the
// face cannot show, of the samples' radius, the point's envelope determinant may reach 0 to first
// order: the verdict is "Uncertain:" and names that point.
TEST(Validation, AProposalNearAFoldIsUncertainAndNamesThePoint) {
  const RunWithCases run = runWithCases(1013, 325);
  ASSERT_TRUE(run.hasFirstPass());
  const PassOutcome& p = run.outcome.passes[0];
  EXPECT_TRUE(p.unground) << "the true machine leaves part of the face unground";
  EXPECT_NE(p.message.find("r = 17.673 mm, x = 27.7019 mm"), std::string::npos) << p.message;
  EXPECT_LT(p.predictedRmsHigh, p.measuredRms) << "a bound below the face measured";
  EXPECT_LT(p.foldMargin, 1);
  EXPECT_EQ(p.verdict.rfind("Uncertain: ", 0), 0u) << p.verdict;
  EXPECT_NE(p.verdict.find("the wheel may stop reaching the face near r = 17.7 mm, x = 27.7 mm (part of it would stay "
                           "unground)"),
            std::string::npos)
      << p.verdict;
  EXPECT_EQ(p.verdict.find("the wheel would not reach part of the face"), std::string::npos) << p.verdict;
}

// A wheel-class scenario of the committed seed, run (no outcome if it is not one).
ScenarioOutcome runWheelScenario(int index, std::uint64_t seed = kSeed) {
  auto s = makeScenario(seed, index);
  EXPECT_TRUE(s.ok() && s->spec.wheel) << "seed " << seed << ", scenario " << index;
  return s.ok() && s->spec.wheel ? runScenario(*s) : ScenarioOutcome{};
}

// The pass was ground, the face it leaves lies within its bound, and the bound informs (at most
// 10 times that face plus 0.02 µm).
void expectBoundHoldsAndInforms(const PassOutcome& p) {
  EXPECT_TRUE(p.ground()) << p.message;
  EXPECT_LE(p.probeRms, p.predictedRmsHigh);
  EXPECT_LE(p.predictedRmsHigh, 10 * p.probeRms + 0.02);
}

// The bound on a pass with the wheel's shape identified alongside (face_prediction.h,
// fromResimulated). Scenario 35 (wheel class): the faces each sampled error moves are measured
// from faces re-simulated without it; measured from the model's faces, which hold the wheel's
// identified shape, the shape (1.08 µm rms) read as a move of the face, and the bound was 1.07 µm
// where the pass leaves 0.0025 µm. Now it holds and informs (at most 10 times the face left plus
// 0.02 µm) on both passes.
TEST(Validation, TheBoundWithTheWheelMeasuresMovesFromResimulatedFaces) {
  const ScenarioOutcome o = runWheelScenario(35);
  ASSERT_EQ(o.passes.size(), 2u);
  for (const PassOutcome& p : o.passes) expectBoundHoldsAndInforms(p);
}

// The bound with a wheel shape the face cannot tell from the axes' motion (face_prediction.h,
// `mimicking`). Scenario 377 (wheel class): the machine's wheel is a slope along its radius, -2 to
// +2.3 µm, which the axes make nearly as well; the identification gives it to the axes (W within
// 0.01 µm of 0), and their mimicry holds at the measurement but not at the axes proposed. The
// first pass leaves 0.515 µm on the probe grid; the bound sampled only the directions the face
// cannot show and said 0.033 µm. With the error less twice its part along the mimicking axis
// changes (the wheel taking it) it holds, still informs, and the verdict names the assumption.
TEST(Validation, TheBoundSamplesTheWheelShapeTheAxesMimic) {
  const ScenarioOutcome o = runWheelScenario(377);
  ASSERT_GE(o.passes.size(), 1u);
  const PassOutcome& p = o.passes[0];
  EXPECT_GT(p.probeRms, 0.3);
  expectBoundHoldsAndInforms(p);
  EXPECT_NE(p.verdict.find("or cannot tell from the wheel's shape"), std::string::npos) << p.verdict;
}

// The calculator's own proposal is a run its next pass takes: on seed 20261125's scenario 314 (150
// µm, straight gash) the first pass moves Y by up to 64 mm over the motion (an axis the face hardly
// shows), and a 50 mm limit on axes run (run_axes.h) refused the second pass, which reaches 0.02 µm.
TEST(Validation, AFirstProposalFarOnAnUnseenAxisIsTakenAsTheNextRun) {
  auto s = makeScenario(20261125, 314);
  ASSERT_TRUE(s.ok());
  const ScenarioOutcome o = runScenario(*s);
  ASSERT_EQ(o.passes.size(), 2u);
  for (const PassOutcome& p : o.passes) EXPECT_FALSE(p.refused) << p.message;
  EXPECT_LT(o.passes.back().denseRms, 0.1);
}

// A wheel dressing below the machine's position resolution is told as none ("needs no dressing"),
// while the figures after the pass take it dressed: the bound takes the wheel left undressed
// (wheel_correction.cpp). Seed 4711's scenario 455 (wheel class), its first pass: the dressing
// proposed is at most 0.085 µm; the bound said 0.0134 µm and the face ground as the verdict says,
// undressed, leaves about 0.06 µm (an independent review found 7 of 14 such passes above it).
TEST(Validation, AWheelLeftUndressedAsToldStaysWithinTheBound) {
  auto s = makeScenario(4711, 455);
  ASSERT_TRUE(s.ok() && s->spec.wheel && s->wheelError);
  CaseInput machine = s->input;  // the machine's wheel: the case's, with the wheel error
  machine.wheelProfileOffset = *s->wheelError;
  auto onMachine = resolveJob(machine);
  auto job = resolveJob(s->input);
  ASSERT_TRUE(onMachine.ok() && job.ok());
  auto ground = simulateGroundFace(onMachine->setup, plusError(job->nominalAxes, s->error), job->grid, Sensitivities::Skip);
  ASSERT_TRUE(ground.ok());
  CaseInput c = s->input;
  c.measured = topographyOf(*ground).normal;
  c.correction.probeNoise = 0.01;
  c.correction.wheel = true;
  auto e = evaluate(*resolveJob(c));
  ASSERT_TRUE(e.ok() && e->correction && e->wheelCorrection);
  const Correction& k = *e->correction;
  EXPECT_NE(k.verdict.find("the wheel needs no dressing (the offset proposed is at most"), std::string::npos) << k.verdict;
  EXPECT_NE(k.verdict.find("the bound takes the wheel left undressed"), std::string::npos) << k.verdict;
  EXPECT_GT(e->wheelCorrection->largestOffset, 0.05);
  EXPECT_LT(e->wheelCorrection->largestOffset, 0.1);
  auto undressed = simulateGroundFace(onMachine->setup, plusError(k.axes, s->error), job->grid, Sensitivities::Skip);
  ASSERT_TRUE(undressed.ok());
  const double left = topographyOf(*undressed).rms;
  EXPECT_GT(left, 0.03);  // the undressed wheel's part shows
  EXPECT_LE(left, k.predictedRmsHigh);
}

// A later wheel pass starts its search at the error its run compensates (wheel_error.h). Seed 9401's
// scenario 575 (wheel class, helical gash): the first pass leaves 0.103 µm on the probe grid. The
// second pass's search started at E = 0 found another error that explains that face (a wheel slope
// of -54 to +54 µm and the axis changes that mimic it), and its proposal left the true machine
// 7.6 µm where the bound said 0.845 µm. Started at the first pass's error, it changes the axes and
// the wheel by fractions of a micrometre, leaves less than it found, and within its bound.
TEST(Validation, ALaterWheelPassStartsAtTheErrorItsRunCompensates) {
  const ScenarioOutcome o = runWheelScenario(575, 9401);
  ASSERT_EQ(o.passes.size(), 2u);
  const PassOutcome& second = o.passes[1];
  ASSERT_TRUE(second.ground()) << second.message;
  EXPECT_LT(second.measuredRms, 0.2);
  EXPECT_LT(second.probeRms, second.measuredRms);
  EXPECT_LT(second.denseRms, 0.1);
  EXPECT_LE(second.probeRms, second.predictedRmsHigh);
}

// A later wheel pass whose search from the earlier error runs out of iterations is sought once more
// from E = 0, and the one that explains the face better is kept (wheel_error.h). Seed 1005's
// scenario 293: from the first pass's error the search ran out of iterations, and its proposal left
// the true machine 172 µm from a face of 0.942 µm, with a bound of 1,650 µm. The search from E = 0
// explains the face better; its proposal (bound 2.5 µm) is one the true machine does not grind in
// full, told "Uncertain:", as before the start at the earlier error.
TEST(Validation, ALaterWheelPassOutOfIterationsFromTheEarlierErrorIsSoughtFromZeroToo) {
  const ScenarioOutcome o = runWheelScenario(293, 1005);
  ASSERT_EQ(o.passes.size(), 2u);
  const PassOutcome& second = o.passes[1];
  EXPECT_LT(second.measuredRms, 1.0);
  EXPECT_LT(second.predictedRmsHigh, 10.0);
  EXPECT_FALSE(second.ground() && second.probeRms > 10.0) << second.probeRms;
  EXPECT_EQ(second.verdict.rfind("Uncertain:", 0), 0u) << second.verdict;
}

// Scenario 97 (30 µm rms): trial faces the wheel cannot grind along the way (rejected steps, not
// an error); the best iterate comes back with its status, and the pass improves the face.
TEST(Validation, TrialFacesThatCannotBeGroundAreRejectedStepsNotErrors) {
  auto s = makeScenario(kSeed, 97);
  ASSERT_TRUE(s.ok());
  const ScenarioOutcome o = runScenario(*s);
  ASSERT_EQ(o.passes.size(), 1u);
  EXPECT_TRUE(o.passes[0].ground()) << o.passes[0].message;
  EXPECT_GT(o.passes[0].unsolvableTrials, 0);
  EXPECT_FALSE(o.passes[0].status.empty());
  EXPECT_LT(o.passes[0].denseRms, 0.1 * o.initialDenseRms);
}

// A miss one face cannot avoid (campaign.h, ClassSummary::twins). Scenario 97 (30 µm rms, a
// straight gash, degree 6 on 8 x 8) misses 0.1 µm: the machine whose error is the identified one
// grinds a face within the declared probe noise (0.01 µm rms) of the one measured, yet the
// proposed axes leave the two machines' faces 0.75 µm apart. A twin further off the measurement,
// or nearer the true machine, is not counted; nor is a scenario that meets the limit.
TEST(Validation, AOnePassMissWithATwinMachineIsCounted) {
  ScenarioOutcome o = outcomeOf(97);
  ASSERT_EQ(o.passes.size(), 1u);
  const PassOutcome& p = o.passes[0];
  EXPECT_GT(p.denseRms, 0.2);
  EXPECT_GE(p.twinMisfit, 0);
  EXPECT_LE(p.twinMisfit, p.probeNoise);
  EXPECT_GT(p.twinGap, 0.2);
  const auto medium = [](std::vector<ScenarioOutcome> os) {
    return summarise(kSeed, std::move(os), 0).classes[static_cast<int>(ScenarioClass::Medium)];
  };
  EXPECT_EQ(medium({o}).misses, 1);
  EXPECT_EQ(medium({o}).twins, 1);
  ScenarioOutcome far = o;
  far.passes[0].twinMisfit = 2 * p.probeNoise;
  EXPECT_EQ(medium({far}).twins, 0);
  ScenarioOutcome near = o;
  near.passes[0].twinGap = 0.15;
  EXPECT_EQ(medium({near}).twins, 0);
  ScenarioOutcome met = o;
  met.passes[0].denseRms = 0.05;
  EXPECT_EQ(medium({met}).misses, 0);
  EXPECT_EQ(medium({met}).twins, 0);
}

// What one pass cannot reach without the error's part that no face shows to first order
// (run_scenario.h, nullPartRms; campaign.h, ClassSummary::nullPartMisses). Scenario 37 (30 µm rms,
// a straight gash): its X, Y and B terms alone, the rest corrected exactly, leave 2.3 µm between
// the probe points. Scenario 1 (30 µm rms, a helical gash): X against A turns the helicoid along
// itself, so that part leaves nothing. One of the two is counted; at 0.05 µm, neither.
TEST(Validation, TheErrorsPartNoFaceShowsIsMeasuredAndCounted) {
  const ScenarioOutcome straight = outcomeOf(37), helical = outcomeOf(1);
  ASSERT_FALSE(straight.passes.empty());
  ASSERT_FALSE(helical.passes.empty());
  EXPECT_GT(straight.passes[0].nullPartRms, 1.0);
  EXPECT_LT(straight.passes[0].nullPartRms, straight.initialDenseRms);
  EXPECT_GE(helical.passes[0].nullPartRms, 0);
  EXPECT_LT(helical.passes[0].nullPartRms, 1e-6);
  const auto medium = [](std::vector<ScenarioOutcome> os) {
    return summarise(kSeed, std::move(os), 0).classes[static_cast<int>(ScenarioClass::Medium)];
  };
  const ClassSummary both = medium({straight, helical});
  EXPECT_EQ(both.nullPartOf, 2);
  EXPECT_EQ(both.nullPartMisses, 1);
  ScenarioOutcome small = straight;
  small.passes[0].nullPartRms = 0.05;
  EXPECT_EQ(medium({small, helical}).nullPartMisses, 0);
  // A wheel scenario's first pass and a later pass are not measured.
  const ScenarioOutcome wheel = outcomeOf(5);
  ASSERT_FALSE(wheel.passes.empty());
  EXPECT_EQ(wheel.passes[0].nullPartRms, -1);
  const ScenarioOutcome large = outcomeOf(2);
  ASSERT_EQ(large.passes.size(), 2u);
  EXPECT_GE(large.passes[0].nullPartRms, 0);
  EXPECT_EQ(large.passes[1].nullPartRms, -1);
}

}  // namespace
}  // namespace hobsharp::validation
