// Every bad-input rule of docs/case-format.md: refused with a message that names the field and
// the reason, and nothing crashes.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include <nlohmann/json.hpp>

#include "result_model.h"
#include "test_support.h"

namespace hobsharp::test {
namespace {

using Json = nlohmann::json;

Json paperJson() { return Json::parse(readFile("tab1.json")); }

// Runs the whole pipeline as the module and the CLI do (evaluateCase); returns the first error, or
// an empty Error when all went through.
Error firstError(const std::string& text) {
  auto e = evaluateCase(text);
  return e ? Error{} : e.error();
}
Error firstError(const Json& j) { return firstError(j.dump()); }

struct Rule {
  const char* name;
  std::function<void(Json&)> change;
  const char* field;    // Error::field
  const char* message;  // a part of Error::message
};

class BadInput : public ::testing::TestWithParam<Rule> {};

TEST_P(BadInput, IsRefusedWithItsMessage) {
  const Rule& rule = GetParam();
  Json j = paperJson();
  rule.change(j);
  const Error e = firstError(j);
  EXPECT_EQ(e.field, rule.field) << e.message;
  EXPECT_NE(e.message.find(rule.message), std::string::npos) << e.message;
  ASSERT_FALSE(std::string(rule.field).empty()) << "every refusal names a field";
  // The message starts with the field; a measured point's in words, counted from 1 (issue 22):
  // "Pass 2, measured point 2: ..." for passes[1].measuredPoints[1], never the path.
  const std::string field = rule.field;
  const std::size_t at = field.find(".measuredPoints[");
  const std::string expected = rule.message;
  if (expected.rfind("Measured grid", 0) == 0 || expected.find(", measured grid") != std::string::npos) {
    // A measured grid (issue 22): named in words, its row and value counted from 1 (with their r
    // and x when checked against the grid), never the path.
    EXPECT_EQ(e.message.rfind(expected, 0), 0u) << e.message;
    EXPECT_EQ(e.message.find("measured["), std::string::npos) << e.message;
    EXPECT_EQ(e.message.find("grid.radial"), std::string::npos) << e.message;
  } else if (at == std::string::npos) {
    EXPECT_EQ(e.message.rfind(rule.field, 0), 0u) << e.message;
  } else {
    const int pass = std::stoi(field.substr(7)) + 1, point = std::stoi(field.substr(at + 16)) + 1;
    EXPECT_EQ(e.message.rfind("Pass " + std::to_string(pass) + ", measured point " + std::to_string(point) + ": ", 0), 0u) << e.message;
    EXPECT_EQ(e.message.find("measuredPoints"), std::string::npos) << e.message;
  }
}

Json measuredRows(int rows, int cols) {
  Json m = Json::array();
  for (int i = 0; i < rows; ++i) m.push_back(Json(std::vector<double>(cols, 0.5)));
  return m;
}

// Two passes of the paper case (5 x 9 grid, degree 4): the nominal axes, then a changed run.
Json twoPasses() {
  const Json nominal = {{"X", {22.4003, 139.5089, 0, 0, 0}}, {"Y", {39.3076, 0, 0, 0, 0}}, {"Z", {-116.446, 0, 0, 0, 0}},
                        {"A", {0, 1, 0, 0, 0}}, {"B", {0.220365, 0, 0, 0, 0}}};
  Json second = nominal;
  second["Y"][0] = 39.3071;
  second["B"][2] = -1.25e-5;
  Json first = {{"axes", nominal}, {"measured", measuredRows(5, 9)}}, next = {{"axes", second}, {"measured", measuredRows(5, 9)}};
  first["measured"][2][3] = 7.125;
  next["measured"][4][8] = -0.0625;
  return Json::array({first, next});
}

const Rule kRules[] = {
    // A missing required field, a wrong type, NaN or infinity, an unknown format.
    {"MissingField", [](Json& j) { j["hob"].erase("pitchDiameter"); }, "hob.pitchDiameter", "is missing"},
    {"MissingObject", [](Json& j) { j.erase("machine"); }, "machine", "is missing"},
    {"MissingTilt", [](Json& j) { j["setup"].erase("tilt"); }, "setup.tilt", "is missing"},
    {"WrongType", [](Json& j) { j["hob"]["outerDiameter"] = "80"; }, "hob.outerDiameter", "must be a number; got a string"},
    {"WrongObjectType", [](Json& j) { j["wheel"] = 100; }, "wheel", "must be an object"},
    {"NaNAsJsonNull", [](Json& j) { j["setup"]["tilt"] = nullptr; }, "setup.tilt", "must be a number; got null"},
    {"Infinity", [](Json& j) { j["machine"]["K1"] = std::numeric_limits<double>::infinity(); }, "machine.K1", "must be a number"},
    {"UnknownFormat", [](Json& j) { j["format"] = "hobsharp-case/2"; }, "format", "unknown format"},
    {"MissingFormat", [](Json& j) { j.erase("format"); }, "format", "is missing"},
    {"UnknownField", [](Json& j) { j["setup"]["centreDistance"] = 69.4; }, "setup.centreDistance", "unknown field"},
    {"UnknownGash", [](Json& j) { j["hob"]["gash"] = "spiral"; }, "hob.gash", "must be one of"},
    {"UnknownHand", [](Json& j) { j["hob"]["hand"] = "up"; }, "hob.hand", "must be one of"},
    // Non-positive sizes, pitchDiameter >= outerDiameter, gash depth at or beyond the hob radius.
    {"ZeroModule", [](Json& j) { j["hob"]["normalModule"] = 0; }, "hob.normalModule", "must be positive"},
    {"NegativeLength", [](Json& j) { j["hob"]["length"] = -140; }, "hob.length", "must be positive"},
    {"ZeroWheel", [](Json& j) { j["wheel"]["outerDiameter"] = 0; }, "wheel.outerDiameter", "must be positive"},
    {"NegativeLead", [](Json& j) { j["hob"]["gashLead"] = -876.56; }, "hob.gashLead", "must be positive"},
    {"NegativeCentreDistance", [](Json& j) { j["setup"]["centerDistance"] = -1; }, "setup.centerDistance", "must be positive"},
    {"PitchBeyondOuter", [](Json& j) { j["hob"]["pitchDiameter"] = 80; }, "hob.pitchDiameter", "must be smaller than hob.outerDiameter"},
    {"GashDepthAtRadius", [](Json& j) { j["hob"]["gashDepth"] = 40; }, "hob.gashDepth", "less than the hob radius"},
    {"GashTooShallow", [](Json& j) { j["hob"]["gashDepth"] = 5; }, "hob.gashDepth", "below the pitch diameter"},
    {"PressureAngle", [](Json& j) { j["hob"]["normalPressureAngle"] = 50; }, "hob.normalPressureAngle", "between 0 and 45"},
    {"NoLeadNorAngle", [](Json& j) { j["hob"].erase("gashLead"); }, "hob.gashLead", "needs hob.gashLead or hob.gashHelixAngle"},
    {"LeadAndAngleDisagree", [](Json& j) { j["hob"]["gashHelixAngle"] = 14.0; }, "hob.gashHelixAngle", "disagrees with hob.gashLead"},
    // A straight gash ignores a lead or helix angle left from a helical case, but not whatever its value.
    {"StraightWithNegativeLead", [](Json& j) { j["hob"]["gash"] = "straight"; j["hob"]["gashLead"] = -3; }, "hob.gashLead", "must be positive"},
    {"StraightWithWildAngle", [](Json& j) { j["hob"]["gash"] = "straight"; j["hob"].erase("gashLead"); j["hob"]["gashHelixAngle"] = -500; }, "hob.gashHelixAngle", "between 0 and 90"},
    {"TiltOutOfRange", [](Json& j) { j["setup"]["tilt"] = 95; }, "setup.tilt", "between -90 and 90"},
    // |rakeOffset| >= r_p.
    {"RakeOffsetAtPitch", [](Json& j) { j["hob"]["rakeOffset"] = 31.25; }, "hob.rakeOffset", "less than the pitch radius"},
    {"RakeOffsetNegative", [](Json& j) { j["hob"]["rakeOffset"] = -35; }, "hob.rakeOffset", "less than the pitch radius"},
    // A wheel too small to reach the gash root.
    {"WheelShortOfRoot", [](Json& j) { j["setup"]["centerDistance"] = 75.0; }, "wheel.outerDiameter", "too small to reach the gash root"},
    {"WheelSmallerThanGash", [](Json& j) { j["wheel"]["outerDiameter"] = 30; j["setup"].erase("centerDistance"); }, "wheel.outerDiameter", "too small for this gash depth"},
    // A grid outside the face, or over the size limit.
    {"GridBelowRoot", [](Json& j) { j["grid"]["rMin"] = 15; }, "grid.rMin", "below the gash root"},
    {"GridBeyondTip", [](Json& j) { j["grid"]["rMax"] = 41; }, "grid.rMax", "beyond the hob's outer radius"},
    {"GridPastHobEnd", [](Json& j) { j["grid"]["xMax"] = 80; }, "grid.xMax", "reaches past the hob's ends"},
    {"GridReversed", [](Json& j) { j["grid"]["xMin"] = 10; j["grid"]["xMax"] = -10; }, "grid.xMax", "greater than grid.xMin"},
    {"GridTooLarge", [](Json& j) { j["grid"]["radial"] = 500; }, "grid.radial", "from 2 to 201"},
    {"GridOneLine", [](Json& j) { j["grid"]["axial"] = 1; }, "grid.axial", "from 2 to 201"},
    {"GridFractional", [](Json& j) { j["grid"]["radial"] = 4.5; }, "grid.radial", "whole number"},
    {"DegreeTooHigh", [](Json& j) { j["degree"] = 7; }, "degree", "from 1 to 6"},
    // Axes lists of the wrong length.
    {"AxesWrongLength", [](Json& j) { j["axes"] = {{"X", {22.4, 139.5, 0}}, {"Y", {39.3, 0, 0, 0, 0}}, {"Z", {-116.4, 0, 0, 0, 0}}, {"A", {0, 1, 0, 0, 0}}, {"B", {0.22, 0, 0, 0, 0}}}; }, "axes.X", "needs 5 coefficients"},
    {"AxesMissingAxis", [](Json& j) { j["axes"] = {{"X", {22.4, 139.5, 0, 0, 0}}}; }, "axes.Y", "is missing"},
    {"AxesNotNumbers", [](Json& j) { j["axes"] = {{"X", {22.4, "a", 0, 0, 0}}, {"Y", {39.3, 0, 0, 0, 0}}, {"Z", {-116.4, 0, 0, 0, 0}}, {"A", {0, 1, 0, 0, 0}}, {"B", {0.22, 0, 0, 0, 0}}}; }, "axes.X[1]", "must be a number"},
    // A measured array whose shape does not match the grid.
    {"MeasuredTooFewRows", [](Json& j) { j["measured"] = measuredRows(4, 9); }, "measured", "Measured grid: needs 5 rows (the radial grid lines) of 9 values (the axial grid lines); got 4 x 9."},
    {"MeasuredShortRow", [](Json& j) { j["measured"] = measuredRows(5, 9); j["measured"][2].erase(8); }, "measured[2]", "Measured grid, row 3: has 8 values; the first row has 9."},
    {"MeasuredNotANumber", [](Json& j) { j["measured"] = measuredRows(5, 9); j["measured"][3][4] = "x"; }, "measured[3][4]", "Measured grid, row 4, value 5: must be a number; got a string."},
    {"MeasuredEmpty", [](Json& j) { j["measured"] = Json::array(); }, "measured", "Measured grid: the list is empty"},
    {"MeasuredNotAList", [](Json& j) { j["measured"] = 3; }, "measured", "Measured grid: must be a list of rows; got a number."},
    // Absurd magnitudes: beyond 10 mm, where the correction's squares would overflow.
    {"MeasuredHuge", [](Json& j) { j["measured"] = measuredRows(5, 9); j["measured"][2][3] = 1e154; }, "measured[2][3]", "Measured grid, row 3 (r = 29.5 mm), value 4 (x = -17.5 mm): must lie within ±10000 µm (10 mm); got 1e+154 µm."},
    {"MeasuredBeyond10mm", [](Json& j) { j["measured"] = measuredRows(5, 9); j["measured"][4][8] = -10000.5; }, "measured[4][8]", "Measured grid, row 5 (r = 40 mm), value 9 (x = 70 mm): must lie within ±10000 µm (10 mm); got -10000.5 µm."},
    {"MeasuredRowsNotLists", [](Json& j) { j["measured"] = measuredRows(5, 9); j["measured"][1] = 7; }, "measured[1]", "Measured grid, row 2: must be a list of values; got a number."},
    // A long first row and 100,000 rows that are not lists: refused before 80 GB are allocated.
    {"MeasuredHugeFirstRow", [](Json& j) { j["measured"] = Json(std::vector<int>(100001, 1)); j["measured"][0] = std::vector<double>(100000, 0.0); }, "measured[1]", "Measured grid, row 2: must be a list of values"},
    // A geometry for which a grid point cannot be solved (Z a0 45 mm off, within a run's limits):
    // the message names r and x.
    {"UnsolvableGridPoint", [](Json& j) { j["axes"] = {{"X", {22.4, 139.5089, 0, 0, 0}}, {"Y", {39.3076, 0, 0, 0, 0}}, {"Z", {-71.446, 0, 0, 0, 0}}, {"A", {0, 1, 0, 0, 0}}, {"B", {0.220365, 0, 0, 0, 0}}}; }, "grid", "cannot be solved at the grid point r = 19 mm, x = -70 mm"},
    // A measured grid of fewer values than free coefficients, as measured points are refused.
    {"GridTooFewForTheDegree", [](Json& j) { j["grid"] = {{"radial", 2}, {"axial", 2}}; j["degree"] = 6; j["measured"] = measuredRows(2, 2); }, "measured", "Measured grid: 4 values are too few for the 35 free coefficients of degree 6 (one equation per value)"},
    // Axes run beyond a run's limits: a unit slip, named with the unit (run_axes.h).
    {"RunAxisInDegrees", [](Json& j) { j["axes"] = {{"X", {22.4, 139.5089, 0, 0, 0}}, {"Y", {39.3076, 0, 0, 0, 0}}, {"Z", {-116.446, 0, 0, 0, 0}}, {"A", {0, 1, 0, 0, 0}}, {"B", {12.626, 0, 0, 0, 0}}}; }, "axes.B", "differs from the nominal axis by up to 12.41 rad (710.8 deg) over the motion; a run is taken to differ from it by at most 90 deg on A and B, far beyond any correction. A and B are in rad: was it typed in degrees?"},
    {"RunAxisInMicrometres", [](Json& j) { j["axes"] = {{"X", {22.4, 139.5089, 0, 0, 0}}, {"Y", {39307.6, 0, 0, 0, 0}}, {"Z", {-116.446, 0, 0, 0, 0}}, {"A", {0, 1, 0, 0, 0}}, {"B", {0.220365, 0, 0, 0, 0}}}; }, "axes.Y", "X, Y and Z are in mm: was it typed in µm?"},
    {"PassAxisInDegrees", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1]["axes"]["B"][0] = 12.626; }, "passes[1].axes.B", "was it typed in degrees?"},
    // The wheel's rim and the gash root (docs/conventions.md, "The wheel's rim").
    {"RimPastTheRoot", [](Json& j) { j["setup"]["centerDistance"] = 60; }, "setup.centerDistance", "the wheel's rim (radius 50 mm) reaches about 9.28052 mm past the gash root"},
    {"WheelAxisInsideTheHob", [](Json& j) { j["setup"]["centerDistance"] = 10; }, "setup.centerDistance", "The rim touches the root at a centre distance of 69.4462 mm"},
    {"RimWiderThanTheWheelReaches", [](Json& j) { j["wheel"]["outerDiameter"] = 400; }, "setup.centerDistance", "reaches about 150 mm past the gash root"},
    {"SettingAngleOfTheOtherHand", [](Json& j) { j["setup"].erase("centerDistance"); j["setup"]["settingAngle"] = -12.626; }, "setup.settingAngle", "Check the setting angle's sign for a right-hand hob (left out, it is derived: 12.626 deg)"},
    {"TiltNearlyRight", [](Json& j) { j["setup"].erase("centerDistance"); j["setup"]["tilt"] = 89.999; }, "setup.tilt", "more than 4 times the wheel's and the hob's radii together (360 mm)"},
    // Correction options.
    {"GashDeviationsNotOnePerGash", [](Json& j) { j["hob"]["gashes"] = 12; j["inspection"] = {{"gashDeviations", {0, 1.5, -2}}}; },
     "inspection.gashDeviations", "needs one deviation per gash: the hob has 12 gashes (hob.gashes); got 3."},
    {"LockedUnknown", [](Json& j) { j["correction"] = {{"locked", {"Q a0"}}}; }, "correction.locked", "write a coefficient as"},
    {"LockedBeyondDegree", [](Json& j) { j["correction"] = {{"locked", {"X a6"}}}; }, "correction.locked", "beyond the polynomial degree"},
    {"TruncationOutOfRange", [](Json& j) { j["correction"] = {{"truncation", 2}}; }, "correction.truncation", "between 0 and 1"},
    // A pass history whose shapes do not match its grid or degree (docs/case-format.md, passes).
    {"PassesNotAList", [](Json& j) { j["passes"] = 3; }, "passes", "must be a list of passes"},
    {"PassNotAnObject", [](Json& j) { j["passes"] = {twoPasses()[0], 7}; }, "passes[1]", "must be an object"},
    {"PassMeasuredTooFewRows", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1]["measured"] = measuredRows(4, 9); }, "passes[1].measured", "Pass 2, measured grid: needs 5 rows"},
    {"PassMeasuredShortRow", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0]["measured"][2].erase(8); }, "passes[0].measured[2]", "Pass 1, measured grid, row 3: has 8 values"},
    {"PassMeasuredBeyond10mm", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1]["measured"][4][8] = 2e4; }, "passes[1].measured[4][8]", "Pass 2, measured grid, row 5 (r = 40 mm), value 9 (x = 70 mm): must lie within ±10000 µm"},
    {"PassMeasuredMissing", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0].erase("measured"); }, "passes[0].measured", "is missing"},
    // A pass measured at the measuring machine's own points: checked like measuredPoints, named in the pass.
    {"PassMeasuredAndPoints", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1]["measuredPoints"] = {{30, 0, 1.5}}; }, "passes[1].measuredPoints", "not both"},
    {"PassPointsNotTriples", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0].erase("measured"); j["passes"][0]["measuredPoints"] = {{30, 0, 1.5}, {30, 1}}; }, "passes[0].measuredPoints[1]", "three numbers"},
    {"PassPointOffTheFace", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1].erase("measured"); j["passes"][1]["measuredPoints"] = {{30, 0, 1.5}, {45, 0, 1}}; }, "passes[1].measuredPoints[1]", "off the rake face"},
    {"PassPointTwice", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1].erase("measured"); j["passes"][1]["measuredPoints"] = {{30, 0, 1.5}, {30, 0, 1}}; }, "passes[1].measuredPoints[1]", "the same point measured twice"},
    {"PassAxesWrongDegree", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1]["axes"]["B"].erase(4); }, "passes[1].axes.B", "needs 5 coefficients"},
    {"PassAxesMissing", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0].erase("axes"); }, "passes[0].axes", "is missing"},
    {"PassUnknownField", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0]["predicted"] = 1; }, "passes[0].predicted", "unknown field"},
    // A pass's own correction options, checked as the case's are, named within the pass.
    {"PassCorrectionNotAnObject", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1]["correction"] = 2; }, "passes[1].correction", "must be an object"},
    {"PassProbeNoiseZero", [](Json& j) { j["passes"] = twoPasses(); j["passes"][1]["correction"] = {{"probeNoise", 0}}; }, "passes[1].correction.probeNoise", "must be positive"},
    {"PassResolutionNegative", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0]["correction"] = {{"resolution", {{"B", -1e-4}}}}; }, "passes[0].correction.resolution.B", "must be"},
    {"PassMethodUnknown", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0]["correction"] = {{"method", "quadratic"}}; }, "passes[0].correction.method", "must be one of"},
    {"PassCorrectionUnknownField", [](Json& j) { j["passes"] = twoPasses(); j["passes"][0]["correction"] = {{"sigma", 1}}; }, "passes[0].correction.sigma", "unknown field"},
    // The job's record: text of bounded length, one line but for the notes; nothing else.
    {"JobNotAnObject", [](Json& j) { j["job"] = "A-17"; }, "job", "must be an object"},
    {"JobUnknownField", [](Json& j) { j["job"] = {{"order", "A-17"}}; }, "job.order", "unknown field (expected one of: number, customer, hobSerial, operator, notes)"},
    {"JobNumberNotText", [](Json& j) { j["job"] = {{"number", 17}}; }, "job.number", "must be text; got a number"},
    {"JobNumberTooLong", [](Json& j) { j["job"] = {{"number", std::string(61, '7')}}; }, "job.number", "must be at most 60 characters; got 61"},
    {"JobCustomerTooLong", [](Json& j) { j["job"] = {{"customer", std::string(101, 'c')}}; }, "job.customer", "at most 100 characters; got 101"},
    {"JobSerialTwoLines", [](Json& j) { j["job"] = {{"hobSerial", "H-1\nH-2"}}; }, "job.hobSerial", "one line of text"},
    {"JobOperatorControl", [](Json& j) { j["job"] = {{"operator", "A\u0007B"}}; }, "job.operator", "one line of text"},
    {"JobNotesTooLong", [](Json& j) { j["job"] = {{"notes", std::string(1001, 'n')}}; }, "job.notes", "at most 1000 characters; got 1001"},
    {"JobNotesControl", [](Json& j) { j["job"] = {{"notes", "ok\u001b[31m"}}; }, "job.notes", "without control characters"},
};

