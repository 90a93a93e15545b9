// Eq. 17: one correction step by truncated SVD, then re-simulation.
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>

#include "correction.h"
#include "test_support.h"

namespace hobsharp::test {
namespace {

// A machine error in the span of the coefficients, of the paper's size.
AxisPolynomials machineError(const AxisPolynomials& nominal) {
  AxisPolynomials e = nominal;
  e[Axis::Y].a[0] += 0.01;
  e[Axis::Z].a[0] -= 0.01;
  e[Axis::Z].a[1] += 0.003;
  e[Axis::A].a[0] += 0.0002;
  e[Axis::B].a[0] += 0.0005;
  e[Axis::B].a[2] += 0.001;
  return e;
}

// The machine adds its error to whatever is commanded.
AxisPolynomials withError(AxisPolynomials commanded, const AxisPolynomials& nominal, const AxisPolynomials& err) {
  for (Axis a : kAxes)
    for (size_t k = 0; k < commanded[a].a.size(); ++k) commanded[a].a[k] += err[a].a[k] - nominal[a].a[k];
  return commanded;
}

// Tab. 1's case on a 6 x 8 grid, which has no node at its centre.
SharpeningJob evenGridJob() {
  CaseInput even = paperCase();
  even.grid.radial = 6;
  even.grid.axial = 8;
  return jobOf(even);
}

// Probe points at shares of the grid's radial span and of its axial half-length.
ProbePoints probesAt(const SharpeningJob& job, std::initializer_list<double> radial, std::initializer_list<double> axial) {
  ProbePoints probes;
  for (double r : radial)
    for (double x : axial)
      probes.push_back({job.grid.r.front() + r * (job.grid.r.back() - job.grid.r.front()), x * job.grid.x.back()});
  return probes;
}

TEST(Correction, OneStepCancelsAnErrorInTheSpanOfTheCoefficients) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  const AxisPolynomials error = machineError(nominal);
  const Topography measured = topographyFor(job, error);
  EXPECT_GT(measured.sse, 3e3);  // around 10^4 µm^2 on the 9 x 5 grid
  EXPECT_LT(measured.sse, 3e4);

  auto c = correctionStep(groundFaceOf(job, nominal), nominal, measured.normal, CorrectionOptions{});
  ASSERT_TRUE(c.ok()) << c.error().message;
  EXPECT_NEAR(c->before.sse, measured.sse, 1e-9);
  EXPECT_LT(c->after.sse, 1e-3);  // predicted, linear
  EXPECT_LT(std::abs(c->after.thickness), 0.05);
  EXPECT_EQ(c->rank, 20);
  EXPECT_NE(c->verdict.find("Correctable"), std::string::npos);

