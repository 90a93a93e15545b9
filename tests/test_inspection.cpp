// The rake-face inspection (core/inspection/, docs/inspection.md): each check on
// constructed faces whose answer is known by hand, the class table at its band edges, the
// indexing correction against the simulated face's own A sensitivity, and bad input refused with
// the field named.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/QR>
#include <nlohmann/json.hpp>

#include "default_tolerances.h"
#include "face_checks.h"
#include "gash_faces.h"
#include "gash_spacing.h"
#include "hand_built_face.h"
#include "index_correction.h"
#include "inspection.h"
#include "result_model.h"
#include "test_support.h"

namespace hobsharp {
namespace {

using Json = nlohmann::json;

// The paper's grid: 5 radii from 19 to 40 mm, 9 axial positions from -70 to 70 mm.
const std::vector<double> kR{19, 24.25, 29.5, 34.75, 40};
const std::vector<double> kX{-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70};

template <class F>
Eigen::MatrixXd faceOf(const std::vector<double>& r, const std::vector<double>& x, F f) {
  Eigen::MatrixXd m(r.size(), x.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j) m(i, j) = f(r[i], x[j]);
  return m;
}

// A zero-rake face with its normal in the transverse plane: the lines are radial, s = r.
const FaceLines kRadial = FaceLines::radial(kR, kX);

TEST(Inspection, AFaceMovedParallelReadsItsOffsetTimesTheDepthOverTheTipRadius) {
  // 10 µm of excess material everywhere: the indicator zeroed at the tip (40 mm) reads
  // 10 (1 - r / 40) below it, 10 * 21 / 40 = 5.25 µm at the root (19 mm). No form, no lead.
  const FaceChecks c = checkFace(faceOf(kR, kX, [](double, double) { return 10.0; }), kRadial, true);
  EXPECT_NEAR(c.radialAlignment, 5.25, 1e-9);
  EXPECT_NEAR(c.cuttingFaceForm, 0, 1e-9);
  ASSERT_TRUE(c.gashLead);
  EXPECT_NEAR(*c.gashLead, 0, 1e-9);
  // Excess material on the whole line is a drag: the line's distance from the axis shrinks by 10 µm.
  EXPECT_NEAR(c.rakeOffset, -0.010, 1e-12);
  EXPECT_NEAR(c.rakeAngle, -0.010 / 40, 1e-12);
  // Material taken off: the face recedes into the tooth toward the root, a hook.
  const FaceChecks hook = checkFace(faceOf(kR, kX, [](double, double) { return -8.0; }), kRadial, false);
  EXPECT_NEAR(hook.radialAlignment, -8 * 21.0 / 40, 1e-9);
  EXPECT_NEAR(hook.rakeOffset, 0.008, 1e-12);
  EXPECT_FALSE(hook.gashLead) << "no gash lead on a straight gash";
}

TEST(Inspection, AFaceTurnedAboutTheHobAxisStaysRadialAndReadsNothing) {
  // A turn of 0.5 mrad moves the point at radius r by 0.5 r µm across the radial line: an index
  // or thickness error, not an alignment error, and no rake error.
  const FaceChecks c = checkFace(faceOf(kR, kX, [](double r, double) { return 0.5 * r; }), kRadial, true);
  EXPECT_NEAR(c.radialAlignment, 0, 1e-9);
  EXPECT_NEAR(c.rakeOffset, 0, 1e-12);
  EXPECT_NEAR(c.cuttingFaceForm, 0, 1e-9);
  // Turned and moved: the offset's reading alone, 6 * 21 / 40 = 3.15 µm at the root.
  const FaceChecks both = checkFace(faceOf(kR, kX, [](double r, double) { return 0.5 * r + 6; }), kRadial, true);
  EXPECT_NEAR(both.radialAlignment, 3.15, 1e-9);
  EXPECT_NEAR(both.rakeOffset, -0.006, 1e-12);
}

TEST(Inspection, ThePerLineFiguresAreTheLargestOverTheFace) {
  // The offset grows along the gash, to 14 µm on the last axial line: 14 * 21 / 40 there, signed.
  const FaceChecks c = checkFace(faceOf(kR, kX, [](double, double x) { return -(x + 70) / 10; }), kRadial, false);
  EXPECT_NEAR(c.radialAlignment, -14 * 21.0 / 40, 1e-9);
  // The rake error is the mean over the lines: 7 µm taken off on average, a hook.
  EXPECT_NEAR(c.rakeOffset, 0.007, 1e-12);
}

TEST(Inspection, APureGashLeadSlopeIsAGashLeadDeviationPer100Millimetres) {
  // 0.05 µm per mm along the hob axis is 5 µm per 100 mm, on every radial line.
  const FaceChecks c = checkFace(faceOf(kR, kX, [](double, double x) { return 0.05 * x; }), kRadial, true);
  ASSERT_TRUE(c.gashLead);
  EXPECT_NEAR(*c.gashLead, 5, 1e-9);
  EXPECT_NEAR(c.cuttingFaceForm, 0, 1e-9);
}

TEST(Inspection, ABowAlongTheRadiusIsFormAndTheIndicatorReadsItFromTheTip) {
  // c (r - 29.5)^2 at r = 19, 29.5, 40: c h^2, 0, c h^2 with h = 10.5. The fitted line is flat at
  // 2/3 c h^2; the residuals c h^2 / 3, -2/3 c h^2, c h^2 / 3 spread c h^2 = 11.025 µm for c = 0.1.
  // The indicator zeroed at 40 mm reads 0 - 11.025 * 29.5 / 40 = -8.131 µm at 29.5 mm and
  // 11.025 - 11.025 * 19 / 40 = 5.788 µm at 19 mm: the largest is -8.131.
  const std::vector<double> r{19, 29.5, 40};
  const FaceChecks c = checkFace(faceOf(r, kX, [](double rr, double) { return 0.1 * (rr - 29.5) * (rr - 29.5); }),
                                 FaceLines::radial(r, kX), true);
  EXPECT_NEAR(c.cuttingFaceForm, 11.025, 1e-9);
  EXPECT_NEAR(c.radialAlignment, -11.025 * 29.5 / 40, 1e-9);
}

TEST(Inspection, ARakeErrorFaceIsReadBackAsItsRakeError) {
  const SharpeningJob job = test::jobOf(test::paperCase());
  const FaceLines lines = FaceLines::of(job.setup, job.grid);
  const FaceChecks c = checkFace(rakeErrorFace(lines, 0.05), lines, true);
  EXPECT_NEAR(c.rakeOffset, 0.05, 1e-12);
  EXPECT_NEAR(c.rakeAngle, 0.05 / lines.alongLine.back(), 1e-15);
  // Material taken off (a hook): the indicator reads minus toward the root.
  EXPECT_NEAR(c.radialAlignment, -50 * (1 - lines.alongLine.front() / lines.alongLine.back()), 1e-9);
}

struct HandBuiltCase {
  const char* name;
  CaseInput input;
};

std::vector<HandBuiltCase> handBuiltCases() {
  CaseInput right = test::withDerivedSetup(test::paperCase());
  CaseInput left = right;
  left.hob.hand = Hand::Left;
  CaseInput straight = test::straightGashCase();
  CaseInput rake = right;
  rake.hob.rakeOffset = 3;
  CaseInput leftRake = left;
  leftRake.hob.rakeOffset = -2;
  CaseInput straightRake = straight;
  straightRake.hob.rakeOffset = 3;
  return {{"helical, right hand", right}, {"helical, left hand", left}, {"straight", straight},
          {"helical, right hand, rake offset 3 mm", rake}, {"helical, left hand, rake offset -2 mm", leftRake},
          {"straight, rake offset 3 mm", straightRake}};
}

TEST(Inspection, HandBuiltFacesGiveTheStandardsReadingWithin10Percent) {
  // A rake error of 0.08 mm, a turn of 0.4 mrad (an index error), both together, and their opposites.
  struct Fault {
    double u, theta;  // mm out of the tooth (excess material), rad
  };
  for (const HandBuiltCase& c : handBuiltCases()) {
    const SharpeningJob job = test::jobOf(c.input);
    const FaceLines lines = FaceLines::of(job.setup, job.grid);
    const double rTip = job.grid.r.back();
    for (const Fault err : {Fault{0.08, 0}, Fault{0, 4e-4}, Fault{0.08, 4e-4}, Fault{-0.1, -4e-4}}) {
      const test::HandBuiltInspection hand = test::handBuiltInspection(job.setup, job.grid, err.u, err.theta);
      const double expected = hand.reading;
      const FaceChecks got = checkFace(hand.normal, lines, job.setup.face.helical());
      const std::string what = std::string(c.name) + ", u = " + std::to_string(err.u) + " mm, theta = " + std::to_string(err.theta);
      if (err.u == 0) {
        // A turn alone: the standard reads (nearly) nothing, and so does the check.
        EXPECT_LT(std::abs(expected), 0.05) << what;
        EXPECT_LT(std::abs(got.radialAlignment), 0.5) << what << ": " << got.radialAlignment;
        EXPECT_LT(std::abs(got.rakeOffset), 5e-4) << what;
        continue;
      }
      // The standard's reading is about u h / r_a (h the depth measured, e small), with the sign of the
      // material: excess material (u > 0, a drag) reads plus.
      const double h = lines.alongLine.back() - lines.alongLine.front();
      EXPECT_NEAR(expected, err.u * 1e3 * h / lines.alongLine.back(), 0.05 * std::abs(expected)) << what;
      EXPECT_NEAR(got.radialAlignment, expected, 0.1 * std::abs(expected)) << what;
      // The rake error: the offset taken off (a hook) is plus, and its angle at the tip.
      EXPECT_NEAR(got.rakeOffset, -err.u, 0.1 * std::abs(err.u)) << what;
      const double e = job.setup.face.rakeOffset;
      EXPECT_NEAR(got.rakeAngle, -err.u / std::sqrt(rTip * rTip - e * e), 0.1 * std::abs(err.u) / rTip) << what;
    }
  }
}

TEST(Inspection, RakeErrorGearEffectAgainstTheRuleOfThumbAndTheFirstOrderFormula) {
  // A typical module-5 hob: 100 mm outside diameter, 12 gashes, a cam relief of 5 mm (a radial
  // relief angle of 10.8 deg at the tip), zero rake, straight gash. The rule of thumb: about 4' of
  // pressure angle per 1 deg of hook or drag on a 14.5 deg hob, about 5' on a 20 deg hob.
  // First order (docs/inspection.md, "Rake error"): d alpha / d gamma = sqrt(r_a^2 - e^2) k sin(alpha_n) cos(alpha_n) / r_p^2.
  const Json hob = Json::parse(R"({"format": "hobsharp-case/1",
    "hob": {"normalModule": 5, "normalPressureAngle": 20, "outerDiameter": 100, "pitchDiameter": 87.5, "gashDepth": 16,
            "length": 100, "rakeOffset": 0, "gash": "straight", "hand": "right", "gashes": 12, "relief": 5},
    "wheel": {"outerDiameter": 125}, "setup": {"tilt": 15}, "machine": {"K1": 100, "K2": 10}, "degree": 4})");
  for (const auto& [alpha, rule] : {std::pair{14.5, 4.0}, std::pair{20.0, 5.0}}) {
    Json j = hob;
    j["hob"]["normalPressureAngle"] = alpha;
    auto e = evaluateCase(j.dump());
    ASSERT_TRUE(e.ok()) << e.error().message;
    ASSERT_TRUE(e->pressureAnglePerRake);
    const double perDegree = *e->pressureAnglePerRake * 60;  // arc-min per deg
    const double k = 5.0 * 12 / (2 * kPi), a = alpha * kRadPerDeg;
    const double firstOrder = 50 * k * std::sin(a) * std::cos(a) / (43.75 * 43.75) * 60;
    // A hook (material off the face, the edge meeting the flank where it is relieved more toward the
    // root) gives the gear a smaller pressure angle; drag a larger one.
    EXPECT_LT(perDegree, 0) << alpha;
    EXPECT_NEAR(-perDegree, firstOrder, 0.03 * firstOrder) << alpha;
    EXPECT_NEAR(-perDegree, rule, 0.25 * rule) << alpha << " deg: " << perDegree << "' per deg";
    // The result's figures: per degree, and for the rake error the face shows.
    const Json r = Json::parse(resultJson(*e));
    EXPECT_NEAR(r["gearEffect"]["pressureAnglePerDegreeOfRake"].get<double>(), perDegree, 1e-12);
    EXPECT_NEAR(r["gearEffect"]["rakeErrorPressureAngle"].get<double>(), perDegree * r["inspection"]["rakeAngle"].get<double>() / 60, 1e-12);
  }
  // The figure per degree is linear: a measured hook of 0.1 mm (0.115 deg at the tip) gives the
  // model's own pressure-angle change on that face to within 2 %.
  Json j = hob;
  auto nominal = evaluateCase(j.dump());
  ASSERT_TRUE(nominal.ok());
  const SharpeningJob& job = nominal->job;
  const FaceLines lines = FaceLines::of(job.setup, job.grid);
  Json rows = Json::array();
  const Eigen::MatrixXd hook = rakeErrorFace(lines, 0.1);
  for (int i = 0; i < hook.rows(); ++i) {
    Json row = Json::array();
    for (int c = 0; c < hook.cols(); ++c) row.push_back(hook(i, c));
    rows.push_back(row);
  }
  j["measured"] = rows;
  auto e = evaluateCase(j.dump());
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->gearEffect);
  const Json r = Json::parse(resultJson(*e));
  const double direct = 0.5 * (e->gearEffect->left.pressureAngle + e->gearEffect->right.pressureAngle) * kDegPerRad * 60;
  EXPECT_NEAR(r["inspection"]["rakeAngle"].get<double>(), 0.1 / 50 * kDegPerRad * 60, 1e-9);
  EXPECT_NEAR(r["gearEffect"]["rakeErrorPressureAngle"].get<double>(), direct, 0.02 * std::abs(direct));
}