INSTANTIATE_TEST_SUITE_P(CaseFile, BadInput, ::testing::ValuesIn(kRules),
                         [](const ::testing::TestParamInfo<Rule>& i) { return std::string(i.param.name); });

TEST(CaseFile, ThePaperCaseIsAccepted) { EXPECT_EQ(firstError(paperJson()).message, ""); }

TEST(CaseFile, NotJson) {
  const Error e = firstError(std::string("{\"format\": \"hobsharp-case/1\", \"hob\": {"));
  EXPECT_NE(e.message.find("not valid JSON"), std::string::npos) << e.message;
  EXPECT_EQ(e.field, "hob") << e.message;  // where the text stopped: inside hob
  EXPECT_NE(firstError(std::string("[1, 2]")).message.find("must be a JSON object"), std::string::npos);
  EXPECT_EQ(firstError(std::string("[1, 2]")).field, "case");
  EXPECT_NE(firstError(std::string("")).message.find("not valid JSON"), std::string::npos);
  EXPECT_EQ(firstError(std::string("")).field, "case");
}

// Syntax errors are named by the JSON path of the value where the text stops being JSON.
TEST(CaseFile, ASyntaxErrorNamesItsPath) {
  std::string text = paperJson().dump();
  const std::string from = "\"tilt\":15.0";
  ASSERT_NE(text.find(from), std::string::npos) << text;
  text.replace(text.find(from), from.size(), "\"tilt\":15.x");
  EXPECT_EQ(firstError(text).field, "setup.tilt") << firstError(text).message;

  Json j = paperJson();
  j["measured"] = measuredRows(5, 9);
  text = j.dump();
  const std::string row = "[0.5,0.5,0.5,0.5,0.5,0.5,0.5,0.5,0.5]";
  const size_t third = text.find(row, text.find(row, text.find(row) + 1) + 1);
  ASSERT_NE(third, std::string::npos);
  text.replace(third, row.size(), "[0.5,0.5,0.5,0.5,-,0.5,0.5,0.5,0.5]");
  const Error e = firstError(text);
  EXPECT_EQ(e.field, "measured[2][4]") << e.message;
  EXPECT_EQ(e.message.rfind("measured[2][4]: ", 0), 0u) << e.message;
}