  // Re-simulate what the machine grinds with the corrected program.
  const Topography after = topographyFor(job, withError(c->axes, nominal, error));
  EXPECT_LT(after.sse, 0.01) << "from " << measured.sse;
  EXPECT_LT(std::abs(after.thickness), 0.05);
}

// Eq. 16's thickness row is the derivative of its datum: the thickness the step predicts is the one
// its predicted face reads (interpolated at the centre of a grid with no node there, the probe
// nearest the mean point at probe points). Before, the row was the mean point's own sensitivity,
// which on these faces the datum's reading misses by a share of the column.
TEST(Correction, TheThicknessRowReadsTheFaceAsTheDatumDoes) {
  const SharpeningJob job = evenGridJob();
  const AxisPolynomials& nominal = job.nominalAxes;
  const AxisPolynomials error = machineError(nominal);
  const GroundFace onGrid = groundFaceOf(job, nominal);
  const ProbePoints probes = probesAt(job, {0.3, 0.55, 0.8}, {-0.7, -0.2, 0.35, 0.9});
  const GroundFace atProbes = simulateGroundFace(job.setup, nominal, probes, job.grid).value();
  for (const GroundFace* run : {&onGrid, &atProbes}) {
    SCOPED_TRACE(run->atProbes() ? "probe points" : "6 x 8 grid");
    auto measured = run->atProbes() ? simulateGroundFace(job.setup, withError(nominal, nominal, error), probes, job.grid)
                                    : simulateGroundFace(job.setup, withError(nominal, nominal, error), job.grid);
    ASSERT_TRUE(measured.ok());
    auto c = correctionStep(*run, nominal, topographyOf(*measured).normal, CorrectionOptions{});
    ASSERT_TRUE(c.ok()) << c.error().message;
    const double read = topographyFromNormal(*run, c->after.normal).thickness;
    EXPECT_NEAR(c->after.thickness, read, 1e-9 * (1 + std::abs(c->before.thickness)));  // µm
    const double meanRow = sensitivityMatrix(*run, c->coefficients).thickness.dot(c->change);
    const double datumRow = c->after.thickness - c->before.thickness;
    std::printf("[ figures  ] %s: the thickness change by the datum's row %.6f µm, by the mean point's %.6f µm\n",
                run->atProbes() ? "probe points" : "6 x 8 grid", datumRow, meanRow);
    EXPECT_GT(std::abs(meanRow - datumRow), run->atProbes() ? 1e-2 : 1e-4);  // µm: the two rows differ here
  }
}

// The pass history's first prediction (correction.simulated) is the face the axes run grind with
// no machine error, read as the measurement is: measured on a perfect machine, the two agree in
// every figure, on a grid with no node at its centre and at probe points, where the simulated
// face's own thickness at the mean point (topography.thickness) differs from that reading.
TEST(Correction, TheFirstPassIsPredictedAsItIsMeasured) {
  const SharpeningJob job = evenGridJob();
  const AxisPolynomials& nominal = job.nominalAxes;
  const AxisPolynomials run = machineError(nominal);  // axes off the nominal ones, on a perfect machine
  const Topography exact = topographyFor(job, run);
  const ProbePoints probes = probesAt(job, {0.1, 0.3, 0.55, 0.8, 0.95}, {-0.7, -0.2, 0.15, 0.35, 0.6, 0.9});
  const GroundFace atProbes = simulateGroundFace(job.setup, run, probes, job.grid).value();
  const Eigen::VectorXd atProbesMeasured = topographyOf(atProbes).normal.col(0);
  auto onGrid = correctMeasuredFace(job.setup, nominal, run, groundFaceOf(job, run), exact.normal, CorrectionOptions{});
  auto onPoints = correctMeasuredPoints(job.setup, nominal, run, job.grid, probes, atProbesMeasured, CorrectionOptions{});
  ASSERT_TRUE(onGrid.ok()) << onGrid.error().message;
  ASSERT_TRUE(onPoints.ok()) << onPoints.error().message;
  for (const Correction* c : {&*onGrid, &*onPoints}) {
    SCOPED_TRACE(c->atProbes() ? "probe points" : "6 x 8 grid");
    const double tol = 1e-9 * (1 + c->before.rms);
    EXPECT_NEAR(c->simulated.rms, c->before.rms, tol);
    EXPECT_NEAR(c->simulated.sse, c->before.sse, 1e-9 * (1 + c->before.sse));
    EXPECT_NEAR(c->simulated.max, c->before.max, tol);
    EXPECT_NEAR(c->simulated.thickness, c->before.thickness, 1e-9 * (1 + std::abs(c->before.thickness)));
    std::printf("[ figures  ] %s: thickness read as measured %.4f µm, the simulated face's own at the mean point %.4f µm\n",
                c->atProbes() ? "probe points" : "6 x 8 grid", c->simulated.thickness, exact.thickness);
    EXPECT_GT(std::abs(c->simulated.thickness - exact.thickness), c->atProbes() ? 0.1 : 1e-4);  // µm: the readings differ here
  }
  EXPECT_NE(onPoints->simulated.rms, exact.rms);  // the points' figures, not the grid's
}

TEST(Correction, ReportsXAgainstAAsUnobservable) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  auto c = correctionStep(groundFaceOf(job, nominal), nominal,
                          topographyFor(job, machineError(nominal)).normal, CorrectionOptions{});
  ASSERT_TRUE(c.ok());
  ASSERT_EQ(c->singularValues.size(), 25);
  EXPECT_LT(c->singularValues(20), 1e-12 * c->singularValues(0));  // exactly rank 20 (docs/conventions.md §What the grid can see)
  EXPECT_GT(c->singularValues(19), 1e-5 * c->singularValues(0));
  ASSERT_EQ(c->unobservable.size(), 5u);
  const double p = job.setup.face.screwParameter;
  std::vector<int> degrees;
  for (const UnobservableCombination& u : c->unobservable) {
    ASSERT_EQ(u.coefficients.size(), 2u) << u.description;
    EXPECT_EQ(u.coefficients[0].axis, Axis::X);
    EXPECT_EQ(u.coefficients[1].axis, Axis::A);
    EXPECT_EQ(u.coefficients[0].degree, u.coefficients[1].degree);
    EXPECT_NEAR(u.amounts[1] / u.amounts[0], 1 / p, 1e-9);  // 1 mm on X = 1/p rad on A
    EXPECT_NE(u.description.find("cancel"), std::string::npos);
    degrees.push_back(u.coefficients[0].degree);
  }
  std::sort(degrees.begin(), degrees.end());
  EXPECT_EQ(degrees, (std::vector<int>{0, 1, 2, 3, 4}));
  // The correction stays out of the unobservable combinations: no X - A fight.
  for (int k = 0; k <= 4; ++k) EXPECT_LT(std::abs(c->change(k)), 0.05) << "X a" << k;
}

