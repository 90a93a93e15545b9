// Identify, then compensate (docs/method.md, "Correction"): the machine error found by nonlinear least
// squares, the axes nominal - error, judged by re-simulating the face the machine then grinds,
// on the probe grid and on a grid 4 times as dense between the probe points.
#include <cmath>
#include <cstdio>
#include <string>

#include "identification_cases.h"

namespace hobsharp::test {
namespace {

struct Hob {
  const char* name;
  CaseInput (*make)();
  double largest;  // the largest SSE0 tested, µm²
};

// The five hobs of the issue. The module-2 hob's face is 30 mm long and 6 mm deep: most errors of
// 1e6 µm² (136 µm rms) leave it unground at the ends, and at 1e5 µm² one pass leaves 1.3e-4 µm²
// (Module2BeyondFiveE4NeedsASecondPass says why); it is held to the target up to 5e4 µm² in one
// pass (the issue measured it at 2.3e4).
const Hob kHobs[] = {
    {"paper", paperCase, 1e6},
    {"left hand, rake offset", leftHandRakeCase, 1e6},
    {"module 2", module2Case, 5e4},
    {"degree 6 on 11 x 21", degree6Case, 1e6},
    {"straight gash", straightModule4Case, 1e6},
};

struct Pass {
  Correction c;
  Topography onGrid;  // the face ground with c.axes and the true error, on the probe grid
  Topography dense;   // the same, 4 times as dense
};

Pass onePass(const SharpeningJob& job, const AxisPolynomials& run, const AxisPolynomials& error,
             const Eigen::MatrixXd& noise, const CorrectionOptions& o, const Eigen::MatrixXd& shape = {}) {
  Eigen::MatrixXd measured = topographyFor(job, withMachineError(run, error)).normal + noise;
  if (shape.size() > 0) measured += shape;
  auto c = correctMeasuredFace(job.setup, job.nominalAxes, run, groundFaceOf(job, run), measured, o);
  EXPECT_TRUE(c.ok()) << c.error().message;
  Pass p{c.value(), {}, {}};
  p.onGrid = topographyFor(job, withMachineError(p.c.axes, error));
  p.dense = denseFace(job, withMachineError(p.c.axes, error));
  return p;
}

CorrectionOptions noiseFree(const SharpeningJob& job) {
  CorrectionOptions o = job.correction;
  o.probeNoise = 1e-4;  // a simulated what-if, declared as such
  return o;
}

TEST(Identification, NoiseFreeOnePassLeavesBelow1e4OnFiveHobs) {
  for (const Hob& hob : kHobs) {
    const SharpeningJob job = jobOf(hob.make());
    for (double sse : {1e2, 1e4, hob.largest}) {
      SCOPED_TRACE(std::string(hob.name) + ", SSE0 " + std::to_string(sse));
      const AxisPolynomials error = inSpanError(job, sse, 7);
      const Pass p = onePass(job, job.nominalAxes, error, Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()),
                             noiseFree(job));
      EXPECT_NEAR(p.c.before.sse, sse, 1e-6 * sse);
      EXPECT_EQ(p.c.summary.status, SolveStatus::Converged) << p.c.summary.reason;
      EXPECT_TRUE(p.c.summary.IsSolutionUsable());
      EXPECT_GT(p.c.summary.iterations, 0);
      EXPECT_LT(p.onGrid.sse, 1e-4);
      EXPECT_LT(rms(p.dense.normal), 2e-3);  // µm between the probe points
      // The re-simulated prediction is the face the machine grinds.
      EXPECT_NEAR(p.c.after.sse, p.onGrid.sse, 1e-4);
      std::printf("[ figures  ] %-24s SSE0 %7.0e -> %.2e µm² (dense rms %.1e µm), %d iterations, rounded %.3f µm²"
                  " (rank %d, %d within noise, %d amplifying)\n",
                  hob.name, sse, p.onGrid.sse, rms(p.dense.normal), p.c.summary.iterations, p.c.afterRounded.sse,
                  p.c.rank, p.c.withinNoise, p.c.amplifyingDropped);
    }
  }
}

// Beyond 5e4 µm² on the module-2 hob, one pass is not enough, and no one-pass method can be:
// the identified error reproduces the measured face to within the declared noise (the probe grid
// cannot tell it from the true one), yet the two differ in directions the 6 x 9 grid shows only
// near the nominal face. A second pass, measured there, sees them and closes the gap.
TEST(Identification, Module2BeyondFiveE4NeedsASecondPass) {
  const SharpeningJob job = jobOf(module2Case());
  const AxisPolynomials error = inSpanError(job, 1e5, 7);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols());
  const CorrectionOptions o = noiseFree(job);
  const Pass first = onePass(job, job.nominalAxes, error, zero, o);
  const double noiseLevel = job.grid.size() * o.probeNoise * o.probeNoise;  // µm²
  EXPECT_LT(first.c.summary.finalCost, noiseLevel);  // the measured face is explained
  EXPECT_GT(first.onGrid.sse, first.c.summary.finalCost);  // yet the error left is larger
  const Pass second = onePass(job, first.c.axes, error, zero, o);
  // In the engineer's units (issue 20 withdrew the 1e-4 µm² targets): nanometres rms.
  EXPECT_LT(second.onGrid.rms, 2e-3);
  EXPECT_LT(rms(second.dense.normal), 2e-3);
  std::printf("[ figures  ] module 2, SSE0 1e5: fitted to %.1e µm², one pass leaves %.2e, two passes %.2e µm²\n",
              first.c.summary.finalCost, first.onGrid.sse, second.onGrid.sse);
}