// A lone UTF-16 surrogate (what JSON.stringify makes of '\ud800') in any string: refused, naming
// the field it stands in.
TEST(CaseFile, ALoneSurrogateNamesItsField) {
  const struct {
    std::function<void(Json&)> put;  // puts the marker string "SURROGATE" somewhere
    const char* field;
  } places[] = {
      {[](Json& j) { j["format"] = "SURROGATE"; }, "format"},
      {[](Json& j) { j["hob"]["hand"] = "SURROGATE"; }, "hob.hand"},
      {[](Json& j) { j["hob"]["gash"] = "SURROGATE"; }, "hob.gash"},
      {[](Json& j) { j["correction"] = {{"locked", {"X a0", "SURROGATE"}}}; }, "correction.locked[1]"},
      {[](Json& j) { j["correction"] = {{"lockedAxes", {"SURROGATE"}}}; }, "correction.lockedAxes[0]"},
      {[](Json& j) { j["measured"] = measuredRows(5, 9); j["measured"][3][2] = "SURROGATE"; }, "measured[3][2]"},
      {[](Json& j) { j["setup"]["SURROGATE"] = 1; }, "setup"},  // in a key: the object it is in
  };
  for (const auto& place : places) {
    Json j = paperJson();
    place.put(j);
    std::string text = j.dump();
    for (const char* lone : {"\\ud800", "\\udfff", "\\ud800\\u0041"}) {
      std::string t = text;
      t.replace(t.find("SURROGATE"), 9, lone);
      const Error e = firstError(t);
      EXPECT_EQ(e.field, place.field) << t;
      EXPECT_EQ(e.message.rfind(std::string(place.field) + ": ", 0), 0u) << e.message;
      EXPECT_NE(e.message.find("surrogate"), std::string::npos) << e.message;
    }
  }
}