// The units in the sentences are written as the page and the verdict write them: rad/rad², never
// rad/rad^2.
TEST(Correction, UnobservableUnitsUseSuperscripts) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  auto c = correctionStep(groundFaceOf(job, nominal), nominal,
                          topographyFor(job, machineError(nominal)).normal, CorrectionOptions{});
  ASSERT_TRUE(c.ok());
  std::map<int, std::string> byDegree;
  for (const UnobservableCombination& u : c->unobservable) byDegree[u.coefficients[0].degree] = u.description;
  ASSERT_EQ(byDegree.size(), 5u);
  for (const auto& [k, text] : byDegree) EXPECT_EQ(text.find('^'), std::string::npos) << text;
  EXPECT_NE(byDegree[0].find("mm on X a0"), std::string::npos) << byDegree[0];
  EXPECT_NE(byDegree[1].find("rad/rad on A a1"), std::string::npos) << byDegree[1];
  EXPECT_NE(byDegree[2].find("rad/rad\u00b2 on A a2"), std::string::npos) << byDegree[2];
  EXPECT_NE(byDegree[4].find("mm/rad\u2074 on X a4"), std::string::npos) << byDegree[4];
}

TEST(Correction, RadialSecondDegreeShapeStaysInTheResidual) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  const FaceGrid& g = job.grid;
  Eigen::MatrixXd shape(g.rows(), g.cols());
  for (int i = 0; i < g.rows(); ++i) {
    const double z = (g.r[i] - g.rMean()) / (0.5 * (g.r.back() - g.r.front()));
    shape.row(i).setConstant(10.0 * z * z);  // µm
  }
  // The part of it that no constant or linear radial shape can take: (z^2 - 1/2) * 10 µm.
  double orthogonal = 0;
  for (int i = 0; i < g.rows(); ++i) orthogonal += g.cols() * std::pow(shape(i, 0) - 5.0, 2);
  auto c = correctionStep(groundFaceOf(job, nominal), nominal, shape, CorrectionOptions{});
  ASSERT_TRUE(c.ok());
  EXPECT_GT(c->after.sse, 0.8 * orthogonal);
  EXPECT_GT(c->uncorrectableShare, 0.3);
  EXPECT_NE(c->verdict.find("uncorrectable"), std::string::npos) << c->verdict;
  EXPECT_NE(c->verdict.find("wheel profile"), std::string::npos);
  EXPECT_GT(c->amplifyingDropped, 0);
  // Not smeared into wild coefficients: over the motion range (|phi| <= 0.5 rad at the grid's
  // ends) no change moves its axis by more than 0.1 mm or 0.01 rad. With amplification = 2 the
  // step takes one more direction, moves Y by 0.14 mm there, and takes nothing off the residual.
  const double range = 0.5;
  for (size_t j = 0; j < c->coefficients.size(); ++j) {
    const Coefficient& k = c->coefficients[j];
    const double bound = (isRotary(k.axis) ? 0.01 : 0.1) / std::pow(range, k.degree);
    EXPECT_LT(std::abs(c->change(j)), bound) << k.name();
  }
  CorrectionOptions loose;
  loose.amplification = 2;
  auto smeared = correctionStep(groundFaceOf(job, nominal), nominal, shape, loose);
  ASSERT_TRUE(smeared.ok());
  EXPECT_GT(smeared->change.cwiseAbs().maxCoeff(), 1.0);  // this test can tell the two apart
  EXPECT_GT(smeared->after.sse, c->after.sse - 1.0);
}