TEST(Inspection, OneGashMisIndexedBy10MicrometresAndItsIndexingCorrection) {
  std::vector<double> d(12, 0.0);
  d[2] = 10;
  const GashSpacing s = gashSpacing(d);
  ASSERT_EQ(s.adjacent.size(), 12u);
  EXPECT_DOUBLE_EQ(s.adjacent[1], 10);   // gash 3 minus gash 2
  EXPECT_DOUBLE_EQ(s.adjacent[2], -10);  // gash 4 minus gash 3
  for (std::size_t k : {0u, 3u, 4u, 11u}) EXPECT_DOUBLE_EQ(s.adjacent[k], 0);
  EXPECT_DOUBLE_EQ(s.adjacentLargest, 10);
  EXPECT_DOUBLE_EQ(s.cumulative, 10);
  // The pitch jump f_uN: pitch k's single pitch deviation minus pitch k-1's: +10 (pitch 2 after
  // pitch 1), -20 (pitch 3 after pitch 2), +10 (pitch 4 after pitch 3), 0 elsewhere.
  ASSERT_EQ(s.pitchJump.size(), 12u);
  EXPECT_DOUBLE_EQ(s.pitchJump[1], 10);
  EXPECT_DOUBLE_EQ(s.pitchJump[2], -20);
  EXPECT_DOUBLE_EQ(s.pitchJump[3], 10);
  for (std::size_t k : {0u, 4u, 11u}) EXPECT_DOUBLE_EQ(s.pitchJump[k], 0);
  EXPECT_DOUBLE_EQ(s.pitchJumpLargest, -20);
  // A steady drift (every gash 2 µm further on) has a single pitch deviation of 2 µm on every
  // pitch but the closing one, and its jumps are at the close only.
  const GashSpacing drift = gashSpacing({0, 2, 4, 6, 8, 10});
  EXPECT_DOUBLE_EQ(drift.pitchJump[1], 0);
  EXPECT_DOUBLE_EQ(drift.pitchJump[2], 0);
  EXPECT_DOUBLE_EQ(drift.pitchJump[5], -12);
  EXPECT_DOUBLE_EQ(std::abs(drift.pitchJumpLargest), 12);

  // 30000 µm per rad (the paper's face at the pitch radius is about that): gash 3 turns back by
  // (10 - 10/12) / 30000 rad, the others forward by (10/12) / 30000 rad; then every face is at the mean.
  const double perRadian = 30000;
  const IndexCorrection exact = indexCorrection(d, perRadian, 0);
  EXPECT_NEAR(exact.angle[2], -(10 - 10.0 / 12) / perRadian, 1e-15);
  EXPECT_NEAR(exact.angle[0], (10.0 / 12) / perRadian, 1e-15);
  EXPECT_NEAR(exact.angle[2] - exact.angle[0], -10 / perRadian, 1e-15);
  const GashSpacing after = gashSpacing(exact.after);
  EXPECT_NEAR(after.cumulative, 0, 1e-12);
  EXPECT_NEAR(after.adjacentLargest, 0, 1e-12);
  // Rounded to the A axis's step (0.0001 deg), the faces are within half a step of the mean.
  const double step = 1e-4 * kRadPerDeg;
  const IndexCorrection rounded = indexCorrection(d, perRadian, step);
  for (std::size_t k = 0; k < d.size(); ++k) {
    EXPECT_NEAR(std::remainder(rounded.rounded[k], step), 0, 1e-18);
    EXPECT_LE(std::abs(rounded.after[k] - 10.0 / 12), 0.5 * perRadian * step + 1e-12);
  }
  EXPECT_GT(gashSpacing(rounded.after).cumulative, 0) << "the rounding leaves something (here 0.52 µm per step)";
}