std::string nested(const std::string& open, const std::string& close, int depth) {
  std::string s;
  s.reserve(static_cast<size_t>(depth) * (open.size() + close.size()));
  for (int i = 0; i < depth; ++i) s += open;
  for (int i = 0; i < depth; ++i) s += close;
  return s;
}

// Nesting is bounded before anything is read: 100,000 deep once crashed the reader (its message
// dumped the value recursively). The field where it goes too deep is named.
TEST(CaseFile, DeepNestingIsRefusedNamingTheField) {
  for (int depth : {65, 1000, 100000, 1000000}) {
    const Error e = firstError("{\"format\": " + nested("[", "]", depth) + "}");
    EXPECT_EQ(e.field, "format") << depth;
    EXPECT_EQ(e.message.rfind("format: ", 0), 0u) << e.message;
    EXPECT_NE(e.message.find("nested more than 64 deep"), std::string::npos) << e.message;
    EXPECT_LT(e.message.size(), 200u) << "no dump of the input";
  }
  const std::string paper = paperJson().dump();
  const std::string gashLead = "\"gashLead\":";
  ASSERT_NE(paper.find(gashLead), std::string::npos);
  std::string text = paper;
  text.insert(text.find(gashLead) + gashLead.size(), nested("[", "]", 100000) + ",\"x\":");
  EXPECT_EQ(firstError(text).field, "hob.gashLead") << firstError(text).message;
  text = paper;
  text.insert(text.find(gashLead) + gashLead.size(), nested("{\"a\":", "}", 100000) + ",\"x\":");
  EXPECT_EQ(firstError(text).field.rfind("hob.gashLead.a.a.a", 0), 0u) << firstError(text).message;
  text = paper;
  text.insert(text.size() - 1, ",\"measured\":[[1]," + nested("[", "]", 100000) + "]");
  EXPECT_EQ(firstError(text).field, "measured") << firstError(text).message;
  const Error root = firstError("[" + nested("{\"a\":[", "]}", 50000) + "]");
  EXPECT_EQ(root.field.rfind("[0].a[0].a[0].a", 0), 0u) << root.field;
  EXPECT_LT(root.message.size(), 1000u);
  EXPECT_EQ(firstError(nested("[", "]", 100000)).field, "case");
}