TEST(Correction, LockedAxesAndCoefficientsStayPut) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  AxisPolynomials error = nominal;  // an error X can take over from A
  error[Axis::A].a[0] += 0.0002;
  error[Axis::Z].a[1] += 0.003;
  const Topography measured = topographyFor(job, error);
  CorrectionOptions o;
  o.lockedAxes = {Axis::A};
  o.locked = {Coefficient{Axis::B, 2}};
  auto c = correctionStep(groundFaceOf(job, nominal), nominal, measured.normal, o);
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->coefficients.size(), 25u - 5u - 1u);
  for (int k = 0; k <= 4; ++k) EXPECT_EQ(c->axes[Axis::A].a[k], nominal[Axis::A].a[k]);
  EXPECT_EQ(c->axes[Axis::B].a[2], nominal[Axis::B].a[2]);
  EXPECT_TRUE(c->unobservable.empty());  // with A locked, X alone is observable
  EXPECT_NEAR(c->axes[Axis::X].a[0] - nominal[Axis::X].a[0], +0.0002 * job.setup.face.screwParameter, 1e-4);  // X takes over A's share
  EXPECT_LT(topographyFor(job, withError(c->axes, nominal, error)).sse, 0.01);
}

TEST(Correction, StraightGash) {
  const SharpeningJob job = jobOf(straightGashCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  AxisPolynomials error = nominal;
  error[Axis::Z].a[0] -= 0.006;
  error[Axis::Z].a[2] += 1e-6;   // mm/mm^2
  error[Axis::A].a[1] += 2e-6;   // rad/mm
  const Topography measured = topographyFor(job, error);
  EXPECT_GT(measured.sse, 1e3);
  auto c = correctionStep(groundFaceOf(job, nominal), nominal, measured.normal, CorrectionOptions{});
  ASSERT_TRUE(c.ok());
  // X (along the gash) and Y (radial, in the face plane) cannot be seen; they are set aside, not blown up.
  int alone = 0;
  for (const UnobservableCombination& u : c->unobservable)
    if (u.coefficients.size() == 1 && (u.coefficients[0].axis == Axis::X || u.coefficients[0].axis == Axis::Y)) ++alone;
  EXPECT_EQ(alone, 10);
  for (int k = 0; k <= 9; ++k) EXPECT_EQ(c->change(k), 0.0) << c->coefficients[k].name();
  EXPECT_LT(topographyFor(job, withError(c->axes, nominal, error)).sse, 0.01);
}

// The precision demand's face per axis error (correction.precision.facePerError): an axis the face
// does not show to first order (X, Y and B on a straight gash) reads 0, not the rounding of its
// sensitivities (Y read 5.6e-17 µm per µm beside exact zeros for X and B; an independent review).
TEST(Correction, AnAxisTheFaceDoesNotShowDemandsNoPrecision) {
  SharpeningJob job = jobOf(straightGashCase());
  AxisPolynomials error = job.nominalAxes;
  error[Axis::Z].a[0] -= 0.006;
  error[Axis::A].a[1] += 2e-6;  // rad/mm
  job.measured = MeasuredFace::onGrid(topographyFor(job, error).normal);
  auto e = evaluate(job);
  ASSERT_TRUE(e.ok());
  ASSERT_TRUE(e->correction);
  const std::array<double, kAxisCount>& f = e->correction->facePerAxisError;
  EXPECT_EQ(f[static_cast<int>(Axis::X)], 0.0);
  EXPECT_EQ(f[static_cast<int>(Axis::Y)], 0.0);
  EXPECT_EQ(f[static_cast<int>(Axis::B)], 0.0);
  EXPECT_GT(f[static_cast<int>(Axis::Z)], 0.1);  // µm of face per µm of Z
  EXPECT_GT(f[static_cast<int>(Axis::A)], 1e-3);  // per µrad
}

TEST(Correction, MeasuredOfTheWrongShapeIsRefused) {
  const SharpeningJob job = jobOf(paperCase());
  auto c = correctionStep(groundFaceOf(job, job.nominalAxes), job.nominalAxes, Eigen::MatrixXd::Zero(4, 9),
                          CorrectionOptions{});
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error().field, "measured");
}