TEST(Inspection, TheIndexSensitivityIsTheSimulatedFacesOwnAColumn) {
  // The column "A a0" of the sensitivity matrix (Eqs. 13-16, solved on the ground face) against
  // the rigid turn of index_correction.h, at every grid point of the paper's case.
  const SharpeningJob job = test::jobOf(test::paperCase());
  auto e = evaluate(job);
  ASSERT_TRUE(e.ok());
  const Coefficient a0{Axis::A, 0};
  int column = -1;
  for (std::size_t k = 0; k < e->sensitivities.coefficients.size(); ++k)
    if (e->sensitivities.coefficients[k] == a0) column = static_cast<int>(k);
  ASSERT_GE(column, 0);
  const Eigen::MatrixXd s = e->sensitivities.topography(column);
  for (int i = 0; i < job.grid.rows(); ++i)
    for (int j = 0; j < job.grid.cols(); ++j)
      EXPECT_NEAR(deviationPerIndexAngle(job.setup, job.grid.r[i], job.grid.x[j]), s(i, j), 1e-6 * std::abs(s(i, j)))
          << i << ", " << j;
  // docs/conventions.md, Sensitivities: A a0 + 0.01 rad gives 188.268 µm at r = 19 mm. That is a
  // finite turn, this a derivative: they agree to the second-order term, a few parts in 1e5.
  EXPECT_NEAR(0.01 * deviationPerIndexAngle(job.setup, 19, 0), 188.268, 1e-4 * 188.268);
}

