// The wheel-profile correction (issue 12 item 3, docs/method.md §Wheel-profile correction,
// core/correction/wheel_correction.h): the axes and a wheel-profile offset from one measured face,
// judged on the face re-simulated with the true wheel offset plus the proposed dressing and the
// true axis error plus the proposed axes, on the probe grid and on a grid 4 times as dense.
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cubic_spline.h"
#include "face_prediction.h"
#include "identification_cases.h"
#include "result_model.h"
#include "wheel_correction.h"
#include "wheel_input.h"
#include "wheel_offset_sensitivity.h"

namespace hobsharp::test {
namespace {

using Json = nlohmann::json;

CaseInput straightCase() {
  CaseInput c = paperCase();
  c.hob.gash = GashKind::Straight;
  c.settingAngle.reset();
  c.centerDistance.reset();
  return c;
}

// A face shape along the radius (µm, z = -1 at the root .. 1 at the tip) of the given degree, at
// most 10 µm: the wheel offset that grinds it is its negative (a constant +5 µm of offset grinds
// the face 5 µm deeper, docs/method.md §The wheel's profile offset).
std::function<double(double)> faceShape(int degree) {
  switch (degree) {
    case 2: return [](double z) { return 10 * z * z - 4; };
    case 3: return [](double z) { return 10 * z * z * z - 2 * z; };
    case 4: return [](double z) { return 10 * z * z * z * z - 8 * z * z + z; };
    default: return [](double) { return 0.0; };
  }
}

// The true wheel as a case gives it: wheel.profileOffset through 11 points, the conjugate wheel
// radii of 11 face radii evenly from root to tip, with the offset that grinds `shape` there.
WheelPointsInput trueWheel(const SharpeningJob& job, const std::function<double(double)>& shape) {
  constexpr int kPoints = 11;
  const std::vector<double> r = evenRadii(job.rootRadius, job.outerRadius, kPoints);
  auto p = wheelProfile(job.setup.face, job.setup.universal, job.setup.normalSign, r);
  EXPECT_TRUE(p.ok());
  WheelPointsInput w;
  for (int k = kPoints - 1; k >= 0; --k) {  // R increasing: the wheel's rim grinds the root
    w.R.push_back(p->R[k]);
    w.values.push_back(-shape(2 * (r[k] - job.rootRadius) / (job.outerRadius - job.rootRadius) - 1));
  }
  return w;
}

struct Scene {
  SharpeningJob job;        // the case as the engineer gives it: the conjugate wheel
  SharpeningSetup truth;    // the wheel the machine really has
  AxisPolynomials error;    // the machine's real axis error
};

Scene sceneOf(const CaseInput& c, const std::function<double(double)>& shape, double axisSse, unsigned seed = 7) {
  Scene s{jobOf(c), {}, {}};
  CaseInput withWheel = c;
  withWheel.wheelProfileOffset = trueWheel(s.job, shape);
  s.truth = jobOf(withWheel).setup;
  s.error = axisSse > 0 ? inSpanError(s.job, axisSse, seed) : times(s.job.nominalAxes, 0.0);
  return s;
}

Eigen::MatrixXd faceOn(const SharpeningSetup& setup, const AxisPolynomials& axes, const FaceGrid& grid) {
  auto f = simulateGroundFace(setup, axes, grid, Sensitivities::Skip);
  EXPECT_TRUE(f.ok()) << (f.ok() ? "" : f.error().message);
  return topographyOf(f.value()).normal;
}

struct Pass {
  Evaluation e;
  Eigen::MatrixXd measured;
  double onGrid = 0;  // SSE re-simulated with the true wheel + dressing and the true error + proposal, µm²
  double denseRms = 0;  // the same face's rms on the grid 4 times as dense, µm
};

Pass onePass(const Scene& s, double probeNoise, const Eigen::MatrixXd& noise = {}) {
  Pass p;
  p.measured = faceOn(s.truth, withMachineError(s.job.nominalAxes, s.error), s.job.grid);
  if (noise.size() > 0) p.measured += noise;
  SharpeningJob job = s.job;
  job.measured = MeasuredFace::onGrid(p.measured);
  job.correction.probeNoise = probeNoise;
  job.correction.wheel = true;
  auto e = evaluate(job);
  EXPECT_TRUE(e.ok()) << (e.ok() ? "" : e.error().message);
  p.e = std::move(e).value();
  EXPECT_TRUE(p.e.wheelCorrection.has_value());
  const WheelCorrection& w = *p.e.wheelCorrection;
  const SharpeningSetup after = withWheelDeviation(s.truth, w.knots, Eigen::Map<const Eigen::VectorXd>(w.offset.data(), w.offset.size()));
  const AxisPolynomials actual = withMachineError(p.e.correction->axes, s.error);
  p.onGrid = faceOn(after, actual, s.job.grid).squaredNorm();
  p.denseRms = rms(faceOn(after, actual, denseGrid(s.job.grid)));
  return p;
}

double largestOffset(const WheelCorrection& w) {
  double m = 0;
  for (double x : w.offset) m = std::max(m, std::abs(x));
  return m;
}

void print(const char* hob, const char* what, const Pass& p) {
  const Correction& c = *p.e.correction;
  const WheelCorrection& w = *p.e.wheelCorrection;
  std::printf("[ figures  ] %-14s %-22s SSE0 %8.1f -> %.2e µm² (predicted %.2e, dense rms %.1e µm), offset <= %.3f µm,"
              " axes %.3f, wheel %.3f, %d iterations\n",
              hob, what, c.before.sse, p.onGrid, c.after.sse, p.denseRms, largestOffset(w), w.axesShare, w.wheelShare,
              c.summary.iterations);
}

// One pass, noise-free (probeNoise 1e-4): a wheel offset of up to 10 µm whose face shape is of
// degree 2 to 4 along the radius, plus an in-span axis error of 1e3 µm²; a face that is pure axis
// error leaves the wheel offset below 0.1 µm. Judged, as issue 20 asks, between the probe rows (a
// grid 4 times as dense): at most `between` µm rms. The wheel's correction is a not-a-knot spline
// through its points (cubic_spline.h); with natural ends it left 0.17, 0.44 and 0.60 µm rms
// between the rows on the paper hob (degrees 2, 3, 4) and 0.11, 0.37 and 0.55 µm on the straight
// gash, against 0.037, 0.12 and 0.28 µm and 3e-4, 4.8e-3 and 0.19 µm now.
// On the probe grid (sums of squares, µm²; `target`, and the prediction's gap to the face ground,
// `predictionGap`) the paper hob leaves 7.6e-3, 4.1e-2 and 1.2e-2 µm² (with natural ends 7.0e-3,
// 1.4e-2, 4.2e-3), about 0.03 µm rms at most; the straight gash below 1.6e-3 µm². What the probe
// grid cannot tell apart (TheProbeGridReadsTheOffsetAtItsKnots below):
// - the 5 points suffice: dressing the true offset's values there, with the true axes, leaves
//   5.7e-6 to 5.9e-4 µm²; on the nominal axes each row is ground at its point's wheel radius only;
// - to first order an offset constant along R, and on Tab. 1 with the axis directions this error
//   needs one linear in R, are faces the axes make too (off their span by 1e-6 and 3e-5 of their
//   size), so the split rule leaves them to the axes, and E and W differ from the truth by such a
//   face (hundreds of µm²) and a line of a few µm;
// - the axes make that offset only where the measured face was ground: the axis error and the
//   offset's slope move each row 8 to 17 µm of wheel radius off its point, so the offset the axes
//   stand in for is read there, and after the pass, ground at the points again, it misses by its
//   slope times that shift. The prediction re-simulates the identified model exactly; it misses
//   the face ground by that (up to 3.8e-2 µm², degree 3 on the paper hob).
void expectTargets(const char* hob, const CaseInput& c, double target, double predictionGap, double between) {
  for (int degree : {2, 3, 4}) {
    SCOPED_TRACE(std::string(hob) + ", degree " + std::to_string(degree));
    const Scene s = sceneOf(c, faceShape(degree), 1e3);
    const Pass p = onePass(s, 1e-4);
    const Correction& k = *p.e.correction;
    const WheelCorrection& w = *p.e.wheelCorrection;
    EXPECT_GT(k.before.sse, 1e3);
    // A tolerance was met; the 5-point wheel leaves a shape of a few nm rms, above the declared
    // 1e-4 µm noise, which the status says ("aboveNoise").
    EXPECT_TRUE(k.summary.status == SolveStatus::Converged || k.summary.status == SolveStatus::AboveNoise)
        << k.summary.reason;
    EXPECT_LT(p.onGrid, target);
    EXPECT_LT(p.denseRms, between);
    // The prediction is the face the machine grinds with both applied.
    EXPECT_NEAR(k.after.sse, p.onGrid, predictionGap);
    EXPECT_GT(largestOffset(w), 1.0);  // the wheel takes the shape
    EXPECT_LE(largestOffset(w), 12.0);
    EXPECT_GT(w.wheelShare, 0.01);
    EXPECT_GT(w.axesShare, 0.1);
    EXPECT_NEAR(w.axesShare + w.wheelShare + k.uncorrectableShare, 1.0, 1e-6);
    EXPECT_NE(k.verdict.find("Correctable with the wheel"), std::string::npos) << k.verdict;
    // The verdict quotes the prediction with its bound (issue 20), not the model's misfit.
    EXPECT_NE(k.verdict.find("on the probe grid the face measured "), std::string::npos) << k.verdict;
    // ... by its bound alone: no figure below it (face_prediction.h).
    EXPECT_NE(k.verdict.find("will be left at most "), std::string::npos) << k.verdict;
    EXPECT_EQ(k.verdict.find("at about"), std::string::npos) << k.verdict;
    EXPECT_EQ(k.verdict.find("predicted sum of squares"), std::string::npos) << k.verdict;
    // ... and says what it assumes of the wheel between the probe rows, which the grid does not show
    // (the review of 2026-12-07: a wave of 1.5 periods between 5 rows left 0.23 µm on the grid
    // against a bound of 0.007 µm).
    const std::string smooth = "if the wheel's shape between the probe rows is one a smooth curve through its " +
                               std::to_string(w.knots.R.size()) + " points makes";
    EXPECT_NE(k.verdict.find(smooth), std::string::npos) << k.verdict;
    EXPECT_NE(predictionCondition(k).find(smooth), std::string::npos) << predictionCondition(k);
    print(hob, ("degree " + std::to_string(degree) + " + axes").c_str(), p);
  }
  SCOPED_TRACE(std::string(hob) + ", pure axis error");
  const Scene s = sceneOf(c, faceShape(0), 1e3);
  const Pass p = onePass(s, 1e-4);
  EXPECT_LT(largestOffset(*p.e.wheelCorrection), 0.1);
  EXPECT_LT(p.onGrid, 0.01);
  EXPECT_LT(p.e.wheelCorrection->wheelShare, 1e-3);
  // A dressing below the machine's 0.1 µm position resolution is none, and the verdict says so
  // instead of "dress the wheel by ... at most 0.004 µm".
  const std::string& verdict = p.e.correction->verdict;
  EXPECT_EQ(verdict.find("Correctable with the axes alone: run the axes proposed; the wheel needs no dressing ("), 0u)
      << verdict;
  EXPECT_EQ(verdict.find("dress the wheel by"), std::string::npos) << verdict;
  print(hob, "pure axis error", p);
}

TEST(WheelCorrection, TargetsOnThePaperHob) { expectTargets("Tab. 1", paperCase(), 0.05, 0.04, 0.3); }
TEST(WheelCorrection, TargetsOnAStraightGash) { expectTargets("straight gash", straightCase(), 0.01, 2e-3, 0.2); }

// Why the paper hob misses the target (above): on the nominal axes the probe grid reads the wheel
// offset at the correction's points and nowhere else, so the 5 points suffice; what the pass leaves
// comes from the identified split, not from the basis.
TEST(WheelCorrection, TheProbeGridReadsTheOffsetAtItsKnots) {
  for (int degree : {2, 3, 4}) {
    SCOPED_TRACE("degree " + std::to_string(degree));
    const Scene s = sceneOf(paperCase(), faceShape(degree), 1e3);
    const SharpeningJob& job = s.job;
    const WheelKnots knots = wheelKnots(job.setup, job.grid, std::max(job.grid.r.front(), job.rootRadius),
                                        std::min(job.grid.r.back(), job.outerRadius)).value();
    ASSERT_EQ(knots.R.size(), 5u);
    // Each row of the run face is ground at one point's wheel radius, and only the offset's value
    // there moves it (dt/d delta = -1, dt/d delta' = 0: Eq. 11 holds for any slope on the nominal axes).
    const SharpeningSetup zero = withWheelDeviation(job.setup, knots, Eigen::VectorXd::Zero(5));
    const GroundFace run = simulateGroundFace(zero, job.nominalAxes, job.grid).value();
    for (int i = 0; i < job.grid.rows(); ++i)
      for (int j = 0; j < job.grid.cols(); ++j) {
        const EnvelopePoint& e = run.envelope[i * job.grid.cols() + j];
        EXPECT_NEAR(e.wheelRadius, knots.R[job.grid.rows() - 1 - i], 1e-9) << i << ", " << j;  // mm
        EXPECT_NEAR(e.dtdOffset, -1.0, 1e-9);
        EXPECT_NEAR(e.dtdOffsetSlope, 0.0, 1e-9);  // mm per unit slope
      }
    // Dressing the true offset's values at the points, with the true error corrected exactly,
    // leaves a face 10 times below the target (5.7e-6 to 5.9e-4 µm²).
    Eigen::VectorXd atKnots(5);
    for (int k = 0; k < 5; ++k) atKnots(k) = 1000 * s.truth.wheel.offset->value(knots.R[k]);
    const double left = faceOn(withWheelDeviation(s.truth, knots, -atKnots), job.nominalAxes, job.grid).squaredNorm();
    EXPECT_LT(left, 1e-3);
    std::printf("[ figures  ] Tab. 1         degree %d: the true offset's values dressed, true axes: %.2e µm²\n", degree, left);
  }
}

// The identification's Jacobian in W is the model's: the columns from wheelDeviationSpline's basis
// are the central differences of the face re-simulated with withWheelDeviation. Off the nominal
// axes (an axis error) and with 15 rows for 12 points, the wheel grinds between the points, where
// a natural spline's basis (which the identification took before) differs from the not-a-knot
// spline the wheel adds.
TEST(WheelCorrection, TheJacobianInTheWheelIsTheModels) {
  CaseInput c = paperCase();
  c.grid.radial = 15;
  const Scene s = sceneOf(c, faceShape(0), 1e3);
  const SharpeningJob& job = s.job;
  const WheelKnots knots = wheelKnots(job.setup, job.grid, std::max(job.grid.r.front(), job.rootRadius),
                                      std::min(job.grid.r.back(), job.outerRadius)).value();
  const int K = static_cast<int>(knots.R.size());
  ASSERT_EQ(K, kMostWheelKnots);
  Eigen::VectorXd W(K);
  for (int k = 0; k < K; ++k) W(k) = 3 * std::sin(1.3 * k);  // µm
  const AxisPolynomials axes = withMachineError(job.nominalAxes, s.error);
  const GroundFace at = simulateGroundFace(withWheelDeviation(job.setup, knots, W), axes, job.grid).value();
  const Eigen::MatrixXd model = wheelOffsetSensitivity(at, wheelDeviationSpline(knots, Eigen::VectorXd::Zero(K))).normal;
  const Eigen::MatrixXd natural = wheelOffsetSensitivity(at, CubicSpline(knots.R, std::vector<double>(K, 0.0))).normal;
  constexpr double h = 0.01;  // µm
  double worst = 0, worstNatural = 0;
  for (int k = 0; k < K; ++k) {
    const auto faceAt = [&](double d) {
      Eigen::VectorXd Wd = W;
      Wd(k) += d;
      const Eigen::MatrixXd f = faceOn(withWheelDeviation(job.setup, knots, Wd), axes, job.grid);
      return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(f.data(), f.size()));
    };
    // faceOn's matrix is column-major, the sensitivities' rows row-major: compare as matrices.
    const Eigen::VectorXd d = (faceAt(h) - faceAt(-h)) / (2 * h);
    const Eigen::MatrixXd byDiff = Eigen::Map<const Eigen::MatrixXd>(d.data(), job.grid.rows(), job.grid.cols());
    Eigen::MatrixXd byModel(job.grid.rows(), job.grid.cols()), byNatural(job.grid.rows(), job.grid.cols());
    for (int i = 0; i < job.grid.rows(); ++i)
      for (int j = 0; j < job.grid.cols(); ++j) {
        byModel(i, j) = model(i * job.grid.cols() + j, k);
        byNatural(i, j) = natural(i * job.grid.cols() + j, k);
      }
    worst = std::max(worst, (byModel - byDiff).cwiseAbs().maxCoeff());
    worstNatural = std::max(worstNatural, (byNatural - byDiff).cwiseAbs().maxCoeff());
  }
  std::printf("[ figures  ] Tab. 1, 15 rows, 12 points: the wheel's Jacobian against differences %.1e µm/µm (natural basis %.1e)\n",
              worst, worstNatural);
  EXPECT_LT(worst, 1e-6);         // µm of face per µm of W
  EXPECT_GT(worstNatural, 1e-3);  // the test tells the two apart
}

// With 1 µm of probe noise the face after the pass stays within the noise level between the
// probe points too; noise alone moves neither the axes nor the wheel much.
TEST(WheelCorrection, WithProbeNoiseTheFaceStaysWithinTheNoise) {
  constexpr double kSigma = 1.0;
  for (const auto& [hob, c] : {std::pair{"Tab. 1", paperCase()}, std::pair{"straight gash", straightCase()}}) {
    for (int degree : {2, 4}) {
      SCOPED_TRACE(std::string(hob) + ", degree " + std::to_string(degree));
      const Scene s = sceneOf(c, faceShape(degree), 1e3);
      const Eigen::MatrixXd noise = probeNoise(s.job.grid.rows(), s.job.grid.cols(), kSigma, 11 + degree);
      const Pass p = onePass(s, kSigma, noise);
      EXPECT_LT(p.denseRms, kSigma);
      EXPECT_LT(std::sqrt(p.onGrid / s.job.grid.size()), kSigma);
      print(hob, ("noise 1 µm, degree " + std::to_string(degree)).c_str(), p);
    }
    const Scene quiet = sceneOf(c, faceShape(0), 0);
    const Pass p = onePass(quiet, kSigma, probeNoise(quiet.job.grid.rows(), quiet.job.grid.cols(), kSigma, 5));
    EXPECT_LT(p.denseRms, 0.5 * kSigma);
    EXPECT_LT(largestOffset(*p.e.wheelCorrection), kSigma);
    print(hob, "noise 1 µm only", p);
  }
}

// A checkerboard of 0.95 µm at sigma 0.5 µm, with the wheel's correction asked for: no axis shape
// and no wheel shape stands out of the noise, nothing is changed and nothing dressed, and the
// verdict says so (the axes' "No change proposed"), not "Correctable with the axes alone" (an
// independent review, 2026-12-07).
TEST(WheelCorrection, NothingToChangeOrDressIsSaidSo) {
  CaseInput in = paperCase();
  in.correction.wheel = true;
  in.correction.probeNoise = 0.5;
  const SharpeningJob nominal = jobOf(in);
  Eigen::MatrixXd shape(nominal.grid.rows(), nominal.grid.cols());
  for (int i = 0; i < shape.rows(); ++i)
    for (int j = 0; j < shape.cols(); ++j) shape(i, j) = (i + j) % 2 ? -0.95 : 0.95;
  in.measured = shape;
  auto e = evaluate(jobOf(in));
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->wheelCorrection.has_value());
  EXPECT_EQ(e->correction->change.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LT(largestOffset(*e->wheelCorrection), 0.1);
  const std::string& v = e->correction->verdict;
  EXPECT_EQ(v.rfind("No change proposed:", 0), 0u) << v;
  EXPECT_NE(v.find("And the wheel needs no dressing"), std::string::npos) << v;
  EXPECT_EQ(v.find("Correctable"), std::string::npos) << v;
}

// A wheel the case records as dressed (wheel.profileOffset: say an earlier pass's dressing O, at
// the correction's points) is dressed back to the conjugate wheel, which grinds the nominal face:
// the dressing takes O away with the identified deviation W, and the face after the pass is as
// good as with the undressed record. (Dressing -W alone would return the wheel to O, whose face is
// worse than the one measured, so the run would be kept.) The dressing itself differs from the
// undressed record's less O by up to 0.4 µm: with O on the wheel the rows are ground at other
// wheel radii, and the split between axes and wheel is decided there.
TEST(WheelCorrection, TheCasesOwnOffsetIsDressedAwayToo) {
  const Scene plain = sceneOf(paperCase(), faceShape(2), 1e3);
  const Pass a = onePass(plain, 1e-4);
  const WheelCorrection& wa = *a.e.wheelCorrection;
  const std::vector<double> O = {1.5, -2.0, 0.5, 3.0, -1.0};  // µm at the correction's points
  ASSERT_EQ(wa.knots.R.size(), O.size());
  const Eigen::Map<const Eigen::VectorXd> o(O.data(), static_cast<int>(O.size()));
  // The machine's wheel is the true one with O dressed on it, and the case says O.
  CaseInput dressedCase = paperCase();
  dressedCase.wheelProfileOffset = WheelPointsInput{wa.knots.R, O};
  const Scene recorded{jobOf(dressedCase), withWheelDeviation(plain.truth, wa.knots, o), plain.error};
  const Pass b = onePass(recorded, 1e-4);  // its onGrid replaces O by the dressing: not the wheel after
  const Correction& kb = *b.e.correction;
  const WheelCorrection& wb = *b.e.wheelCorrection;
  EXPECT_FALSE(kb.runKept) << kb.verdict;
  ASSERT_EQ(wb.knots.R, wa.knots.R);
  // The dressing is -(O + W): the case's offset goes with the identified deviation.
  for (size_t k = 0; k < O.size(); ++k) EXPECT_NEAR(wb.offset[k], -(wb.deviation[k] + O[k]), 1e-12) << k;
  // The wheel after the pass: the true one, O and the dressing on the same points.
  const Eigen::Map<const Eigen::VectorXd> d(wb.offset.data(), static_cast<int>(wb.offset.size()));
  const SharpeningSetup after = withWheelDeviation(plain.truth, wa.knots, o + d);
  const double onGrid = faceOn(after, withMachineError(kb.axes, plain.error), plain.job.grid).squaredNorm();
  std::printf("[ figures  ] Tab. 1 degree 2 + axes, the case's wheel dressed by O: %.2e µm² (predicted %.2e; undressed record %.2e)\n",
              onGrid, kb.after.sse, a.onGrid);
  EXPECT_LT(onGrid, 0.01);
  EXPECT_NEAR(onGrid, a.onGrid, 0.5 * a.onGrid);
}

// The split: a wheel shape alone is the wheel's; the axes move little for it.
TEST(WheelCorrection, AWheelShapeAloneIsLeftToTheWheel) {
  const Scene s = sceneOf(paperCase(), faceShape(2), 0);
  const Pass p = onePass(s, 1e-4);
  const WheelCorrection& w = *p.e.wheelCorrection;
  EXPECT_LT(p.onGrid, 0.01);
  EXPECT_GT(w.wheelShare, w.axesShare);
  // The dressing is the shape's offset back, up to what the axes make (a constant and a tilt
  // along the radius): its second difference over the points is the shape's.
  const std::vector<double>& R = w.knots.R;
  for (size_t k = 1; k + 1 < R.size(); ++k) {
    const double bend = w.offset[k + 1] - 2 * w.offset[k] + w.offset[k - 1];
    EXPECT_GT(bend, 0.0) << k;  // -(-shape): the face shape 10 z² bends up, so does the dressing
  }
  print("Tab. 1", "degree 2 alone", p);
}

// The result: the new fields, finite, of the grid's shape; the dresser path is the conjugate
// profile moved by the dressing; without correction.wheel the result has none of them and is
// unchanged by `"wheel": false`.
TEST(WheelCorrection, ResultFieldsAndTheSwitch) {
  const Scene s = sceneOf(paperCase(), faceShape(3), 1e3);
  const Eigen::MatrixXd measured = faceOn(s.truth, withMachineError(s.job.nominalAxes, s.error), s.job.grid);
  Json j = Json::parse(readFile("tab1.json"));
  Json rows = Json::array();
  for (int i = 0; i < measured.rows(); ++i) {
    Json row = Json::array();
    for (int k = 0; k < measured.cols(); ++k) row.push_back(measured(i, k));
    rows.push_back(row);
  }
  j["measured"] = rows;
  j["correction"]["probeNoise"] = 1e-4;
  auto plain = evaluateCase(j.dump());
  ASSERT_TRUE(plain.ok()) << plain.error().message;
  Json off = j;
  off["correction"]["wheel"] = false;
  auto unchanged = evaluateCase(off.dump());
  ASSERT_TRUE(unchanged.ok());
  EXPECT_EQ(resultJson(*plain), resultJson(*unchanged));
  const Json plainResult = Json::parse(resultJson(*plain));
  EXPECT_FALSE(plainResult["correction"].contains("wheelProfileOffset"));
  EXPECT_FALSE(plainResult["correction"].contains("removedByWheel"));

  j["correction"]["wheel"] = true;
  auto on = evaluateCase(j.dump());
  ASSERT_TRUE(on.ok()) << on.error().message;
  const Json r = Json::parse(resultJson(*on));
  const Json& c = r["correction"];
  ASSERT_TRUE(c.contains("wheelProfileOffset"));
  const size_t knots = c["wheelProfileOffset"]["R"].size();
  EXPECT_EQ(knots, 5u);  // one point per radial line of the 9 x 5 grid
  EXPECT_EQ(c["wheelProfileOffset"]["offset"].size(), knots);
  for (size_t k = 1; k < knots; ++k)
    EXPECT_GT(c["wheelProfileOffset"]["R"][k].get<double>(), c["wheelProfileOffset"]["R"][k - 1].get<double>());
  EXPECT_EQ(c["dresserPath"]["R"].size(), r["wheelProfile"]["R"].size());
  EXPECT_EQ(c["dresserPath"]["Z"].size(), r["wheelProfile"]["Z"].size());
  // The dresser path lies the dressing's offset from the conjugate profile, along its normal.
  const WheelCorrection& w = *on->wheelCorrection;
  for (size_t k = 0; k < w.dresser.R.size(); ++k) {
    const double moved = std::hypot(w.dresser.dressedR[k] - on->job.wheelProfile.R[k], w.dresser.dressedZ[k] - on->job.wheelProfile.Z[k]);
    EXPECT_NEAR(moved * 1000, std::abs(w.dresser.offset[k] * 1000), 1e-9) << k;
    EXPECT_LE(std::abs(w.dresser.offset[k]) * 1000, 1.5 * largestOffset(w) + 1e-9);
  }
  // Fig. 4 draws the wheel's offset after the dressing as the spline, not through its points: the
  // field is the proposed spline at the profile's radii (this case's wheel has no offset of its own).
  const CubicSpline proposed = CubicSpline::notAKnot(c["wheelProfileOffset"]["R"].get<std::vector<double>>(),
                                                     c["wheelProfileOffset"]["offset"].get<std::vector<double>>());
  ASSERT_EQ(c["dresserPath"]["offset"].size(), r["wheelProfile"]["R"].size());
  for (size_t k = 0; k < r["wheelProfile"]["R"].size(); ++k)
    EXPECT_NEAR(c["dresserPath"]["offset"][k].get<double>(), proposed.value(r["wheelProfile"]["R"][k].get<double>()), 1e-9) << k;
  for (const char* grid : {"removedByAxes", "removedByWheel", "residual"}) {
    ASSERT_EQ(c[grid].size(), 5u) << grid;
    for (const Json& row : c[grid]) ASSERT_EQ(row.size(), 9u) << grid;
  }
  // measured = removed by the axes + removed by the wheel + what is left.
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 9; ++k)
      EXPECT_NEAR(c["removedByAxes"][i][k].get<double>() + c["removedByWheel"][i][k].get<double>() +
                      c["residual"][i][k].get<double>(),
                  measured(i, k), 1e-9);
  for (const char* share : {"wheelShare", "axesShare"}) {
    EXPECT_GE(c[share].get<double>(), 0.0);
    EXPECT_LE(c[share].get<double>(), 1.0);
  }
  EXPECT_LT(c["sseAfter"].get<double>(), 0.01);
  EXPECT_EQ(firstNonFinite(*on), "");
  // The dressing read back as a case's offset is within the contact range.
  Json again = Json::parse(readFile("tab1.json"));
  again["wheel"]["profileOffset"] = {{"R", c["wheelProfileOffset"]["R"]}, {"offset", c["wheelProfileOffset"]["offset"]}};
  auto readBack = evaluateCase(again.dump());
  EXPECT_TRUE(readBack.ok()) << (readBack.ok() ? "" : readBack.error().message);
}