// 64 levels are still read (and then refused for their type), 65 are not.
TEST(CaseFile, NestingUpToTheLimitIsRead) {
  const std::string paper = paperJson().dump();
  const std::string rake = "\"rakeOffset\":0.0";
  ASSERT_NE(paper.find(rake), std::string::npos) << paper;
  std::string text = paper;  // the document and hob are two levels
  text.replace(text.find(rake), rake.size(), "\"rakeOffset\":" + nested("[", "]", kMaxCaseNesting - 2));
  Error e = firstError(text);
  EXPECT_EQ(e.field, "hob.rakeOffset");
  EXPECT_NE(e.message.find("must be a number; got a list"), std::string::npos) << e.message;
  text = paper;
  text.replace(text.find(rake), rake.size(), "\"rakeOffset\":" + nested("[", "]", kMaxCaseNesting - 1));
  e = firstError(text);
  EXPECT_EQ(e.field, "hob.rakeOffset");
  EXPECT_NE(e.message.find("nested more than 64 deep"), std::string::npos) << e.message;
}

// A user's string in a message is cut short, and the message names the field.
TEST(CaseFile, LongStringsAreShownCut) {
  Json j = paperJson();
  j["hob"]["hand"] = std::string(1000000, 'x');
  Error e = firstError(j);
  EXPECT_EQ(e.field, "hob.hand");
  EXPECT_LT(e.message.size(), 200u);
  j = paperJson();
  j["format"] = std::string(1000000, 'y');
  e = firstError(j);
  EXPECT_EQ(e.field, "format");
  EXPECT_LT(e.message.size(), 200u);
  j = paperJson();
  j["setup"][std::string(39, 'z') + "\u00b5" + std::string(100, 'z')] = 1;  // 40 bytes end inside the µ
  e = firstError(j);
  EXPECT_EQ(e.field, "setup." + std::string(39, 'z') + "...") << e.field;
  EXPECT_LT(e.message.size(), 300u);
}

