// The result model (core/result_model.h): one description, the same fields in the JSON writer and
// in the field list; optional fields only where they belong; no non-finite number handed out.
#include <algorithm>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "result_model.h"
#include "test_support.h"

namespace hobsharp {
namespace {

using Json = nlohmann::json;
using test::paperCase;

Evaluation evaluated(const CaseInput& in) {
  auto job = resolveJob(in);
  EXPECT_TRUE(job.ok()) << (job.ok() ? "" : job.error().message);
  auto r = evaluate(job.value());
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  return r.value();
}

// The paper's case with a measured topography of a machine error of the paper's size.
CaseInput measuredCase() {
  CaseInput in = paperCase();
  const SharpeningJob job = test::jobOf(in);
  AxisPolynomials run = job.nominalAxes;
  run[Axis::Y].a[0] += 0.01;
  run[Axis::B].a[2] += 0.001;
  in.measured = test::topographyFor(job, run).normal;
  // One topography per gash, so that the spacing, the indexing correction and the per-gash figures
  // are in the result too.
  for (double shift : {0.0, 1.5, -2.0, 0.5}) in.inspection.gashTopographies.push_back(in.measured->array() + shift);
  return in;
}

// The JSON's leaves as dotted paths, lists and axis objects counted as one field.
void leaves(const Json& j, const std::string& path, std::set<std::string>* out) {
  // An axes object {X: [a0..an], .., B: [..]} is one field; {X: number, ..} is five.
  if (j.is_object() && !(j.contains("X") && j.contains("B") && j["X"].is_array())) {
    for (auto it = j.begin(); it != j.end(); ++it) leaves(*it, path.empty() ? it.key() : path + "." + it.key(), out);
  } else {
    out->insert(path);
  }
}

TEST(ResultModel, FieldPathsAreUniqueAndOptionalOnesSayWhen) {
  std::set<std::string> paths;
  for (const FieldDescription& f : resultFields()) {
    EXPECT_TRUE(paths.insert(f.path).second) << f.path << " is described twice";
    EXPECT_FALSE(f.meaning.empty()) << f.path;
    // The inspection's optional fields: helical only, with per-gash deviations, or after a correction.
    const bool optionalInspection =
        f.path.rfind("inspection.after.", 0) == 0 || f.path.rfind("inspection.checks.gashLead.", 0) == 0 ||
        f.path.rfind("inspection.checks.adjacentSpacing.", 0) == 0 ||
        f.path.rfind("inspection.checks.pitchJump.", 0) == 0 || f.path == "inspection.gashLead" ||
        f.path == "inspection.adjacentSpacing" || f.path == "inspection.pitchJump" || f.path == "inspection.cumulativeSpacing" ||
        f.path == "inspection.spacing.adjacent" || f.path == "inspection.spacing.pitchJump" || f.path == "inspection.indexCorrection" ||
        f.path == "inspection.indexCorrectionDeg" || f.path.rfind("inspection.perGash.", 0) == 0;
    const bool wheelOffset = f.path.rfind("wheelOffset.", 0) == 0 || f.path == "wheelProfile.offset" ||
                             f.path == "wheelProfile.dressedR" || f.path == "wheelProfile.dressedZ";
    // The gear effect: its reason always, its figures with the hob's relief.
    const bool gearEffect = f.path.rfind("gearEffect.", 0) == 0 && f.path != "gearEffect.reason";
    const bool optional = f.path.rfind("correction.", 0) == 0 || f.path == "setup.gashLead" ||
                          f.path == "setup.gashHelixAngle" || optionalInspection || wheelOffset || gearEffect;
    EXPECT_EQ(!f.when.empty(), optional) << f.path;
  }
  EXPECT_EQ(paths.count("topography.normal"), 1u);
  EXPECT_EQ(paths.count("correction.residual"), 1u);
  // A label is what the page shows beside the figure: a few words, never a field's path.
  const std::vector<FieldDescription> fields = resultFields();
  for (const FieldDescription& f : fields) {
    if (f.label.empty()) continue;
    EXPECT_LE(f.label.size(), 80u) << f.path;  // bytes
    for (const std::string& p : paths) EXPECT_EQ(f.label.find(p), std::string::npos) << f.path << ": " << f.label;
  }
  for (const char* p : {"topography.rms", "correction.rmsBefore", "correction.sseAfter", "gearEffect.left.profileSlope",
                        "correction.precision.facePerError.A"})
    EXPECT_FALSE(std::find_if(fields.begin(), fields.end(), [&](const FieldDescription& f) { return f.path == p; })->label.empty())
        << p;
  for (const char* p : {"inspection.radialAlignment", "inspection.cuttingFaceForm", "inspection.gashLead",
                        "inspection.class", "inspection.limitingCheck", "inspection.checks.radialAlignment.tolerances",
                        "inspection.after.class", "inspection.pitchJump", "inspection.uncertainty", "inspection.provenClass",
                        "inspection.conformity", "inspection.rakeAngle", "inspection.rakeOffset",
                        "inspection.checks.radialAlignment.conformity", "gearEffect.rakeErrorPressureAngle"})
    EXPECT_EQ(paths.count(p), 1u) << p;
}

TEST(ResultModel, TheJsonHoldsExactlyTheDescribedFields) {
  std::set<std::string> described;
  for (const FieldDescription& f : resultFields()) described.insert(f.path);
  // A dressed wheel as well (wheel.profileOffset: the contact range is R = 29.53 to 50.0 mm).
  CaseInput withWheel = measuredCase();
  withWheel.wheelProfileOffset = WheelPointsInput{{30, 40, 49.9}, {1, -1, 0.5}};
  withWheel.hob.relief = HobReliefInput{12, 4.5, std::nullopt};  // and the gear effect, of 12 gashes:
  for (double shift : {1.0, 0.0, 1.5, -2.0, 0.5, 0.0, 1.0, -1.0})  // one topography per gash
    withWheel.inspection.gashTopographies.push_back(withWheel.measured->array() + shift);
  withWheel.correction.wheel = true;  // and the wheel-profile correction's fields
  const Json j = Json::parse(resultJson(evaluated(withWheel)));
  std::set<std::string> written;
  leaves(j, "", &written);
  // The fields only a measurement at points off the grid has (docs/measured-points.md): the
  // same measurement as points 0.01 mm off the grid's radii.
  const std::set<std::string> pointsOnly = {"correction.pointMeasured", "correction.pointResidual", "correction.measuredOnGrid"};
  for (const std::string& f : pointsOnly) EXPECT_EQ(written.count(f), 0u) << f << " with a grid";
  CaseInput withPoints = withWheel;
  withPoints.correction.wheel = false;  // the wheel correction takes a grid (refused with points off it)
  const SharpeningJob job = test::jobOf(paperCase());
  withPoints.measuredPoints.emplace();
  for (int i = 0; i < job.grid.rows(); ++i)
    for (int k = 0; k < job.grid.cols(); ++k)
      withPoints.measuredPoints->push_back({job.grid.r[i] + (i == 0 ? 0.01 : -0.01), job.grid.x[k], (*withWheel.measured)(i, k)});
  withPoints.measured.reset();
  std::set<std::string> writtenWithPoints;
  leaves(Json::parse(resultJson(evaluated(withPoints))), "", &writtenWithPoints);
  for (const std::string& f : pointsOnly) EXPECT_EQ(writtenWithPoints.count(f), 1u) << f << " with points";
  written.insert(pointsOnly.begin(), pointsOnly.end());
  EXPECT_EQ(written, described);
  const std::set<std::string> wheelOnly = {"correction.wheelProfileOffset.R", "correction.wheelProfileOffset.offset",
                                           "correction.dresserPath.R", "correction.dresserPath.Z", "correction.dresserPath.offset", "correction.removedByAxes",
                                           "correction.removedByWheel", "correction.axesShare", "correction.wheelShare"};
  for (const std::string& f : wheelOnly) EXPECT_EQ(writtenWithPoints.count(f), 0u) << f << " with points";
  writtenWithPoints.insert(wheelOnly.begin(), wheelOnly.end());
  EXPECT_EQ(writtenWithPoints, written);
  // Axes run that alone grind no face the wheel envelops (Z a0 45 mm off): the correction is
  // linearised at the nominal axes, and the face the run grinds is not given (correction.*Simulated
  // would be the nominal axes' face).
  CaseInput lost = paperCase();
  lost.measured = measuredCase().measured;
  lost.axes = test::jobOf(lost).nominalAxes;
  (*lost.axes)[Axis::Z].a[0] += 45.0;
  const Json linearised = Json::parse(resultJson(evaluated(lost)));
  ASSERT_TRUE(linearised["correction"]["linearisedAtNominal"].get<bool>());
  const std::set<std::string> runFaceOnly = {"correction.rmsSimulated", "correction.sseSimulated", "correction.maxSimulated",
                                             "correction.thicknessSimulated"};
  for (const std::string& f : runFaceOnly) {
    EXPECT_EQ(written.count(f), 1u) << f;
    EXPECT_FALSE(linearised["correction"].contains(f.substr(f.find('.') + 1))) << f << " linearised at the nominal axes";
  }
  // Without a measured topography there is no correction, without a wheel offset no wheelOffset.
  const Json nominal = Json::parse(resultJson(evaluated(paperCase())));
  EXPECT_FALSE(nominal.contains("correction"));
  EXPECT_FALSE(nominal.contains("wheelOffset"));
  EXPECT_FALSE(nominal["wheelProfile"].contains("dressedR"));
  EXPECT_TRUE(nominal["setup"].contains("gashLead"));
  // Nor a verdict after it; the inspection of the simulated face is there, without spacing.
  EXPECT_FALSE(nominal["inspection"].contains("after"));
  EXPECT_TRUE(nominal["inspection"].contains("radialAlignment"));
  EXPECT_FALSE(nominal["inspection"].contains("adjacentSpacing"));
  // Without the hob's relief, the gear effect is only the reason there is none.
  EXPECT_EQ(nominal["gearEffect"].size(), 1u);
  EXPECT_NE(nominal["gearEffect"]["reason"].get<std::string>(), "");
}

TEST(ResultModel, ShapesAndUnitsAsTheJsApiStatesThem) {
  const Evaluation e = evaluated(measuredCase());
  const Json j = Json::parse(resultJson(e));
  ASSERT_EQ(j["topography"]["normal"].size(), 5u);
  ASSERT_EQ(j["topography"]["normal"][0].size(), 9u);
  EXPECT_DOUBLE_EQ(j["topography"]["normal"][2][7].get<double>(), e.topography.normal(2, 7));
  ASSERT_EQ(j["sensitivities"]["normal"].size(), 25u);
  EXPECT_DOUBLE_EQ(j["sensitivities"]["normal"][6][1][4].get<double>(), e.sensitivities.topography(6)(1, 4));
  EXPECT_EQ(j["sensitivities"]["coefficients"][6], "Y a1");
  EXPECT_EQ(j["axes"]["B"].size(), 5u);
  EXPECT_DOUBLE_EQ(j["setup"]["settingAngle"].get<double>(), 12.626);
  EXPECT_NEAR(j["setup"]["gashLead"].get<double>(), 876.56, 1e-9);
  EXPECT_DOUBLE_EQ(j["correction"]["maxBefore"].get<double>(), e.correction->before.max);
  EXPECT_DOUBLE_EQ(j["correction"]["residual"][4][8].get<double>(), e.correction->after.normal(4, 8));
  EXPECT_EQ(j["correction"]["rank"].get<int>(), e.correction->rank);
  EXPECT_EQ(j["setup"]["motionUnit"], "rad");
  EXPECT_LE(j["motion"]["min"].get<double>(), 0.0);
  EXPECT_GE(j["motion"]["max"].get<double>(), 0.0);
  // A straight gash: no lead, the motion in mm.
  CaseInput straight = paperCase();
  straight.hob.gash = GashKind::Straight;
  straight.settingAngle = 0.0;
  straight.centerDistance.reset();
  const Json s = Json::parse(resultJson(evaluated(straight)));
  EXPECT_FALSE(s["setup"].contains("gashLead"));
  EXPECT_FALSE(s["inspection"].contains("gashLead"));
  EXPECT_FALSE(s["inspection"]["checks"].contains("gashLead"));
  EXPECT_EQ(s["setup"]["motionUnit"], "mm");
}

TEST(ResultModel, ANonFiniteNumberIsNamedByItsPath) {
  Evaluation e = evaluated(measuredCase());
  EXPECT_EQ(firstNonFinite(e), "");
  Evaluation a = e;
  a.topography.normal(2, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(firstNonFinite(a), "topography.normal[2][3]");
  Evaluation b = e;
  b.sensitivities.normal(1 * 9 + 4, 7) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(firstNonFinite(b), "sensitivities.normal[7][1][4]");
  Evaluation c = e;
  c.correction->axes[Axis::B].a[1] = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(firstNonFinite(c), "correction.axes.B[1]");
}

TEST(ResultModel, EvaluateCaseReportsEachKindOfFailure) {
  Json j = Json::parse(test::readFile("tab1.json"));
  j["hob"]["gashDepth"] = 60;
  auto refused = evaluateCase(j.dump());
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::InvalidInput);
  EXPECT_EQ(refused.error().field, "hob.gashDepth");
  j = Json::parse(test::readFile("tab1.json"));
  j["setup"]["settingAngle"] = -60;
  auto unsolvable = evaluateCase(j.dump());
  ASSERT_FALSE(unsolvable.ok());
  EXPECT_EQ(unsolvable.error().code, ErrorCode::Unsolvable);
  EXPECT_EQ(unsolvable.error().field, "setup");
  EXPECT_TRUE(evaluateCase(test::readFile("tab1.json")).ok());
}

}  // namespace
}  // namespace hobsharp