// What the verdict says of the noise is what it tests: an rms left of at most twice sigma is
// "to within twice the probe noise", never "down to the probe noise", which the status's
// chi-square ceiling (1.28 sigma on Tab. 1's 45 points) could deny beside it ("ended above the
// probe noise").
// A checkerboard of `amplitude` µm on g: + and - from point to point, which no smooth axis motion grinds.
Eigen::MatrixXd checkerboard(const FaceGrid& g, double amplitude) {
  Eigen::MatrixXd shape(g.rows(), g.cols());
  for (int i = 0; i < g.rows(); ++i)
    for (int j = 0; j < g.cols(); ++j) shape(i, j) = (i + j) % 2 ? -amplitude : amplitude;
  return shape;
}

TEST(Correction, TheVerdictSaysWhichNoiseItMeans) {
  constexpr double kSigma = 0.5;  // µm
  const SharpeningJob nominalJob = jobOf(paperCase());
  CaseInput in = paperCase();
  in.measured = topographyFor(nominalJob, machineError(nominalJob.nominalAxes)).normal + checkerboard(nominalJob.grid, 0.9);
  in.correction.probeNoise = kSigma;
  auto e = evaluate(jobOf(in));
  ASSERT_TRUE(e.ok()) << e.error().message;
  const Correction& c = *e->correction;
  std::printf("[ figures  ] Tab. 1, sigma 0.5 µm, a 0.9 µm checkerboard: %.3f µm rms left, %s\n", c.after.rms,
              statusName(c.summary.status));
  EXPECT_EQ(c.summary.status, SolveStatus::AboveNoise) << c.summary.reason;
  EXPECT_GT(c.after.rms, 1.28 * kSigma);
  EXPECT_LE(c.after.rms, 2 * kSigma);
  EXPECT_GT(c.uncorrectableShare, CorrectionOptions{}.correctableShare);
  EXPECT_EQ(c.verdict.rfind("Correctable: the axes can cancel the measured deviation to within twice the probe noise (rms)", 0), 0u)
      << c.verdict;
  EXPECT_EQ(c.verdict.find("down to the probe noise"), std::string::npos);
}