TEST(Inspection, TheDefaultTableIsTheCataloguesAndValidAndSaysWhereEachValueIsFrom) {
  const ToleranceTable& t = defaultToleranceTable();
  EXPECT_TRUE(checkToleranceTable(t, "table").ok());
  ASSERT_EQ(t.bands(), 9);
  EXPECT_DOUBLE_EQ(t.moduleEdges.front(), 0.63);
  EXPECT_DOUBLE_EQ(t.moduleEdges.back(), 40);
  EXPECT_EQ(t.at(Check::AdjacentSpacing, ToleranceClass::AA, 0), 10.0);
  EXPECT_EQ(t.at(Check::AdjacentSpacing, ToleranceClass::D, 8), 630.0);
  EXPECT_EQ(t.at(Check::PitchJump, ToleranceClass::C, 8), 345.0);  // as printed
  // Luren's slide prints the form and position of the cutting face: AA 10, 10, 12, 16, 20, 25 and
  // A 12, 16, 20, 25 for the bands from 0.63-1 on; the rest is the catalogue's series, marked so.
  const std::vector<double> aa{10, 10, 12, 16, 20, 25};
  for (int b = 0; b < 6; ++b) {
    EXPECT_EQ(t.at(Check::RadialAlignment, ToleranceClass::AA, b), aa[b]) << b;
    EXPECT_EQ(t.confidenceAt(Check::RadialAlignment, ToleranceClass::AA, b), Confidence::Printed) << b;
  }
  EXPECT_EQ(t.confidenceAt(Check::RadialAlignment, ToleranceClass::AA, 6), Confidence::Series);
  EXPECT_EQ(t.at(Check::RadialAlignment, ToleranceClass::A, 3), 25.0);
  EXPECT_EQ(t.confidenceAt(Check::RadialAlignment, ToleranceClass::A, 3), Confidence::Printed);
  EXPECT_EQ(t.confidenceAt(Check::RadialAlignment, ToleranceClass::A, 4), Confidence::Series);
  EXPECT_EQ(t.confidenceAt(Check::RadialAlignment, ToleranceClass::D, 0), Confidence::Series);
  // The gash lead per 100 mm: AA 50, A 70, B 100 on every band, and no C or D.
  for (int b = 0; b < 9; ++b) {
    EXPECT_EQ(t.at(Check::GashLead, ToleranceClass::A, b), 70.0);
    EXPECT_FALSE(t.at(Check::GashLead, ToleranceClass::C, b));
    EXPECT_EQ(t.loosest(Check::GashLead, b), ToleranceClass::B);
  }
  // The form alone has no public row: not graded, and the table says so.
  for (ToleranceClass k : kClasses) EXPECT_FALSE(t.at(Check::CuttingFaceForm, k, 3));
  EXPECT_STREQ(defaultToleranceSource(Check::CuttingFaceForm), "");
  EXPECT_NE(std::string(defaultToleranceSource(Check::AdjacentSpacing)).find("p. 45"), std::string::npos);
  EXPECT_NE(std::string(defaultToleranceSource(Check::RadialAlignment)).find("Luren"), std::string::npos);
  EXPECT_NE(std::string(defaultSeriesSource(Check::RadialAlignment)).find("not confirmed"), std::string::npos);
  EXPECT_NE(std::string(defaultToleranceSource(Check::PitchJump)).find("pitch jump"), std::string::npos);
}

TEST(Inspection, AMeasuredFaceIsGradedOnEveryModuleBandWithTheDefaultTable) {
  // No gash deviations: the radial alignment alone grades the face, from module 0.64 to 40.
  FaceChecks face;
  face.radialAlignment = -9;
  face.cuttingFaceForm = 3;
  const ToleranceTable& t = defaultToleranceTable();
  for (double m : {0.64, 1.0, 1.3, 2.0, 3.0, 5.0, 8.0, 12.0, 20.0, 30.0, 40.0}) {
    const Inspection in = inspect(face, std::nullopt, t, m, MeasurementUncertainty::of(2, 100));
    EXPECT_EQ(in.grade, Grade::AA) << m;
    EXPECT_EQ(in.limiting, Check::RadialAlignment) << m;
    EXPECT_NE(in.conformity, Conformity::NotGraded) << m;
  }
}

