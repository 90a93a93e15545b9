// The rake-face inspection (core/inspection/, README "Rake-face inspection"): each check on
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

TEST(Inspection, APureTiltAlongTheRadiusIsARadialAlignmentDeviationAndNoForm) {
  // 2 µm per mm of radius, with a different offset on every axial line: the fitted line rises
  // 2 * 21 = 42 µm from root to tip; nothing is left about it; nothing changes along the gash.
  const FaceChecks c = checkFace(faceOf(kR, kX, [](double r, double) { return 2 * (r - 19) + 5; }), kR, kX, true);
  EXPECT_NEAR(c.radialAlignment, 42, 1e-9);
  EXPECT_NEAR(c.cuttingFaceForm, 0, 1e-9);
  ASSERT_TRUE(c.gashLead);
  EXPECT_NEAR(*c.gashLead, 0, 1e-9);
  // The tip behind the root: the sign says so.
  const FaceChecks back = checkFace(faceOf(kR, kX, [](double r, double) { return -0.5 * (r - 19); }), kR, kX, true);
  EXPECT_NEAR(back.radialAlignment, -10.5, 1e-9);
}

TEST(Inspection, ThePerLineFiguresAreTheLargestOverTheFace) {
  // The tilt grows along the gash: the largest is on the last axial line, 1 µm/mm * 21 mm... and
  // the one of largest magnitude keeps its sign.
  const FaceChecks c =
      checkFace(faceOf(kR, kX, [](double r, double x) { return -(x + 70) / 140 * (r - 19); }), kR, kX, false);
  EXPECT_NEAR(c.radialAlignment, -21, 1e-9);
  EXPECT_FALSE(c.gashLead) << "no gash lead on a straight gash";
}

TEST(Inspection, APureGashLeadSlopeIsAGashLeadDeviationPer100Millimetres) {
  // 0.05 µm per mm along the hob axis is 5 µm per 100 mm, on every radial line.
  const FaceChecks c = checkFace(faceOf(kR, kX, [](double, double x) { return 0.05 * x + 3; }), kR, kX, true);
  ASSERT_TRUE(c.gashLead);
  EXPECT_NEAR(*c.gashLead, 5, 1e-9);
  EXPECT_NEAR(c.radialAlignment, 0, 1e-9);
  EXPECT_NEAR(c.cuttingFaceForm, 0, 1e-9);
}