// The same checkerboard alone (0.95 µm, no machine error): no axis direction stands above the
// noise and nothing is changed, so the verdict says no change is proposed, not "Correctable" (an
// independent review, 2026-12-07, found "Correctable … to within twice the probe noise" here,
// which sends the engineer to grind the same face again).
TEST(Correction, AShapeNoAxisMakesWithinTwiceTheNoiseProposesNoChange) {
  constexpr double kSigma = 0.5;  // µm
  CaseInput in = paperCase();
  in.measured = checkerboard(jobOf(in).grid, 0.95);
  in.correction.probeNoise = kSigma;
  auto e = evaluate(jobOf(in));
  ASSERT_TRUE(e.ok()) << e.error().message;
  const Correction& c = *e->correction;
  EXPECT_FALSE(c.stop);
  EXPECT_EQ(c.change.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(c.verdict.rfind("No change proposed: no shape the axes make stands out of the probe noise (sigma 0.5 µm) in "
                            "the face measured (0.95 µm rms); what is left is a shape they do not produce",
                            0),
            0u)
      << c.verdict;
  EXPECT_EQ(c.verdict.find("Correctable"), std::string::npos) << c.verdict;
}

// A face within the whole-face chi-square ceiling is not told to stop when a shape the axes make
// stands out of the noise in it (measured_face_correction.cpp, kStopDeviations): a Y a0 shape of
// 0.6 µm rms at sigma 0.5 µm, about 8 sigma along its one direction on Tab. 1's 45 points, and
// 0.53 µm, about 7 sigma (an independent review, 2026-12-07, had both told to stop). At 0.3 µm,
// about 4 sigma, it is within the noise and is told to stop.
TEST(Correction, AShapeTheAxesMakeAboveTheNoiseIsNotToldToStop) {
  constexpr double kSigma = 0.5;  // µm
  const SharpeningJob nominalJob = jobOf(paperCase());
  AxisPolynomials shifted = nominalJob.nominalAxes;
  shifted[Axis::Y].a[0] += 0.001;  // 1 µm
  const Eigen::MatrixXd unit = topographyFor(nominalJob, shifted).normal;
  const double unitRms = std::sqrt(unit.squaredNorm() / static_cast<double>(unit.size()));
  for (const double rms : {0.6, 0.53, 0.3}) {
    CaseInput in = paperCase();
    in.measured = unit * (rms / unitRms);
    in.correction.probeNoise = kSigma;
    auto e = evaluate(jobOf(in));
    ASSERT_TRUE(e.ok()) << e.error().message;
    const Correction& c = *e->correction;
    // Both are within the whole-face ceiling (45 sigma² (1 + 3 sqrt(2/45)), 0.64 µm rms).
    ASSERT_LT(c.before.rms, 0.64);
    if (rms > 0.5) {
      EXPECT_FALSE(c.stop) << c.verdict;
      EXPECT_EQ(c.verdict.rfind("Correctable:", 0), 0u) << c.verdict;
      EXPECT_LT(c.predictedRmsHigh, 0.3);
    } else {
      EXPECT_TRUE(c.stop) << c.verdict;
    }
  }
}

TEST(Correction, EvaluationWithMeasuredGivesTheCorrection) {
  CaseInput in = paperCase();
  const SharpeningJob nominalJob = jobOf(in);
  in.measured = topographyFor(nominalJob, machineError(nominalJob.nominalAxes)).normal;
  in.correction.probeNoise = 1e-4;  // a simulated what-if: noise-free, declared as such
  auto e = evaluate(jobOf(in));
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->correction.has_value());
  EXPECT_LT(e->correction->after.sse, 1e-3);
  EXPECT_GT(e->correction->before.sse, 3e3);
  // Without measured data there is no correction.
  EXPECT_FALSE(evaluate(nominalJob)->correction.has_value());
}

}  // namespace
}  // namespace hobsharp::test