// A run that holds moves the identification leaves out (here an earlier linear step's, with a
// coarse A resolution) and leaves a face within the probe noise: the run axes are kept unchanged
// (the stop verdict; before the stop, the correction found here would have ground a worse face,
// and the guard against that, runKept, kept them), and the verdict says so.
TEST(Identification, NeverProposesAWorseFaceThanTheOneMeasured) {
  const SharpeningJob job = jobOf(paperCase());
  AxisPolynomials error = times(job.nominalAxes, 0.0);
  error[Axis::Z].a[0] = -0.01;
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols());
  CorrectionOptions linear = job.correction;
  linear.method = CorrectionMethod::Linear;
  linear.resolution.step[static_cast<int>(Axis::A)] = 0.01;  // deg
  const Pass first = onePass(job, job.nominalAxes, error, zero, linear);
  ASSERT_LT(first.onGrid.sse, 1e-6);
  CorrectionOptions o = noiseFree(job);
  o.resolution = linear.resolution;
  const Pass second = onePass(job, first.c.axes, error, zero, o);
  EXPECT_TRUE(second.c.stop || second.c.runKept);
  for (Axis a : kAxes) EXPECT_EQ(second.c.axes[a].a, first.c.axes[a].a) << axisName(a);
  EXPECT_EQ(second.c.after.sse, second.c.before.sse);
  EXPECT_NEAR(second.onGrid.sse, second.c.before.sse, 1e-9);  // the same axes grind the same face
  EXPECT_TRUE(second.c.verdict.rfind("Stop:", 0) == 0 || second.c.verdict.find("No change proposed") != std::string::npos)
      << second.c.verdict;
  for (double v : second.c.axisChangeSize) EXPECT_EQ(v, 0.0);
  std::printf("[ figures  ] run kept: the discarded proposal predicted %.3g µm², measured %.3g µm²\n",
              second.c.discardedSse, second.c.before.sse);
}

// The paper's linear step, side by side: it leaves ~1.4e-11 SSE0² on the paper hob.
TEST(Identification, LinearMethodStaysAvailableAndIsWorseForLargeErrors) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials error = inSpanError(job, 1e6, 7);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols());
  CorrectionOptions linear = noiseFree(job);
  linear.method = CorrectionMethod::Linear;
  const Pass l = onePass(job, job.nominalAxes, error, zero, linear);
  const Pass n = onePass(job, job.nominalAxes, error, zero, noiseFree(job));
  EXPECT_EQ(l.c.method, CorrectionMethod::Linear);
  EXPECT_EQ(l.c.summary.iterations, 1);
  EXPECT_GT(l.onGrid.sse, 1e-2);
  EXPECT_LT(n.onGrid.sse, 1e-4);
  // The linear step's sseAfter is re-simulated too: its own error model, not the linear prediction.
  EXPECT_GT(l.c.after.sse, 0.0);
  EXPECT_TRUE(std::isfinite(l.c.after.sse));
}