// Refusals name the field.
TEST(WheelCorrection, RefusalsNameTheField) {
  Json j = Json::parse(readFile("tab1.json"));
  j["correction"]["wheel"] = "yes";
  auto e = evaluateCase(j.dump());
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().field, "correction.wheel");
  EXPECT_EQ(e.error().message.rfind("correction.wheel: must be true or false", 0), 0u) << e.error().message;
  j["correction"]["wheel"] = true;
  j["correction"]["method"] = "linear";
  e = evaluateCase(j.dump());
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().field, "correction.wheel");
  EXPECT_NE(e.error().message.find("nonlinear"), std::string::npos) << e.error().message;
  // A pass's options are checked the same way.
  Json pass = Json::parse(readFile("tab1.json"));
  pass["passes"] = Json::array();
  const SharpeningJob job = jobOf(paperCase());
  Json axes = Json::object();
  for (Axis a : kAxes) axes[axisName(a)] = job.nominalAxes[a].a;
  Json zero = Json::array();
  for (int i = 0; i < 5; ++i) zero.push_back(std::vector<double>(9, 0.0));
  pass["passes"].push_back({{"axes", axes}, {"measured", zero}, {"correction", {{"wheel", 1}}}});
  e = evaluateCase(pass.dump());
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().field, "passes[0].correction.wheel");
}

}  // namespace
}  // namespace hobsharp::test