TEST(Inspection, ABowAlongTheRadiusIsFormNotAlignment) {
  // c (r - 29.5)^2 at r = 19, 29.5, 40: c h^2, 0, c h^2 with h = 10.5. The fitted line is flat at
  // 2/3 c h^2; the residuals c h^2 / 3, -2/3 c h^2, c h^2 / 3 spread c h^2 = 11.025 µm for c = 0.1.
  const std::vector<double> r{19, 29.5, 40};
  const FaceChecks c = checkFace(faceOf(r, kX, [](double rr, double) { return 0.1 * (rr - 29.5) * (rr - 29.5); }), r, kX, true);
  EXPECT_NEAR(c.cuttingFaceForm, 11.025, 1e-9);
  EXPECT_NEAR(c.radialAlignment, 0, 1e-9);
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

TEST(Inspection, TheDefaultTableIsTheCataloguesAndValid) {
  const ToleranceTable& t = defaultToleranceTable();
  EXPECT_TRUE(checkToleranceTable(t, "table").ok());
  ASSERT_EQ(t.bands(), 9);
  EXPECT_DOUBLE_EQ(t.moduleEdges.front(), 0.63);
  EXPECT_DOUBLE_EQ(t.moduleEdges.back(), 40);
  EXPECT_EQ(t.at(Check::AdjacentSpacing, ToleranceClass::AA, 0), 10.0);
  EXPECT_EQ(t.at(Check::AdjacentSpacing, ToleranceClass::D, 8), 630.0);
  EXPECT_EQ(t.at(Check::CumulativeSpacing, ToleranceClass::C, 8), 345.0);  // as printed
  // No public value was found for these: the table has none, and says where each value is from.
  for (Check c : {Check::CuttingFaceForm, Check::RadialAlignment, Check::GashLead}) {
    for (ToleranceClass k : kClasses) EXPECT_FALSE(t.at(c, k, 3)) << checkName(c);
    EXPECT_STREQ(defaultToleranceSource(c), "");
  }
  EXPECT_NE(std::string(defaultToleranceSource(Check::AdjacentSpacing)).find("p. 45"), std::string::npos);
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
  EXPECT_EQ(gradeOf(t, Check::RadialAlignment, 2, 1), Grade::NotGraded);
  EXPECT_STREQ(gradeName(Grade::OutsideD), "outside D");
}

TEST(Inspection, TheClassIsTheWorstCheckAndNamesIt) {
  ToleranceTable t = defaultToleranceTable();
  FaceChecks face;
  face.radialAlignment = -30;
  face.cuttingFaceForm = 4;
  // Only spacing has tolerances: the face checks are not graded, the class is the spacing's.
  GashSpacing s = gashSpacing({0, 30, 0, 0});  // adjacent +-30, cumulative 30
  Inspection in = inspect(face, s, t, 7);       // over 6.3 to 10: AA 25, A 40
  ASSERT_TRUE(in.band);
  EXPECT_EQ(in.find(Check::RadialAlignment)->grade, Grade::NotGraded);
  EXPECT_EQ(in.find(Check::AdjacentSpacing)->grade, Grade::A);
  EXPECT_EQ(in.grade, Grade::A);
  ASSERT_TRUE(in.limiting);
  // An edited table with a radial alignment row: -30 µm against AA 10, A 16, B 32 is class B and limits.
  auto& row = t.cells[static_cast<int>(Check::RadialAlignment)];
  for (int k = 0; k < 3; ++k) row[k].assign(t.bands(), std::optional<double>());
  row[0][5] = 10;
  row[1][5] = 16;
  row[2][5] = 32;
  ASSERT_TRUE(checkToleranceTable(t, "t").ok());
  in = inspect(face, s, t, 7);
  EXPECT_EQ(in.grade, Grade::B);
  EXPECT_EQ(in.limiting, Check::RadialAlignment);
  EXPECT_EQ(in.find(Check::RadialAlignment)->tolerances, (std::vector<double>{10, 16, 32}));
  // No band for the module, or no tolerance at all: not graded, nothing limits.
  in = inspect(face, std::nullopt, defaultToleranceTable(), 7);
  EXPECT_EQ(in.grade, Grade::NotGraded);
  EXPECT_FALSE(in.limiting);
  in = inspect(face, s, defaultToleranceTable(), 50);
  EXPECT_EQ(in.grade, Grade::NotGraded);
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
  EXPECT_EQ(r["inspection"]["class"], "A");  // 30 µm: over AA's 25, within A's 40
  EXPECT_EQ(r["inspection"]["checks"]["adjacentSpacing"]["tolerances"], Json({25, 40, 80, 160, 315}));
  EXPECT_EQ(r["inspection"]["checks"]["radialAlignment"]["grade"], "not graded");
  // The nominal face has no deviation to speak of.
  EXPECT_LT(std::abs(r["inspection"]["radialAlignment"].get<double>()), 1e-6);
  // After the rounded indexing correction the gashes are within half an A step of each other.
  EXPECT_EQ(r["inspection"]["after"]["class"], "AA");
  EXPECT_LT(r["inspection"]["after"]["cumulativeSpacing"].get<double>(), 0.6);
  ASSERT_EQ(r["inspection"]["indexCorrectionDeg"].size(), 12u);
  const double perRadian = e->indexCorrection->perRadian;
  EXPECT_NEAR(r["inspection"]["indexCorrection"][2].get<double>() - r["inspection"]["indexCorrection"][0].get<double>(),
              -30 / perRadian * 1e6, 1e-9);

  // A measured face tilted 1 µm per mm of radius, with a table that grades radial alignment.
  j = paperJson();
  const SharpeningJob job = test::jobOf(test::paperCase());
  const Eigen::MatrixXd tilt = faceOf(job.grid.r, job.grid.x, [](double rr, double) { return rr - 19; });
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
  EXPECT_NEAR(r["inspection"]["radialAlignment"].get<double>(), 21, 1e-9);
  EXPECT_EQ(r["inspection"]["class"], "B");
  EXPECT_EQ(r["inspection"]["limitingCheck"], "radialAlignment");
  ASSERT_TRUE(r["inspection"].contains("after"));
  // The correction predicts its face; the verdict after is graded by the same table.
  EXPECT_NEAR(r["inspection"]["after"]["radialAlignment"].get<double>(),
              checkFace(e->correction->after.normal, job.grid.r, job.grid.x, true).radialAlignment, 1e-12);
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
  const GashFaces f = inspectGashFaces(gashes, job.grid.r, job.grid.x, true, rp);
  ASSERT_EQ(f.deviations.size(), 4u);
  for (int k : {0, 1, 3}) EXPECT_NEAR(f.deviations[k], 2, 1e-12) << k;
  EXPECT_NEAR(f.deviations[2], 12, 1e-12);
  EXPECT_NEAR(f.worst.radialAlignment, job.grid.r.back() - job.grid.r.front(), 1e-9);
  EXPECT_NEAR(f.faces[1].radialAlignment, f.worst.radialAlignment, 0);
  EXPECT_NEAR(f.worst.cuttingFaceForm, 0, 1e-12);

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
  j["inspection"]["gashTopographies"] = Json::array({flat, flat});
  j["inspection"]["gashDeviations"] = Json::array({1, 2});
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies");
  j["inspection"]["gashTopographies"] = Json::array();
  EXPECT_EQ(refusal(j).field, "inspection.gashTopographies");
}

}  // namespace
}  // namespace hobsharp