// Pure probe noise of sigma = 1 µm: nothing above the noise, nothing changed.
TEST(Identification, NoiseOnlyLeavesAPerfectFaceWithinAThirdOfTheNoise) {
  for (const Hob& hob : {kHobs[0], kHobs[4]}) {
    const SharpeningJob job = jobOf(hob.make());
    CorrectionOptions o = job.correction;
    o.probeNoise = 1.0;
    const AxisPolynomials none = times(job.nominalAxes, 0.0);
    for (unsigned seed = 1; seed <= 4; ++seed) {
      SCOPED_TRACE(std::string(hob.name) + ", seed " + std::to_string(seed));
      const Pass p = onePass(job, job.nominalAxes, none, probeNoise(job.grid.rows(), job.grid.cols(), 1.0, seed), o);
      EXPECT_LE(rms(p.dense.normal), 0.3);
      EXPECT_LE(rms(p.onGrid.normal), 0.3);
      std::printf("[ figures  ] %-24s noise only, seed %u: dense rms after %.3f µm\n", hob.name, seed, rms(p.dense.normal));
    }
  }
}

// A 5 µm second-degree shape along the radius (the wheel's), with 0.5 µm noise: the axes take
// what they can make with small moves and leave the rest, and say so.
TEST(Identification, RadialShapeIsLeftToTheWheelWithoutWildMoves) {
  for (const Hob& hob : {kHobs[0], kHobs[1], kHobs[4]}) {
    SCOPED_TRACE(hob.name);
    const SharpeningJob job = jobOf(hob.make());
    CorrectionOptions o = job.correction;
    o.probeNoise = 0.5;
    const FaceGrid& g = job.grid;
    Eigen::MatrixXd shape(g.rows(), g.cols());
    for (int i = 0; i < g.rows(); ++i) shape.row(i).setConstant(radialShape(g, g.r[i], 5.0));
    const Pass p = onePass(job, job.nominalAxes, times(job.nominalAxes, 0.0),
                           probeNoise(g.rows(), g.cols(), 0.5, 3), o, shape);
    // The face after the pass still has the wheel's shape: judge face + shape on the dense grid.
    double before = 0, after = 0;
    for (int i = 0; i < p.dense.normal.rows(); ++i)
      for (int j = 0; j < p.dense.normal.cols(); ++j) {
        const double s = radialShape(g, p.dense.grid.r[i], 5.0);
        before += s * s;
        after += std::pow(p.dense.normal(i, j) + s, 2);
      }
    EXPECT_LT(after, before);
    EXPECT_LT(std::abs(p.c.axisChangeSize[static_cast<int>(Axis::B)]), 100.0);  // µrad
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) EXPECT_LT(std::abs(p.c.axisChangeSize[static_cast<int>(a)]), 20.0);
    EXPECT_NE(p.c.verdict.find("wheel profile"), std::string::npos) << p.c.verdict;
    std::printf("[ figures  ] %-24s radial 5 µm: dense SSE %.0f -> %.0f µm², B %.1f µrad\n", hob.name, before, after,
                p.c.axisChangeSize[static_cast<int>(Axis::B)]);
  }
}

// Two passes with fresh noise: the second does not undo the first, and each leaves the face
// within the noise level between the probe points.
TEST(Identification, TwoPassesWithFreshNoiseStayWithinTheNoise) {
  for (const Hob& hob : {kHobs[0], kHobs[4]}) {
    SCOPED_TRACE(hob.name);
    const SharpeningJob job = jobOf(hob.make());
    const double sigma = 0.5;
    CorrectionOptions o = job.correction;
    o.probeNoise = sigma;
    const AxisPolynomials error = inSpanError(job, 1e4, 11);
    const int rows = job.grid.rows(), cols = job.grid.cols();
    const Pass first = onePass(job, job.nominalAxes, error, probeNoise(rows, cols, sigma, 21), o);
    const Pass second = onePass(job, first.c.axes, error, probeNoise(rows, cols, sigma, 22), o);
    EXPECT_LE(rms(first.dense.normal), sigma);
    EXPECT_LE(rms(second.dense.normal), sigma);
    EXPECT_LE(rms(second.onGrid.normal), sigma);
    // The second pass changes each axis by no more than a few standard uncertainties.
    for (int i = 0; i < kAxisCount; ++i)
      EXPECT_LE(std::abs(second.c.axisChangeSize[i]), 4 * second.c.uncertainty[i] + 1e-9) << axisName(kAxes[i]);
    std::printf("[ figures  ] %-24s two passes, sigma 0.5: dense rms %.3f then %.3f µm\n", hob.name,
                rms(first.dense.normal), rms(second.dense.normal));
  }
}