TEST(Inspection, TheGuardBandOfTheMeasurementsUncertainty) {
  // Module 2 (band 1.6 to 2.5): radial alignment AA 12, A 20, B 40, C 80, D 160 µm. U = 2 µm.
  const ToleranceTable& t = defaultToleranceTable();
  auto at = [&](double value, double u) {
    FaceChecks face;
    face.radialAlignment = value;
    return inspect(face, std::nullopt, t, 2, MeasurementUncertainty::of(u, 100));
  };
  // 9 µm: within 12 - 2, conforms to AA, AA proven.
  Inspection in = at(9, 2);
  EXPECT_EQ(in.grade, Grade::AA);
  EXPECT_EQ(in.find(Check::RadialAlignment)->conformity, Conformity::Conforms);
  EXPECT_EQ(in.proven, Grade::AA);
  EXPECT_EQ(in.conformity, Conformity::Conforms);
  // -11 µm: class AA without the uncertainty, but within U of 12: undecided, and A is what is proven.
  in = at(-11, 2);
  EXPECT_EQ(in.grade, Grade::AA);
  EXPECT_EQ(in.find(Check::RadialAlignment)->conformity, Conformity::Undecided);
  EXPECT_EQ(in.proven, Grade::A);
  EXPECT_EQ(in.conformity, Conformity::Undecided);
  // 13 µm: class A; against AA it would not conform (13 < 12 + 2 is still undecided there), against
  // A's 20 it conforms; proven A.
  in = at(13, 2);
  EXPECT_EQ(in.grade, Grade::A);
  EXPECT_EQ(in.find(Check::RadialAlignment)->conformity, Conformity::Conforms);
  EXPECT_EQ(in.proven, Grade::A);
  // Beyond the loosest class by more than U: does not conform; by less: undecided.
  EXPECT_EQ(at(160 + 2.5, 2).grade, Grade::OutsideD);
  EXPECT_EQ(at(160 + 2.5, 2).find(Check::RadialAlignment)->conformity, Conformity::DoesNotConform);
  EXPECT_EQ(at(160 + 1.5, 2).find(Check::RadialAlignment)->conformity, Conformity::Undecided);
  EXPECT_EQ(at(160 + 2.5, 2).proven, Grade::OutsideD);
  EXPECT_EQ(provenText(at(160 - 1.5, 2).proven), "none");
  // With U = 0 the two classes are the same; U above a tenth of the tolerance is flagged.
  EXPECT_EQ(at(11, 0).proven, Grade::AA);
  EXPECT_TRUE(at(11, 0).uncertaintyAboveTenth.empty());
  EXPECT_EQ(at(11, 2).uncertaintyAboveTenth, std::vector<Check>{Check::RadialAlignment});
  // The gash lead's U is per 100 mm: 2 µm over 50 mm of hob is 4 µm per 100 mm.
  EXPECT_DOUBLE_EQ(MeasurementUncertainty::of(2, 50).of(Check::GashLead), 4);
  EXPECT_DOUBLE_EQ(MeasurementUncertainty::of(2, 50).of(Check::PitchJump), 2);
}

// A reading computed at a tolerance carries the rounding of its arithmetic: 34.7 - 16.0 x 24.25 / 40
// is 25.000000000000004 in doubles, the indicator's 25.0 µm. It is graded at AA's 25 µm (module 7),
// its conformity there undecided, not pushed into class A by 4e-15 µm; a reading 1e-5 µm beyond is A.
TEST(Inspection, AReadingAtAToleranceIsGradedByItsValueNotItsRounding) {
  const ToleranceTable& t = defaultToleranceTable();
  const double reading = 34.7 - 16.0 * 24.25 / 40;
  ASSERT_GT(reading, 25.0) << "the arithmetic's rounding this test is about";
  auto at = [&](double value) {
    FaceChecks face;
    face.radialAlignment = value;
    return inspect(face, std::nullopt, t, 7, MeasurementUncertainty::of(2, 100));
  };
  EXPECT_EQ(at(reading).grade, Grade::AA);
  EXPECT_EQ(at(reading).conformity, Conformity::Undecided);
  EXPECT_EQ(at(-reading).grade, Grade::AA);
  EXPECT_EQ(at(25.00001).grade, Grade::A);
  // A reason to leave the face's checks ungraded keeps their readings and grades nothing of them.
  FaceChecks face;
  face.radialAlignment = 5;
  const Inspection in = inspect(face, std::nullopt, t, 7, MeasurementUncertainty::of(2, 100), "a reason");
  EXPECT_EQ(in.grade, Grade::NotGraded);
  EXPECT_EQ(in.find(Check::RadialAlignment)->grade, Grade::NotGraded);
  EXPECT_DOUBLE_EQ(in.find(Check::RadialAlignment)->value, 5);
  EXPECT_EQ(in.faceNotGraded, "a reason");
}

TEST(Inspection, TheClassTableAtItsBandEdges) {
  const ToleranceTable& t = defaultToleranceTable();
  // "over 0.63 to 1": 0.63 itself is outside, 1 is in the first band, just above 1 the second.
  EXPECT_FALSE(moduleBand(t, 0.63));
  EXPECT_EQ(moduleBand(t, 0.64), 0);
  EXPECT_EQ(moduleBand(t, 1.0), 0);
  EXPECT_EQ(moduleBand(t, std::nextafter(1.0, 2.0)), 1);
  EXPECT_EQ(moduleBand(t, 2.5), 2);
  EXPECT_EQ(moduleBand(t, 7), 5);
  EXPECT_EQ(moduleBand(t, 40), 8);
  EXPECT_FALSE(moduleBand(t, std::nextafter(40.0, 41.0)));
  // Over 1.6 to 2.5 the adjacent spacing's tolerances are 12, 20, 40, 80, 160 µm.
  EXPECT_EQ(gradeOf(t, Check::AdjacentSpacing, 2, 12), Grade::AA);
  EXPECT_EQ(gradeOf(t, Check::AdjacentSpacing, 2, std::nextafter(12.0, 13.0)), Grade::A);
  EXPECT_EQ(gradeOf(t, Check::AdjacentSpacing, 2, 20), Grade::A);
  EXPECT_EQ(gradeOf(t, Check::AdjacentSpacing, 2, 79), Grade::C);
  EXPECT_EQ(gradeOf(t, Check::AdjacentSpacing, 2, 160), Grade::D);
  EXPECT_EQ(gradeOf(t, Check::AdjacentSpacing, 2, 160.01), Grade::OutsideD);
  EXPECT_EQ(gradeOf(t, Check::CuttingFaceForm, 2, 1), Grade::NotGraded);
  EXPECT_STREQ(gradeName(Grade::OutsideD), "outside D");
}