// Absurd axis coefficients are refused at the axis, as a unit slip (run_axes.h), before anything
// is simulated: tried for every coefficient up to 1e300, with a measured topography. Within the
// limits, far from nominal, they cannot overflow the way absurd measured values did: the wheel then
// misses the face and the grid point is refused, or the numbers stay finite.
TEST(CaseFile, AbsurdAxisCoefficientsAreRefusedOrStayFinite) {
  const Json axes = {{"X", {22.4003, 139.5089, 0, 0, 0}}, {"Y", {39.3076, 0, 0, 0, 0}}, {"Z", {-116.446, 0, 0, 0, 0}},
                     {"A", {0, 1, 0, 0, 0}}, {"B", {0.220365, 0, 0, 0, 0}}};
  int refused = 0, finite = 0;
  for (const char* axis : {"X", "Y", "Z", "A", "B"})
    for (int k = 0; k <= 4; ++k) {
      const bool rotary = std::string(axis) == "A" || std::string(axis) == "B";
      for (double v : {1e300, -1e300, 1e154, 1e20}) {
        Json j = paperJson();
        j["axes"] = axes;
        j["axes"][axis][k] = v;
        j["measured"] = measuredRows(5, 9);
        auto in = parseCase(j.dump());
        ASSERT_TRUE(in.ok()) << in.error().message;
        auto job = resolveJob(*in);
        ASSERT_FALSE(job.ok()) << axis << " a" << k << " = " << v;
        EXPECT_EQ(job.error().field, "axes." + std::string(axis));
        EXPECT_NE(job.error().message.find(rotary ? "was it typed in degrees?" : "was it typed in µm?"), std::string::npos)
            << job.error().message;
      }
      // Far off, within the limits (1000 mm, 90 deg over the motion, about 0.56 rad each way here), either sign.
      for (double sign : {1.0, -1.0}) {
        Json j = paperJson();
        j["axes"] = axes;
        const double most = rotary ? 0.5 : 45.0;
        j["axes"][axis][k] = j["axes"][axis][k].get<double>() + sign * most / std::pow(0.6, k);
        j["measured"] = measuredRows(5, 9);
        auto job = resolveJob(*parseCase(j.dump()));
        ASSERT_TRUE(job.ok()) << job.error().message;
        auto e = evaluate(*job);
        if (!e) {
          EXPECT_EQ(e.error().field, "grid") << e.error().message;
          ++refused;
          continue;
        }
        ++finite;
        const std::string what = std::string(axis) + " a" + std::to_string(k) + " " + (sign > 0 ? "+" : "-");
        EXPECT_TRUE(e->topography.normal.allFinite()) << what;
        EXPECT_TRUE(std::isfinite(e->topography.sse)) << what;
        EXPECT_TRUE(e->sensitivities.normal.allFinite()) << what;
        ASSERT_TRUE(e->correction.has_value()) << what;
        EXPECT_TRUE(e->correction->change.allFinite()) << what;
        EXPECT_TRUE(e->correction->after.normal.allFinite()) << what;
        EXPECT_TRUE(std::isfinite(e->correction->before.sse) && std::isfinite(e->correction->after.sse)) << what;
        for (Axis a : kAxes)
          for (double c : e->correction->axes[a].a) EXPECT_TRUE(std::isfinite(c)) << what;
      }
    }
  EXPECT_GT(refused, 0);
  EXPECT_GT(finite, 0);
}