// The structural null space, by construction: X against A on a helical gash, X, Y and B on a
// straight one, and the locks.
TEST(Identification, StructuralNullSpaceIsLeftOut) {
  {
    const SharpeningJob job = jobOf(straightModule4Case());
    const Pass p = onePass(job, job.nominalAxes, inSpanError(job, 1e4, 5),
                           Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()), noiseFree(job));
    for (Axis a : {Axis::X, Axis::Y, Axis::B})
      for (double v : p.c.identifiedError[a].a) EXPECT_EQ(v, 0.0) << axisName(a);
    EXPECT_EQ(p.c.unobservable.size(), 3u * 6u);  // X, Y, B a0..a5, each alone
  }
  {
    const SharpeningJob job = jobOf(paperCase());
    const Pass p = onePass(job, job.nominalAxes, inSpanError(job, 1e4, 5),
                           Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()), noiseFree(job));
    ASSERT_EQ(p.c.unobservable.size(), 5u);
    const double pitch = job.setup.face.screwParameter;
    for (const UnobservableCombination& u : p.c.unobservable) {
      ASSERT_EQ(u.coefficients.size(), 2u);
      EXPECT_NEAR(u.amounts[1], 1 / pitch, 1e-12);
      EXPECT_NE(u.description.find("helicoid"), std::string::npos);
    }
  }
  {
    const SharpeningJob job = jobOf(paperCase());
    CorrectionOptions o = noiseFree(job);
    o.lockedAxes = {Axis::A};
    o.locked = {Coefficient{Axis::B, 2}};
    AxisPolynomials error = times(job.nominalAxes, 0.0);
    error[Axis::A].a[0] = 2e-4;
    error[Axis::Z].a[1] = 3e-3;
    const Pass p = onePass(job, job.nominalAxes, error, Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()), o);
    for (int k = 0; k <= 4; ++k) EXPECT_EQ(p.c.axes[Axis::A].a[k], job.nominalAxes[Axis::A].a[k]);
    EXPECT_EQ(p.c.axes[Axis::B].a[2], job.nominalAxes[Axis::B].a[2]);
    EXPECT_TRUE(p.c.unobservable.empty());  // with A locked, X alone takes the helicoid's turn
    EXPECT_LT(p.onGrid.sse, 1e-4);
  }
}