TEST(Inspection, TheClassIsTheWorstCheckAndNamesIt) {
  const ToleranceTable& t = defaultToleranceTable();
  const MeasurementUncertainty noU = MeasurementUncertainty::of(0, 100);
  FaceChecks face;
  face.radialAlignment = -30;
  face.cuttingFaceForm = 4;
  // Over 6.3 to 10 (module 7): radial alignment AA 25, A 40: class A. Gash 2 off by 30 µm: single
  // pitch +-30 (A), pitch jump -60 (B: 80): the pitch jump limits.
  const GashSpacing s = gashSpacing({0, 30, 0, 0});
  EXPECT_DOUBLE_EQ(s.pitchJumpLargest, -60);
  Inspection in = inspect(face, s, t, 7, noU);
  ASSERT_TRUE(in.band);
  EXPECT_EQ(in.find(Check::RadialAlignment)->grade, Grade::A);
  EXPECT_EQ(in.find(Check::CuttingFaceForm)->grade, Grade::NotGraded);
  EXPECT_EQ(in.find(Check::AdjacentSpacing)->grade, Grade::A);
  EXPECT_EQ(in.find(Check::PitchJump)->grade, Grade::B);
  EXPECT_EQ(in.grade, Grade::B);
  EXPECT_EQ(in.limiting, Check::PitchJump);
  // Of two checks of the same grade, the one using more of its tolerance limits: without spacing
  // the alignment alone.
  in = inspect(face, std::nullopt, t, 7, noU);
  EXPECT_EQ(in.grade, Grade::A);
  EXPECT_EQ(in.limiting, Check::RadialAlignment);
  EXPECT_EQ(in.find(Check::RadialAlignment)->tolerances, (std::vector<double>{25, 40, 80, 160, 315}));
  // A table that stops at B: beyond it is "outside B".
  FaceChecks lead;
  lead.gashLead = 120;
  in = inspect(lead, std::nullopt, t, 7, noU);
  EXPECT_EQ(in.find(Check::GashLead)->grade, Grade::OutsideD);
  EXPECT_EQ(classText(in), "outside B");
  // No band for the module: not graded, nothing limits.
  in = inspect(face, std::nullopt, t, 50, noU);
  EXPECT_EQ(in.grade, Grade::NotGraded);
  EXPECT_FALSE(in.limiting);
}

Json paperJson() { return Json::parse(test::readFile("tab1.json")); }

Error refusal(const Json& j) {
  auto e = evaluateCase(j.dump());
  EXPECT_FALSE(e.ok());
  return e.ok() ? Error{} : e.error();
}

TEST(Inspection, TheCaseCarriesGashDeviationsAndAnEditedTable) {
  Json j = paperJson();
  std::vector<double> d(12, 0.0);
  d[2] = 30;
  j["inspection"]["gashDeviations"] = d;
  auto e = evaluateCase(j.dump());
  ASSERT_TRUE(e.ok()) << e.error().message;
  Json r = Json::parse(resultJson(*e));
  EXPECT_EQ(r["inspection"]["source"], "simulated");
  EXPECT_EQ(r["inspection"]["moduleBand"], "over 6.3 to 10 mm");
  EXPECT_EQ(r["inspection"]["moduleBandIndex"], 5);
  EXPECT_DOUBLE_EQ(r["inspection"]["adjacentSpacing"].get<double>(), 30);
  EXPECT_DOUBLE_EQ(r["inspection"]["cumulativeSpacing"].get<double>(), 30);
  // 30 µm of single pitch: over AA's 25, within A's 40; a pitch jump of -60 µm: B's 80.
  EXPECT_DOUBLE_EQ(r["inspection"]["pitchJump"].get<double>(), -60);
  EXPECT_EQ(r["inspection"]["checks"]["adjacentSpacing"]["grade"], "A");
  EXPECT_EQ(r["inspection"]["class"], "B");
  EXPECT_EQ(r["inspection"]["limitingCheck"], "pitchJump");
  EXPECT_EQ(r["inspection"]["checks"]["adjacentSpacing"]["tolerances"], Json({25, 40, 80, 160, 315}));
  EXPECT_EQ(r["inspection"]["checks"]["radialAlignment"]["grade"], "AA");
  EXPECT_EQ(r["inspection"]["checks"]["radialAlignment"]["confidence"], "printed");
  EXPECT_EQ(r["inspection"]["checks"]["cuttingFaceForm"]["grade"], "not graded");
  EXPECT_NE(r["inspection"]["notGraded"].get<std::string>().find("cutting-face form"), std::string::npos);
  EXPECT_NE(r["inspection"]["notGraded"].get<std::string>().find("Enter the hob maker"), std::string::npos);
  // The nominal face has no deviation to speak of.
  EXPECT_LT(std::abs(r["inspection"]["radialAlignment"].get<double>()), 1e-6);
  // After the rounded indexing correction the gashes are within half an A step of each other.
  EXPECT_EQ(r["inspection"]["after"]["class"], "AA");
  EXPECT_LT(r["inspection"]["after"]["cumulativeSpacing"].get<double>(), 0.6);
  ASSERT_EQ(r["inspection"]["indexCorrectionDeg"].size(), 12u);
  const double perRadian = e->indexCorrection->perRadian;
  EXPECT_NEAR(r["inspection"]["indexCorrection"][2].get<double>() - r["inspection"]["indexCorrection"][0].get<double>(),
              -30 / perRadian * 1e6, 1e-9);

  // A measured face with 0.05 mm taken off (a hook), with a table that grades radial alignment.
  j = paperJson();
  const SharpeningJob job = test::jobOf(test::paperCase());
  const FaceLines lines = FaceLines::of(job.setup, job.grid);
  const Eigen::MatrixXd tilt = rakeErrorFace(lines, 0.05);
  Json rows = Json::array();
  for (int i = 0; i < tilt.rows(); ++i) {
    Json row = Json::array();
    for (int k = 0; k < tilt.cols(); ++k) row.push_back(tilt(i, k));
    rows.push_back(row);
  }
  j["measured"] = rows;
  Json table = Json::parse(R"({"moduleBands": [6.3, 10], "checks": {"radialAlignment": {"AA": [10], "A": [16], "B": [32]}}})");
  j["inspection"]["tolerances"] = table;
  e = evaluateCase(j.dump());
  ASSERT_TRUE(e.ok()) << e.error().message;
  r = Json::parse(resultJson(*e));
  EXPECT_EQ(r["inspection"]["source"], "measured");
  EXPECT_NEAR(r["inspection"]["radialAlignment"].get<double>(), -50 * 21.0 / 40, 1e-9);
  EXPECT_NEAR(r["inspection"]["rakeOffset"].get<double>(), 0.05, 1e-12);
  EXPECT_NEAR(r["inspection"]["rakeAngle"].get<double>(), 0.05 / 40 * kDegPerRad * 60, 1e-9);
  EXPECT_EQ(r["inspection"]["checks"]["radialAlignment"]["confidence"], "entered");
  EXPECT_EQ(r["inspection"]["class"], "B");
  EXPECT_EQ(r["inspection"]["limitingCheck"], "radialAlignment");
  ASSERT_TRUE(r["inspection"].contains("after"));
  // The correction predicts its face; the verdict after is graded by the same table.
  EXPECT_NEAR(r["inspection"]["after"]["radialAlignment"].get<double>(),
              checkFace(e->correction->after.normal, lines, true).radialAlignment, 1e-12);
  EXPECT_FALSE(r["inspection"]["after"]["class"].get<std::string>().empty());
  // The data file itself is a table the case takes.
  j["inspection"]["tolerances"] = Json::parse(test::readFile("../../data/din3968-cutting-face.json"));
  EXPECT_TRUE(evaluateCase(j.dump()).ok());
}

