#include "case_file.h"

#include <string>

namespace hobsharp::validation {
namespace {

using Json = nlohmann::json;

Json rows(const Eigen::MatrixXd& m) {
  Json out = Json::array();
  for (int i = 0; i < m.rows(); ++i) {
    Json row = Json::array();
    for (int j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    out.push_back(std::move(row));
  }
  return out;
}

// Each axis's a0..an, degree + 1 of them (a shorter polynomial padded with zeros).
Json axesOf(const AxisPolynomials& p, int degree) {
  Json out = Json::object();
  for (Axis a : kAxes) {
    Json k = Json::array();
    for (int d = 0; d <= degree; ++d) k.push_back(p[a].coefficient(d));
    out[axisName(a)] = std::move(k);
  }
  return out;
}

Json correctionOf(const CorrectionInput& c) {
  Json out = Json::object();
  if (c.method) out["method"] = *c.method;
  if (c.probeNoise) out["probeNoise"] = *c.probeNoise;
  for (Axis a : kAxes)
    if (const auto& r = c.resolution[static_cast<size_t>(a)]) out["resolution"][axisName(a)] = *r;
  if (c.truncation) out["truncation"] = *c.truncation;
  if (c.amplification) out["amplification"] = *c.amplification;
  for (Axis a : c.lockedAxes) out["lockedAxes"].push_back(axisName(a));
  for (const Coefficient& k : c.locked) out["locked"].push_back(k.name());
  if (c.wheel) out["wheel"] = *c.wheel;
  return out;
}

}  // namespace

Json caseFile(const CaseInput& c) {
  Json j;
  j["format"] = "hobsharp-case/1";
  const HobInput& h = c.hob;
  Json& hob = j["hob"];
  hob["normalModule"] = h.normalModule;
  hob["normalPressureAngle"] = h.normalPressureAngle;
  hob["outerDiameter"] = h.outerDiameter;
  hob["pitchDiameter"] = h.pitchDiameter;
  hob["gashDepth"] = h.gashDepth;
  hob["length"] = h.length;
  hob["rakeOffset"] = h.rakeOffset;
  hob["gash"] = h.gash == GashKind::Helical ? "helical" : "straight";
  hob["hand"] = h.hand == Hand::Right ? "right" : "left";
  if (h.gashLead) hob["gashLead"] = *h.gashLead;
  if (h.gashHelixAngle) hob["gashHelixAngle"] = *h.gashHelixAngle;
  if (h.relief.gashes) hob["gashes"] = *h.relief.gashes;
  if (h.relief.relief) hob["relief"] = *h.relief.relief;
  if (h.relief.sideReliefAngle) hob["sideReliefAngle"] = *h.relief.sideReliefAngle;
  j["wheel"]["outerDiameter"] = c.wheelOuterDiameter;
  if (c.wheelProfileOffset) j["wheel"]["profileOffset"] = {{"R", c.wheelProfileOffset->R}, {"offset", c.wheelProfileOffset->values}};
  if (c.wheelMeasuredProfile)
    j["wheel"]["measuredProfile"] = {{"R", c.wheelMeasuredProfile->R}, {"Z", c.wheelMeasuredProfile->values}};
  j["setup"]["tilt"] = c.tilt;
  if (c.settingAngle) j["setup"]["settingAngle"] = *c.settingAngle;
  if (c.centerDistance) j["setup"]["centerDistance"] = *c.centerDistance;
  j["machine"] = {{"K1", c.machine.K1}, {"K2", c.machine.K2}};
  j["degree"] = c.degree;
  const GridInput& g = c.grid;
  Json& grid = j["grid"] = Json::object();
  if (g.radial) grid["radial"] = *g.radial;
  if (g.axial) grid["axial"] = *g.axial;
  if (g.rMin) grid["rMin"] = *g.rMin;
  if (g.rMax) grid["rMax"] = *g.rMax;
  if (g.xMin) grid["xMin"] = *g.xMin;
  if (g.xMax) grid["xMax"] = *g.xMax;
  if (c.axes) j["axes"] = axesOf(*c.axes, c.degree);
  if (c.measured) j["measured"] = rows(*c.measured);
  const Json correction = correctionOf(c.correction);
  if (!correction.empty()) j["correction"] = correction;
  for (const PassInput& p : c.passes) {
    Json pass;
    pass["axes"] = axesOf(p.axes, c.degree);
    pass["measured"] = rows(p.measured);
    if (p.correction) pass["correction"] = correctionOf(*p.correction);
    j["passes"].push_back(std::move(pass));
  }
  return j;
}

}  // namespace hobsharp::validation