// A grid with fewer points than identifiable directions (3 x 3 at degree 4, straight gash: 9
// points, 10 directions). A case gives it and is refused, as measured points are: fewer values than
// free coefficients (a 2 x 2 grid at degree 6 was called "Correctable" from 4 values; an independent
// review). The engine, given such a face all the same, corrects it in the directions it shows
// (found by the case fuzzer): the job is resolved without the measurement, which is set after.
TEST(Identification, FewerPointsThanDirections) {
  CaseInput in = straightGashCase();
  in.grid = GridInput{};
  in.grid.radial = 3;
  in.grid.axial = 3;
  Eigen::MatrixXd m(3, 3);
  m << 1.0, 0.75, 0.5, 1.5, 1.25, 1.0, 2.0, 1.75, 1.5;
  in.measured = m;
  auto refused = resolveJob(in);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().field, "measured");
  EXPECT_NE(refused.error().message.find("9 values are too few for the 25 free coefficients of degree 4"), std::string::npos)
      << refused.error().message;
  in.measured.reset();
  SharpeningJob straight = jobOf(in);
  straight.measured = MeasuredFace::onGrid(m);
  auto e = evaluate(straight);
  ASSERT_TRUE(e.ok()) << e.error().message;
  EXPECT_LE(e->correction->rank, 9);
  EXPECT_LE(e->correction->singularValues.size(), 9);
  EXPECT_TRUE(std::isfinite(e->correction->after.sse));
  EXPECT_LT(e->correction->after.sse, e->correction->before.sse);
  // The precision demand of what the face shows (Z and A on a straight gash): a figure, never the 0
  // that would read as perfectly precise (the decomposition of 9 points has fewer singular values
  // than directions); the same with the paper's helical hob on 4 x 4 points (16 against 20).
  EXPECT_GT(e->correction->changePerNoise[static_cast<int>(Axis::Z)], 0);
  EXPECT_GT(e->correction->changePerNoise[static_cast<int>(Axis::A)], 0);
  CaseInput helical = paperCase();
  helical.grid.radial = 4;
  helical.grid.axial = 4;
  SharpeningJob job = jobOf(helical);
  job.measured = MeasuredFace::onGrid(topographyFor(job, withMachineError(job.nominalAxes, inSpanError(job, 100, 5))).normal);
  auto h = evaluate(job);
  ASSERT_TRUE(h.ok()) << h.error().message;
  for (Axis a : kAxes) EXPECT_GT(h->correction->changePerNoise[static_cast<int>(a)], 0) << axisName(a);
}

// The coefficients as the NC program carries them (docs/conventions.md §Machine resolution): 10
// significant digits in mm or deg per deg^k, re-simulated beside the exact proposal. Noise-free,
// the face they grind is the exact proposal's to 0.01 µm rms; the former rule (each coefficient to
// a whole number of position steps at the end of the motion range) was not, which this checks too.
TEST(Identification, RoundedAxesAreWhatTheProgramCarries) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials error = inSpanError(job, 1e4, 3);
  const Pass p = onePass(job, job.nominalAxes, error, Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()),
                         noiseFree(job));
  ASSERT_EQ(job.correction.resolution.coefficientDigits, 10);
  constexpr double kDeg = 180 / 3.14159265358979323846;
  for (Axis a : kAxes)
    for (int k = 0; k <= 4; ++k) {
      // In the program's units: X, Y, Z in mm, A, B in deg, per deg^k of hob rotation (helical).
      const double unit = (isRotary(a) ? kDeg : 1.0) * std::pow(kDeg, -k);
      const double programmed = p.c.roundedAxes[a].a[k] * unit, exact = p.c.axes[a].a[k] * unit;
      EXPECT_LE(std::abs(programmed - exact), 5e-10 * std::abs(exact) * (1 + 1e-6)) << axisName(a) << " a" << k;
      if (programmed == 0) continue;
      const double digits = programmed * std::pow(10.0, 9 - std::floor(std::log10(std::abs(programmed))));
      EXPECT_NEAR(digits, std::round(digits), 1e-4) << axisName(a) << " a" << k << " = " << programmed;
    }
  const Topography exact = topographyFor(job, withMachineError(p.c.axes, error));
  const Topography rounded = topographyFor(job, withMachineError(p.c.roundedAxes, error));
  EXPECT_NEAR(p.c.afterRounded.sse, rounded.sse, 1e-9 + 1e-6 * rounded.sse);
  EXPECT_NEAR(p.c.afterRounded.rms, rounded.rms, 1e-9 + 1e-6 * rounded.rms);
  const double apart = rms(rounded.normal - exact.normal);
  std::printf("rounded axes' face off the exact one: %.3g µm rms; resolution floor %.3g µm rms\n", apart,
              p.c.resolutionFloor);
  EXPECT_LE(apart, 0.01);
  // The former rule, for contrast: it leaves more than the 0.01 µm the test allows.
  const MotionRange range = motionRange(groundFaceOf(job, job.nominalAxes));
  const double reach = std::max(std::abs(range.min), std::abs(range.max));
  AxisPolynomials steps = p.c.axes;
  for (Axis a : kAxes)
    for (int k = 0; k <= 4; ++k) {
      const double step = coefficientStep(job.correction.resolution, Coefficient{a, k}, reach);
      steps[a].a[k] = std::round(steps[a].a[k] / step) * step;
    }
  EXPECT_GT(rms(topographyFor(job, withMachineError(steps, error)).normal - exact.normal), 0.01);
}