// Found by the fuzzer: an unknown key that is empty or starts with NUL gave a refusal with an
// empty field. Keys are shown escaped, as JSON writes them.
TEST(CaseFile, OddKeysAreNamed) {
  const struct {
    const char* text;
    const char* field;
  } odd[] = {
      {"{\"format\": \"hobsharp-case/1\", \"\": 1}", "\"\""},
      {"{\"format\": \"hobsharp-case/1\", \"\\u0000a\": 1}", "\\u0000a"},
      {"{\"format\": \"hobsharp-case/1\", \"a\\\"\\n\": 1}", "a\\\"\\u000a"},
  };
  for (const auto& o : odd) {
    const Error e = firstError(std::string(o.text));
    EXPECT_EQ(e.field, o.field) << o.text;
    EXPECT_EQ(e.message.rfind(std::string(o.field) + ": unknown field", 0), 0u) << e.message;
    EXPECT_TRUE(std::none_of(e.message.begin(), e.message.end(), [](char c) { return c >= 0 && c < 0x20; }));
  }
  Json j = paperJson();
  j["hob"]["hand"] = std::string("le\0ft\n", 6);
  const Error e = firstError(j);
  EXPECT_NE(e.message.find("got \"le\\u0000ft\\u000a\""), std::string::npos) << e.message;
}

// Measured deviations up to 10 mm are taken, and the correction stays finite.
TEST(CaseFile, LargeButPossibleMeasuredValuesStayFinite) {
  Json j = paperJson();
  j["measured"] = measuredRows(5, 9);
  j["measured"][2][3] = 10000.0;
  j["measured"][0][0] = -10000.0;
  auto in = parseCase(j.dump());
  ASSERT_TRUE(in.ok()) << in.error().message;
  auto e = evaluate(jobOf(*in));
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->correction.has_value());
  EXPECT_TRUE(std::isfinite(e->correction->before.sse));
  EXPECT_TRUE(std::isfinite(e->correction->after.sse));
  EXPECT_TRUE(e->correction->after.normal.allFinite());
  EXPECT_TRUE(e->correction->change.allFinite());
  for (Axis a : kAxes) EXPECT_TRUE(std::all_of(e->correction->axes[a].a.begin(), e->correction->axes[a].a.end(),
                                               [](double c) { return std::isfinite(c); }));
}

// JSON has no infinity: a number too large for a double is refused where it stands.
TEST(CaseFile, OverflowingNumberIsRefusedWhereItStands) {
  std::string text = paperJson().dump();
  const std::string from = "\"K1\":100.0";
  ASSERT_NE(text.find(from), std::string::npos) << text;
  const size_t at = text.find(from) + 5;
  text.replace(text.find(from), from.size(), "\"K1\":1e999");
  const Error e = firstError(text);
  EXPECT_NE(e.message.find("not valid JSON"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("character " + std::to_string(at + 5)), std::string::npos) << e.message << " at " << at;
  EXPECT_NE(e.message.find("(a number too large: beyond ±1.8e308)"), std::string::npos) << e.message;  // not "syntax error"
}

// The job's record is read as given (characters counted, not bytes: 60 umlauts are 120 bytes),
// and the notes keep their line breaks; the calculation does not use it.
TEST(CaseFile, TheJobIsRead) {
  Json j = paperJson();
  std::string umlauts;
  for (int k = 0; k < 60; ++k) umlauts += "\u00e4";
  j["job"] = {{"number", "A-2026-117"}, {"customer", umlauts}, {"hobSerial", "H 4711"}, {"operator", "K. Weber"},
              {"notes", "Second pass.\nWheel dressed."}};
  auto in = parseCase(j.dump());
  ASSERT_TRUE(in) << in.error().message;
  EXPECT_EQ(in->job.number.value_or(""), "A-2026-117");
  EXPECT_EQ(in->job.customer.value_or(""), umlauts);
  EXPECT_EQ(in->job.hobSerial.value_or(""), "H 4711");
  EXPECT_EQ(in->job.operatorName.value_or(""), "K. Weber");
  EXPECT_EQ(in->job.notes.value_or(""), "Second pass.\nWheel dressed.");
  EXPECT_EQ(firstError(j).message, "");
  auto none = parseCase(paperJson().dump());
  ASSERT_TRUE(none);
  EXPECT_FALSE(none->job.number || none->job.customer || none->job.hobSerial || none->job.operatorName || none->job.notes);
}

TEST(CaseFile, DefaultsFillTheOptionalFields) {
  Json j = paperJson();
  j["setup"].erase("settingAngle");
  j["setup"].erase("centerDistance");
  j.erase("grid");
  j.erase("degree");
  j["hob"].erase("rakeOffset");
  j["hob"].erase("gash");
  j["hob"].erase("hand");
  auto in = parseCase(j.dump());
  ASSERT_TRUE(in.ok()) << in.error().message;
  auto job = resolveJob(*in);
  ASSERT_TRUE(job.ok()) << job.error().message;
  EXPECT_EQ(job->grid.rows(), 5);
  EXPECT_EQ(job->grid.cols(), 9);
  EXPECT_DOUBLE_EQ(job->grid.r.front(), 19.0);  // gash root
  EXPECT_DOUBLE_EQ(job->grid.r.back(), 40.0);   // outer radius
  EXPECT_NEAR(job->grid.x.back() - job->grid.x.front(), 140.0, 1e-12);
  EXPECT_EQ(job->nominalAxes.degree(), 4);
  EXPECT_TRUE(job->settingAngleDerived);
  EXPECT_TRUE(job->centerDistanceDerived);
}

TEST(CaseFile, AxesAndMeasuredAreRead) {
  Json j = paperJson();
  j["axes"] = {{"X", {22.4003, 139.5089, 0, 0, 0}}, {"Y", {39.3076, 0, 0, 0, 0}}, {"Z", {-116.446, 0, 0, 0, 0}},
               {"A", {0, 1, 0, 0, 0}}, {"B", {0.220365, 0, 0, 0, 0}}};
  j["measured"] = measuredRows(5, 9);
  j["correction"] = {{"lockedAxes", {"B"}}, {"locked", {"Z a4"}}, {"truncation", 1e-8}};
  auto in = parseCase(j.dump());
  ASSERT_TRUE(in.ok()) << in.error().message;
  EXPECT_DOUBLE_EQ((*in->axes)[Axis::Y].a[0], 39.3076);
  EXPECT_EQ(in->measured->rows(), 5);
  EXPECT_EQ(in->measured->cols(), 9);
  ASSERT_EQ(in->correction.lockedAxes.size(), 1u);
  EXPECT_EQ(in->correction.lockedAxes[0], Axis::B);
  ASSERT_EQ(in->correction.locked.size(), 1u);
  EXPECT_EQ(in->correction.locked[0].name(), "Z a4");
  auto e = evaluate(jobOf(*in));
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->correction.has_value());
  EXPECT_EQ(e->correction->coefficients.size(), 19u);
}