TEST(Inspection, BadInspectionInputIsRefusedNamingTheField) {
  auto with = [](const char* member, const Json& value) {
    Json j = paperJson();
    j["inspection"][member] = value;
    return j;
  };
  auto tableWith = [&](const char* patch) {
    Json t = Json::parse(R"({"moduleBands": [1, 2, 4], "checks": {"adjacentSpacing": {"AA": [10, 12], "A": [20, 25]}}})");
    t.merge_patch(Json::parse(patch));
    return with("tolerances", t);
  };
  EXPECT_EQ(refusal(with("gashDeviations", Json::array({1}))).field, "inspection.gashDeviations");
  EXPECT_EQ(refusal(with("gashDeviations", Json::array())).field, "inspection.gashDeviations");
  EXPECT_EQ(refusal(with("gashDeviations", Json::array({1, "a"}))).field, "inspection.gashDeviations[1]");
  EXPECT_EQ(refusal(with("gashDeviations", Json::array({1, 2e4}))).field, "inspection.gashDeviations[1]");
  EXPECT_EQ(refusal(with("gashDeviations", Json(std::vector<double>(101, 0.0)))).field, "inspection.gashDeviations");
  EXPECT_EQ(refusal(with("gashDeviation", Json::array({1, 2}))).field, "inspection.gashDeviation");
  EXPECT_EQ(refusal(tableWith(R"({"moduleBands": [1, 4, 2]})")).field, "inspection.tolerances.moduleBands[2]");
  EXPECT_EQ(refusal(tableWith(R"({"moduleBands": [1]})")).field, "inspection.tolerances.moduleBands");
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"adjacentSpacing": {"A": [20]}}})")).field,
            "inspection.tolerances.checks.adjacentSpacing.A");
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"adjacentSpacing": {"A": [20, -1]}}})")).field,
            "inspection.tolerances.checks.adjacentSpacing.A[1]");
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"adjacentSpacing": {"A": [5, 25]}}})")).field,
            "inspection.tolerances.checks.adjacentSpacing.A[0]");  // looser than AA's 10 yet tighter
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"adjacentSpacing": {"A": [20, "x"]}}})")).field,
            "inspection.tolerances.checks.adjacentSpacing.A[1]");
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"spacing": {"A": [20, 25]}}})")).field,
            "inspection.tolerances.checks.spacing");
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"adjacentSpacing": {"E": [20, 25]}}})")).field,
            "inspection.tolerances.checks.adjacentSpacing.E");
  EXPECT_EQ(refusal(tableWith(R"({"format": "other"})")).field, "inspection.tolerances.format");
  EXPECT_EQ(refusal(with("uncertainty", -1)).field, "inspection.uncertainty");
  EXPECT_EQ(refusal(with("uncertainty", 101)).field, "inspection.uncertainty");
  EXPECT_EQ(refusal(with("uncertainty", "2")).field, "inspection.uncertainty");
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"cumulativeSpacing": {"AA": [20, 25]}}})")).field,
            "inspection.tolerances.checks.cumulativeSpacing");
  EXPECT_EQ(refusal(tableWith(R"({"checks": {"adjacentSpacing": {"confidence": {"AA": ["printed", "guessed"]}}}})")).field,
            "inspection.tolerances.checks.adjacentSpacing.confidence.AA[1]");
  const Error e = refusal(tableWith(R"({"checks": {"adjacentSpacing": {"A": [20, -1]}}})"));
  EXPECT_EQ(e.message.rfind("inspection.tolerances.checks.adjacentSpacing.A[1]: ", 0), 0u) << e.message;
}