// The pass's floor against an independent computation: positions quantised at random (each
// axis's constant offset uniform in +-step/2, all five at once), the face re-simulated by the
// nonlinear model, the mean square over the draws. Within 10 % on the paper's hob and on a straight
// gash (where X and B do not move the face).
TEST(Identification, ResolutionFloorIsWhatQuantisedPositionsLeave) {
  for (const CaseInput& in : {paperCase(), straightModule4Case()}) {
    const SharpeningJob job = jobOf(in);
    const AxisPolynomials error = inSpanError(job, 1e2, 5);
    const Pass p = onePass(job, job.nominalAxes, error, Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()),
                           noiseFree(job));
    const Topography run = topographyFor(job, job.nominalAxes);
    std::mt19937 gen(17);
    std::uniform_real_distribution<double> half(-0.5, 0.5);
    constexpr int kDraws = 1000;
    double meanSquare = 0;
    for (int d = 0; d < kDraws; ++d) {
      AxisPolynomials quantised = job.nominalAxes;
      for (Axis a : kAxes) quantised[a].a[0] += half(gen) * job.correction.resolution.inAxisUnit(a);
      meanSquare += std::pow(rms(topographyFor(job, quantised).normal - run.normal), 2) / kDraws;
    }
    const double monteCarlo = std::sqrt(meanSquare);
    std::printf("%s: resolution floor %.4g µm rms, Monte Carlo %.4g µm rms\n",
                in.hob.gash == GashKind::Straight ? "straight gash" : "paper", p.c.resolutionFloor, monteCarlo);
    EXPECT_GT(p.c.resolutionFloor, 0.001);
    EXPECT_NEAR(p.c.resolutionFloor, monteCarlo, 0.1 * monteCarlo);
  }
}

// The engineer's figures: identified error, change, uncertainty from sigma, precision demand.
TEST(Identification, FiguresPerAxis) {
  const SharpeningJob job = jobOf(paperCase());
  AxisPolynomials error = times(job.nominalAxes, 0.0);
  error[Axis::Z].a[0] = -0.01;  // 10 µm
  error[Axis::B].a[0] = 2e-4;   // 200 µrad: about as many machine steps as Z
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols());
  const Pass p = onePass(job, job.nominalAxes, error, zero, noiseFree(job));
  const int Z = static_cast<int>(Axis::Z), B = static_cast<int>(Axis::B);
  EXPECT_NEAR(p.c.identifiedErrorSize[Z], -10.0, 0.01);  // what the face shows above 3e-4 µm
  EXPECT_NEAR(p.c.identifiedErrorSize[B], 200.0, 1.0);
  for (int i = 0; i < kAxisCount; ++i) {
    EXPECT_NEAR(p.c.axisChangeSize[i], -p.c.identifiedErrorSize[i], 1e-6) << axisName(kAxes[i]);  // run = nominal
    EXPECT_GE(p.c.uncertainty[i], 0.0);
    EXPECT_NEAR(p.c.uncertainty[i], 1e-4 * p.c.changePerNoise[i], 1e-12);
    EXPECT_GT(p.c.facePerAxisError[i], 0.0);
  }
  // Z and B together are seen; X and A, whose constant parts are one helicoid turn, are not moved.
  EXPECT_GT(p.c.changePerNoise[Z], 0.0);
  EXPECT_GT(p.c.changePerNoise[B], 0.0);
  // Z moves the face about 1:1 at some grid point; B with a lever of a few mm (µm per µrad).
  EXPECT_GT(p.c.facePerAxisError[Z], 0.3);
  EXPECT_LT(p.c.facePerAxisError[Z], 1.5);
  EXPECT_GT(p.c.facePerAxisError[B], 1e-3);
  EXPECT_LT(p.c.facePerAxisError[B], 0.1);
  // With noise, the uncertainty is sigma times the change per µm of noise, and it grows with sigma.
  CorrectionOptions noisy = job.correction;
  noisy.probeNoise = 1.0;
  const Pass q = onePass(job, job.nominalAxes, error, probeNoise(job.grid.rows(), job.grid.cols(), 1.0, 9), noisy);
  for (int i = 0; i < kAxisCount; ++i) EXPECT_NEAR(q.c.uncertainty[i], q.c.changePerNoise[i], 1e-12);
  EXPECT_GT(q.c.uncertainty[Z], p.c.uncertainty[Z]);
}