// The pass history round-trips: every value read is the value written, a case without passes
// and the same case with them give the same result (the calculation does not use them), and
// the page's empty history ([]) reads as none.
TEST(CaseFile, PassesRoundTrip) {
  Json j = paperJson();
  j["passes"] = twoPasses();
  auto in = parseCase(j.dump());
  ASSERT_TRUE(in.ok()) << in.error().message;
  ASSERT_EQ(in->passes.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p) {
    const Json& written = j["passes"][p];
    const PassInput& read = in->passes[p];
    for (Axis a : kAxes) EXPECT_EQ(Json(read.axes[a].a), written["axes"][axisName(a)]) << "pass " << p << " " << axisName(a);
    ASSERT_EQ(read.measured.rows(), 5);
    ASSERT_EQ(read.measured.cols(), 9);
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 9; ++c) EXPECT_EQ(read.measured(r, c), written["measured"][r][c].get<double>());
  }
  EXPECT_EQ(in->passes[0].measured(2, 3), 7.125);
  EXPECT_EQ(in->passes[1].measured(4, 8), -0.0625);
  EXPECT_EQ(in->passes[1].axes[Axis::B].a[2], -1.25e-5);
  EXPECT_FALSE(in->passes[0].correction.has_value());
  {  // a pass keeps the options its correction was computed with
    Json k = j;
    k["passes"][1]["correction"] = {{"method", "linear"}, {"probeNoise", 1e-4}, {"resolution", {{"A", 0.001}}},
                                    {"lockedAxes", {"A"}}};
    auto read = parseCase(k.dump());
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_TRUE(read->passes[1].correction.has_value());
    EXPECT_EQ(read->passes[1].correction->method, std::optional<std::string>("linear"));
    EXPECT_EQ(read->passes[1].correction->probeNoise, std::optional<double>(1e-4));
    EXPECT_EQ(read->passes[1].correction->resolution[static_cast<int>(Axis::A)], std::optional<double>(0.001));
    EXPECT_EQ(read->passes[1].correction->lockedAxes, std::vector<Axis>{Axis::A});
    EXPECT_TRUE(evaluateCase(k.dump()).ok());
  }

  auto with = evaluateCase(j.dump());
  ASSERT_TRUE(with.ok()) << with.error().message;
  j.erase("passes");
  auto without = evaluateCase(j.dump());
  ASSERT_TRUE(without.ok()) << without.error().message;
  EXPECT_EQ(with->topography.sse, without->topography.sse);
  EXPECT_EQ(with->topography.normal, without->topography.normal);

  {  // a pass measured at the measuring machine's points keeps them as read, and changes nothing computed
    Json k = j;
    k["passes"] = twoPasses();
    k["passes"][0].erase("measured");
    k["passes"][0]["measuredPoints"] = {{19.5, -60, 1.25}, {30, 0, -0.5}, {38, 60.5, 2}};
    auto read = parseCase(k.dump());
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_TRUE(read->passes[0].measuredPoints.has_value());
    ASSERT_EQ(read->passes[0].measuredPoints->size(), 3u);
    EXPECT_EQ((*read->passes[0].measuredPoints)[2].x, 60.5);
    EXPECT_EQ((*read->passes[0].measuredPoints)[0].deviation, 1.25);
    EXPECT_EQ(read->passes[0].measured.size(), 0);
    EXPECT_FALSE(read->passes[1].measuredPoints.has_value());
    auto withPoints = evaluateCase(k.dump());
    ASSERT_TRUE(withPoints.ok()) << withPoints.error().message;
    EXPECT_EQ(withPoints->topography.normal, without->topography.normal);
  }

  j["passes"] = Json::array();
  auto empty = parseCase(j.dump());
  ASSERT_TRUE(empty.ok()) << empty.error().message;
  EXPECT_TRUE(empty->passes.empty());
}

// Random damage to the paper's case: every variant is either accepted or refused with a message,
// and none crashes.
TEST(CaseFile, RandomDamageNeverCrashes) {
  const std::string text = paperJson().dump();
  std::mt19937 rng(2012);
  const std::string junk = "{}[]\",:-0123456789.eE nultrfas";
  int refused = 0;
  for (int n = 0; n < 2000; ++n) {
    std::string s = text;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < edits && !s.empty(); ++k) {
      const size_t at = rng() % s.size();
      switch (rng() % 3) {
        case 0: s.erase(at, 1 + rng() % 4); break;
        case 1: s.insert(at, 1, junk[rng() % junk.size()]); break;
        default: s[at] = junk[rng() % junk.size()];
      }
    }
    const Error e = firstError(s);
    if (!e.message.empty()) ++refused;
  }
  EXPECT_GT(refused, 1000);
}

}  // namespace
}  // namespace hobsharp::test
