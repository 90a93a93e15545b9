// A measurement at the measuring machine's own points (`measuredPoints`, README "Measured
// points"): points at a grid's positions give exactly the grid's result, in any order; points off
// the face, outside the ground region, at no grid position or twice at one, and a grid position
// without a point, are refused naming the point.
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "result_model.h"
#include "test_support.h"

namespace hobsharp {
namespace {

using Json = nlohmann::json;

// The paper's case measured after a machine error, as a grid.
Json gridCase() {
  Json j = Json::parse(test::readFile("tab1.json"));
  const SharpeningJob job = test::jobOf(test::paperCase());
  AxisPolynomials run = job.nominalAxes;
  run[Axis::Y].a[0] += 0.01;
  run[Axis::B].a[2] += 0.001;
  const Eigen::MatrixXd m = test::topographyFor(job, run).normal;
  Json rows = Json::array();
  for (int i = 0; i < m.rows(); ++i) {
    Json row = Json::array();
    for (int k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    rows.push_back(row);
  }
  j["measured"] = rows;
  return j;
}

// The same values as points [r, x, deviation] at the grid's positions, shuffled.
Json pointsCase(const Json& grid) {
  const SharpeningJob job = test::jobOf(test::paperCase());
  Json points = Json::array();
  for (int i = 0; i < job.grid.rows(); ++i)
    for (int k = 0; k < job.grid.cols(); ++k)
      points.push_back(Json::array({job.grid.r[i], job.grid.x[k], grid["measured"][i][k]}));
  std::vector<Json> shuffled(points.begin(), points.end());
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(11));
  Json j = grid;
  j.erase("measured");
  j["measuredPoints"] = shuffled;
  return j;
}

Error refusal(const Json& j) {
  auto e = evaluateCase(j.dump());
  EXPECT_FALSE(e.ok());
  return e.ok() ? Error{} : e.error();
}

TEST(MeasuredPoints, PointsAtAGridsPositionsGiveExactlyTheGridResult) {
  const Json grid = gridCase();
  auto a = evaluateCase(grid.dump());
  auto b = evaluateCase(pointsCase(grid).dump());
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_TRUE(b.ok()) << b.error().message;
  Json ra = Json::parse(resultJson(*a)), rb = Json::parse(resultJson(*b));
  EXPECT_EQ(ra["inspection"]["source"], "measured");
  EXPECT_EQ(rb["inspection"]["source"], "measuredPoints");
  ra["inspection"].erase("source");
  rb["inspection"].erase("source");
  ASSERT_TRUE(ra.contains("correction"));
  EXPECT_EQ(ra, rb) << "every figure, the correction's and the inspection's, bit for bit";
  // Points a measuring machine wrote a little off the nominal positions (within 0.001 mm) are at them.
  Json nudged = pointsCase(grid);
  for (Json& p : nudged["measuredPoints"]) p[0] = p[0].get<double>() + 4e-4, p[1] = p[1].get<double>() - 4e-4;
  auto c = evaluateCase(nudged.dump());
  ASSERT_TRUE(c.ok()) << c.error().message;
  EXPECT_EQ(c->correction->before.normal, a->correction->before.normal);
}

TEST(MeasuredPoints, BadPointsAreRefusedNamingThePoint) {
  const Json good = pointsCase(gridCase());
  auto with = [&](std::size_t k, const Json& point) {
    Json j = good;
    j["measuredPoints"][k] = point;
    return j;
  };
  const Json p0 = good["measuredPoints"][0];
  const double r = p0[0], x = p0[1];
  Error e = refusal(with(3, Json::array({10.0, 0.0, 1.0})));  // inside the gash root
  EXPECT_EQ(e.field, "measuredPoints[3]");
  EXPECT_NE(e.message.find("off the rake face"), std::string::npos) << e.message;
  e = refusal(with(3, Json::array({30.0, 400.0, 1.0})));  // beyond the hob's end
  EXPECT_EQ(e.field, "measuredPoints[3]");
  EXPECT_NE(e.message.find("outside the ground region"), std::string::npos) << e.message;
  e = refusal(with(3, Json::array({r + 0.5, x, 1.0})));  // between grid lines
  EXPECT_EQ(e.field, "measuredPoints[3]");
  EXPECT_NE(e.message.find("not at a position of the grid"), std::string::npos) << e.message;
  e = refusal(with(3, Json::array({r, x, 2.0})));  // a second point at the first one's position
  EXPECT_EQ(e.field, "measuredPoints[3]");
  EXPECT_NE(e.message.find("same grid position as measuredPoints[0]"), std::string::npos) << e.message;
  EXPECT_EQ(refusal(with(3, Json::array({r, x, 2e4}))).field, "measuredPoints[3]");
  EXPECT_EQ(refusal(with(3, Json::array({r, x}))).field, "measuredPoints[3]");
  EXPECT_EQ(refusal(with(3, Json::array({r, "x", 1.0}))).field, "measuredPoints[3][1]");
  EXPECT_EQ(refusal(with(3, Json::array({r, x, nullptr}))).field, "measuredPoints[3][2]");
  Json missing = good;
  missing["measuredPoints"].erase(missing["measuredPoints"].begin() + 7);
  e = refusal(missing);
  EXPECT_EQ(e.field, "measuredPoints");
  EXPECT_NE(e.message.find("has no point at the grid position"), std::string::npos) << e.message;
  Json both = good;
  both["measured"] = gridCase()["measured"];
  EXPECT_EQ(refusal(both).field, "measuredPoints");
  Json empty = good;
  empty["measuredPoints"] = Json::array();
  EXPECT_EQ(refusal(empty).field, "measuredPoints");
  const Error m = refusal(with(3, Json::array({10.0, 0.0, 1.0})));
  EXPECT_EQ(m.message.rfind("measuredPoints[3]: ", 0), 0u) << m.message;
}

}  // namespace
}  // namespace hobsharp