// A solve stopped by its iteration limit returns its status and its best iterate, finite.
TEST(Identification, NonConvergingSolveReturnsItsBestIterate) {
  const SharpeningJob job = jobOf(paperCase());
  CorrectionOptions o = noiseFree(job);
  o.solver.maxIterations = 1;
  o.solver.maxIterationsEveryCoefficient = 1;  // the search over every coefficient that may follow
  const AxisPolynomials error = inSpanError(job, 1e6, 7);
  const Pass p = onePass(job, job.nominalAxes, error, Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()), o);
  EXPECT_EQ(p.c.summary.status, SolveStatus::NoConvergence) << p.c.summary.reason;
  EXPECT_TRUE(p.c.summary.IsSolutionUsable());
  EXPECT_EQ(p.c.summary.iterations, 1);
  EXPECT_TRUE(std::isfinite(p.c.after.sse));
  EXPECT_LT(p.c.after.sse, p.c.before.sse);
  EXPECT_NE(p.c.verdict.find("did not converge"), std::string::npos) << p.c.verdict;
}

TEST(Identification, BadInputIsRefusedWithTheFieldNamed) {
  struct Bad {
    void (*change)(CaseInput&);
    const char* field;
  };
  const Bad bad[] = {
      {[](CaseInput& c) { c.correction.probeNoise = 0.0; }, "correction.probeNoise"},
      {[](CaseInput& c) { c.correction.probeNoise = -1.0; }, "correction.probeNoise"},
      {[](CaseInput& c) { c.correction.probeNoise = std::nan(""); }, "correction.probeNoise"},
      {[](CaseInput& c) { c.correction.probeNoise = INFINITY; }, "correction.probeNoise"},
      {[](CaseInput& c) { c.correction.resolution[0] = 0.0; }, "correction.resolution.X"},
      {[](CaseInput& c) { c.correction.resolution[4] = -1e-4; }, "correction.resolution.B"},
      {[](CaseInput& c) { c.correction.probeNoise = 1e5; }, "correction.probeNoise"},
      {[](CaseInput& c) { c.correction.resolution[1] = 1e-300; }, "correction.resolution.Y"},
      {[](CaseInput& c) { c.correction.resolution[3] = 10.0; }, "correction.resolution.A"},
  };
  for (const Bad& b : bad) {
    CaseInput in = paperCase();
    b.change(in);
    auto job = resolveJob(in);
    ASSERT_FALSE(job.ok()) << b.field;
    EXPECT_EQ(job.error().field, b.field);
    EXPECT_EQ(job.error().message.rfind(std::string(b.field) + ":", 0), 0u) << job.error().message;
  }
  // And from the case file's text.
  const std::string text = readFile("tab1.json");
  const std::string head = text.substr(0, text.rfind('}'));
  auto withCorrection = [&](const std::string& json) { return head + ", \"correction\": " + json + "}"; };
  EXPECT_EQ(parseCase(withCorrection("{\"method\": \"quadratic\"}")).error().field, "correction.method");
  EXPECT_EQ(parseCase(withCorrection("{\"resolution\": {\"C\": 1}}")).error().field, "correction.resolution.C");
  EXPECT_EQ(parseCase(withCorrection("{\"probeNoise\": \"1\"}")).error().field, "correction.probeNoise");
  auto ok = parseCase(withCorrection("{\"method\": \"linear\", \"probeNoise\": 2, \"resolution\": {\"A\": 0.001}}"));
  ASSERT_TRUE(ok.ok()) << ok.error().message;
  const SharpeningJob job = jobOf(*ok);
  EXPECT_EQ(job.correction.method, CorrectionMethod::Linear);
  EXPECT_EQ(job.correction.probeNoise, 2.0);
  EXPECT_EQ(job.correction.resolution.step[3], 0.001);
  EXPECT_EQ(job.correction.resolution.step[0], 0.1);  // the default where not given
}

}  // namespace
}  // namespace hobsharp::test