Json gridJson(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (int i = 0; i < m.rows(); ++i) {
    Json row = Json::array();
    for (int k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    rows.push_back(row);
  }
  return rows;
}

TEST(Inspection, AGashsDeviationAtThePitchRadiusIsItsFittedLineThere) {
  // 3 µm at the pitch radius, a tilt of 0.5 µm per mm and a shape along the gash that averages out.
  const double rp = 31.25;
  const Eigen::MatrixXd g = faceOf(kR, kX, [&](double r, double x) { return 3 + 0.5 * (r - rp) + 0.01 * x; });
  EXPECT_NEAR(deviationAtRadius(g, kR, rp), 3, 1e-12);
  // A bow over the radius: the least-squares line through it at rp, against the same fit by Eigen's QR.
  const Eigen::MatrixXd bow = faceOf(kR, kX, [&](double r, double) { return 0.02 * (r - 19) * (r - 40); });
  Eigen::MatrixXd A(kR.size(), 2);
  Eigen::VectorXd y(kR.size());
  for (std::size_t i = 0; i < kR.size(); ++i) A(i, 0) = 1, A(i, 1) = kR[i], y(i) = bow(i, 0);
  const Eigen::Vector2d c = A.colPivHouseholderQr().solve(y);
  EXPECT_NEAR(deviationAtRadius(bow, kR, rp), c(0) + c(1) * rp, 1e-12);
}

TEST(Inspection, OneTopographyPerGashGivesTheSpacingAndTheWorstGashsFace) {
  // Four gashes: all with the same 2 µm face, gash 3 mis-indexed by 10 µm, gash 2 tilted 1 µm per mm.
  const SharpeningJob job = test::jobOf(test::paperCase());
  const double rp = job.setup.face.pitchRadius;
  std::vector<Eigen::MatrixXd> gashes(4, faceOf(job.grid.r, job.grid.x, [](double, double) { return 2.0; }));
  gashes[2].array() += 10;
  gashes[1] = faceOf(job.grid.r, job.grid.x, [&](double r, double) { return 2 + (r - rp); });
  // On radial lines (s = r) the readings are known by hand: gash 2's indicator, zeroed at 40 mm,
  // reads (2 + 19 - r_p) - (2 + 40 - r_p) 19 / 40 at the root, the largest of the hob.
  const GashFaces radial = inspectGashFaces(gashes, FaceLines::radial(job.grid.r, job.grid.x), true, rp);
  ASSERT_EQ(radial.deviations.size(), 4u);
  for (int k : {0, 1, 3}) EXPECT_NEAR(radial.deviations[k], 2, 1e-12) << k;
  EXPECT_NEAR(radial.deviations[2], 12, 1e-12);
  EXPECT_NEAR(radial.worst.radialAlignment, (2 + 19 - rp) - (2 + 40 - rp) * 19 / 40, 1e-9);
  EXPECT_NEAR(radial.faces[1].radialAlignment, radial.worst.radialAlignment, 0);
  EXPECT_NEAR(radial.faces[2].radialAlignment, 12 * 21.0 / 40, 1e-9);
  EXPECT_NEAR(radial.worst.cuttingFaceForm, 0, 1e-12);
  // The case reads them on the hob's own lines.
  const GashFaces f = inspectGashFaces(gashes, FaceLines::of(job.setup, job.grid), true, rp);
  EXPECT_NEAR(f.faces[1].radialAlignment, f.worst.radialAlignment, 0);

  Json j = paperJson();
  for (const Eigen::MatrixXd& g : gashes) j["inspection"]["gashTopographies"].push_back(gridJson(g));
  auto e = evaluateCase(j.dump());
  ASSERT_TRUE(e.ok()) << e.error().message;
  Json r = Json::parse(resultJson(*e));
  EXPECT_EQ(r["inspection"]["source"], "gashTopographies");
  EXPECT_NEAR(r["inspection"]["cumulativeSpacing"].get<double>(), 10, 1e-9);
  EXPECT_NEAR(std::abs(r["inspection"]["adjacentSpacing"].get<double>()), 10, 1e-9);
  EXPECT_NEAR(r["inspection"]["radialAlignment"].get<double>(), f.worst.radialAlignment, 1e-12);
  EXPECT_NEAR(r["inspection"]["perGash"]["deviation"][2].get<double>(), 12, 1e-9);
  EXPECT_NEAR(r["inspection"]["perGash"]["radialAlignment"][1].get<double>(), f.worst.radialAlignment, 1e-12);
  // The same spacing as the deviations given directly, and the same indexing correction.
  Json d = paperJson();
  d["inspection"]["gashDeviations"] = f.deviations;
  Json rd = Json::parse(resultJson(*evaluateCase(d.dump())));
  EXPECT_EQ(r["inspection"]["indexCorrection"], rd["inspection"]["indexCorrection"]);
  EXPECT_EQ(r["inspection"]["after"]["cumulativeSpacing"], rd["inspection"]["after"]["cumulativeSpacing"]);
  // The indexing correction leaves the faces' form: after it, the worst gash's alignment stays.
  EXPECT_NEAR(r["inspection"]["after"]["radialAlignment"].get<double>(), f.worst.radialAlignment, 1e-12);
}

TEST(Inspection, BadGashTopographiesAreRefusedNamingTheGash) {
  const SharpeningJob job = test::jobOf(test::paperCase());
  const Json flat = gridJson(Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()));
  Json j = paperJson();
  j["inspection"]["gashTopographies"] = Json::array({flat});
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies");  // one gash
  j["inspection"]["gashTopographies"] = Json::array({flat, gridJson(Eigen::MatrixXd::Zero(3, 9))});
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies[1]");
  Json bad = flat;
  bad[2][4] = "x";
  j["inspection"]["gashTopographies"] = Json::array({flat, bad});
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies[1][2][4]");
  bad[2][4] = 2e4;
  j["inspection"]["gashTopographies"] = Json::array({flat, bad});
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies[1][2][4]");
  // In words, the gash, row and value counted from 1 (issue 22).
  EXPECT_EQ(refusal(j).message, "Gash 2's topography, row 3 (r = 29.5 mm), value 5 (x = 0 mm): must lie within ±10000 µm (10 mm); got 20000 µm.");
  j["inspection"]["gashTopographies"] = Json::array({flat, flat});
  j["inspection"]["gashDeviations"] = Json::array({1, 2});
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies");
  j["inspection"]["gashTopographies"] = Json::array();
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies");
}

}  // namespace
}  // namespace hobsharp
