// The native side of the native-versus-WebAssembly comparison (tests/js/module.test.mjs):
// evaluates a case file with the native build and prints the figures as JSON, full precision.
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "case_json.h"
#include "evaluation.h"

using hobsharp::Axis;
using Json = nlohmann::json;

namespace {

Json axes(const hobsharp::AxisPolynomials& a) {
  Json o;
  for (Axis x : hobsharp::kAxes) o[hobsharp::axisName(x)] = a[x].a;
  return o;
}

Json rows(const Eigen::MatrixXd& m) {
  Json r = Json::array();
  for (int i = 0; i < m.rows(); ++i) {
    std::vector<double> row(m.cols());
    for (int j = 0; j < m.cols(); ++j) row[j] = m(i, j);
    r.push_back(row);
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: hobsharp_native_eval case.json\n";
    return 2;
  }
  std::ifstream f(argv[1]);
  std::stringstream text;
  text << f.rdbuf();
  auto in = hobsharp::parseCase(text.str());
  if (!in) return std::cerr << in.error().message << "\n", 1;
  auto job = hobsharp::resolveJob(*in);
  if (!job) return std::cerr << job.error().message << "\n", 1;
  auto e = hobsharp::evaluate(*job);
  if (!e) return std::cerr << e.error().message << "\n", 1;
  Json o;
  o["axes"] = axes(e->job.nominalAxes);
  o["setup"] = {{"centerDistance", e->job.setup.universal.centerDistance.coefficient(0)},
                {"settingAngle", e->job.setup.universal.settingAngle.coefficient(0) * 180 / M_PI}};
  o["wheelProfile"] = {{"r", e->wheelProfile.r}, {"R", e->wheelProfile.R}, {"Z", e->wheelProfile.Z}};
  o["topography"] = {{"normal", rows(e->topography.normal)}, {"circular", rows(e->topography.circular)},
                     {"thickness", e->topography.thickness}, {"sse", e->topography.sse}};
  o["sensitivities"] = Json::array();
  for (int j = 0; j < e->sensitivities.normal.cols(); ++j) o["sensitivities"].push_back(rows(e->sensitivities.topography(j)));
  if (e->correction) {
    o["correction"] = {{"axes", axes(e->correction->axes)}, {"residual", rows(e->correction->after.normal)},
                       {"sseAfter", e->correction->after.sse}, {"rank", e->correction->rank}};
  }
  std::cout.precision(17);
  std::cout << o.dump() << "\n";
  return 0;
}
