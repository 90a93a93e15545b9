// The effect of the rake face on the gear (core/gear/, docs/gear-effect.md), against a
// second method: the closed-form first-order estimate (the face displaced along the circle by
// delta_c = delta / |n . e_theta| meets the relieved flank k delta_c / R earlier, so the hob's flank
// stands k sin(alpha_n) delta_c / R proud) and finite differences of the full computation; zero
// error gives zero effect; left/right hand mirror symmetry; left/right flank symmetry; the case's
// relief fields and their refusals.
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gear_effect.h"
#include "hob_relief.h"
#include "result_model.h"
#include "test_support.h"

namespace hobsharp {
namespace {

using Json = nlohmann::json;

constexpr double kAlpha = 20 * kRadPerDeg;
const BasicRack kRack{7.0, kAlpha, 31.25};  // Tab. 1: m_n 7, alpha_n 20 deg, d_p 62.5
// A relief of 4.5 mm over one of 12 gash pitches.
const double kRelief = reliefPerRadianFromCam(4.5, 12);

template <class F>
Eigen::MatrixXd faceOn(const FaceGrid& g, F f) {
  Eigen::MatrixXd m(g.rows(), g.cols());
  for (int i = 0; i < g.rows(); ++i)
    for (int j = 0; j < g.cols(); ++j) m(i, j) = f(g.r[i], g.x[j]);
  return m;
}

GearEffect effectOf(const SharpeningJob& job, const Eigen::MatrixXd& face, double relief = kRelief) {
  auto g = gearEffect(job.setup.face, job.setup.normalSign, job.grid.r, job.grid.x, face, kRack, relief);
  EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error().message);
  return g.value();
}

// The second method, written out on its own: the first-order gear profile (µm) of flank `s`
// (-1 left, +1 right) of the tooth at xc, at the heights of `g`, for a face f(r, x) in µm.
template <class F>
std::vector<double> firstOrderProfile(const ToothFace& face, const GearEffect& g, double xc, double s, F f) {
  std::vector<double> out;
  for (double h : g.height) {
    const double R = kRack.pitchRadius - h;
    const double x = xc + s * (kPi * kRack.module / 4 - (R - kRack.pitchRadius) * std::tan(kAlpha));
    const double u = face.uAtRadius(R), w = face.wAtAxial(x);
    const Eigen::Vector3d n = face.normal(u, w).normalized();
    const Eigen::Vector3d p = face.point(u, w);
    const double theta = std::atan2(p.z(), p.y());
    const double along = std::abs(n.dot(Eigen::Vector3d(0, -std::sin(theta), std::cos(theta))));
    const double circular = f(R, x) / along;                             // µm along the circle
    out.push_back(-kRelief * std::sin(kAlpha) * circular / R);           // the gear's deficit
  }
  return out;
}

// The least-squares rise over the heights: fH_alpha.
double rise(const std::vector<double>& h, const std::vector<double>& y) {
  double hm = 0, ym = 0;
  for (std::size_t k = 0; k < h.size(); ++k) hm += h[k] / h.size(), ym += y[k] / h.size();
  double shh = 0, shy = 0;
  for (std::size_t k = 0; k < h.size(); ++k) shh += (h[k] - hm) * (h[k] - hm), shy += (h[k] - hm) * (y[k] - ym);
  return shy / shh * (h.back() - h.front());
}

template <class F>
void expectFirstOrder(const SharpeningJob& job, F f, double relative) {
  const GearEffect g = effectOf(job, faceOn(job.grid, f));
  ASSERT_FALSE(g.teeth.empty());
  for (const ToothEdges& t : g.teeth) {
    for (const double s : {-1.0, 1.0}) {
      const std::vector<double> estimate = firstOrderProfile(job.setup.face, g, t.x, s, f);
      const std::vector<double>& full = s < 0 ? t.leftProfile : t.rightProfile;
      double scale = 0;
      for (double e : estimate) scale = std::max(scale, std::abs(e));
      ASSERT_GT(scale, 0.01) << "the case must move the profile";
      for (std::size_t k = 0; k < full.size(); ++k)
        EXPECT_NEAR(full[k], estimate[k], relative * scale) << "tooth x = " << t.x << ", flank " << s << ", point " << k;
      const ProfileFigures& p = s < 0 ? t.left : t.right;
      EXPECT_NEAR(p.slope, rise(g.height, estimate), relative * scale * 2);
    }
  }
}

TEST(GearEffect, NoRakeFaceErrorGivesNoGearEffect) {
  const SharpeningJob job = test::jobOf(test::paperCase());
  const GearEffect g = effectOf(job, Eigen::MatrixXd::Zero(job.grid.rows(), job.grid.cols()));
  ASSERT_EQ(g.teeth.size(), 5u) << "five teeth of pi m_n = 22 mm pitch lie whole on 140 mm";
  for (const ToothEdges& t : g.teeth) {
    for (double d : t.leftProfile) EXPECT_NEAR(d, 0, 1e-9);
    for (double d : t.rightProfile) EXPECT_NEAR(d, 0, 1e-9);
    EXPECT_NEAR(t.left.slope, 0, 1e-9);
    EXPECT_NEAR(t.right.form, 0, 1e-9);
  }
  // With a rake offset and on a straight gash too.
  CaseInput c = test::paperCase();
  c.hob.rakeOffset = 3;
  const SharpeningJob offset = test::jobOf(test::withDerivedSetup(c));
  const GearEffect withOffset = effectOf(offset, Eigen::MatrixXd::Zero(5, 9));
  for (double d : withOffset.teeth[2].rightProfile) EXPECT_NEAR(d, 0, 1e-9);
  const SharpeningJob plane = test::jobOf(test::straightGashCase());
  const GearEffect onPlane = effectOf(plane, Eigen::MatrixXd::Zero(5, 9));
  for (const ToothEdges& t : onPlane.teeth)
    for (double d : t.leftProfile) EXPECT_NEAR(d, 0, 1e-9);
}

TEST(GearEffect, MatchesTheClosedFormFirstOrderEstimate) {
  const SharpeningJob job = test::jobOf(test::paperCase());
  // A radial-alignment tilt, a gash-lead slope, a twist, a constant: each within 0.2 % of the
  // first-order estimate, the rest being of second order (delta / R ~ 3e-4).
  expectFirstOrder(job, [](double r, double) { return 0.5 * (r - 31.25); }, 2e-3);
  expectFirstOrder(job, [](double, double x) { return 0.1 * x; }, 2e-3);
  expectFirstOrder(job, [](double r, double x) { return 0.004 * (r - 25) * x; }, 2e-3);
  expectFirstOrder(job, [](double, double) { return 8.0; }, 2e-3);
}

TEST(GearEffect, ARadialTiltChangesThePressureAngleByItsFirstOrderAmount) {
  // A tilt about the pitch radius, d(delta)/dr = a, changes the pressure angle by about
  // -a (k / r_p) sin a_n cos a_n / cos(gash helix), as docs/gear-effect.md derives (the 1/r of the side
  // relief angle bends it by a few per cent over +-m_n); both flanks alike.
  const SharpeningJob job = test::jobOf(test::paperCase());
  const double a = 1.0;  // µm per mm of radius: 21 µm over the face
  const GearEffect g = effectOf(job, faceOn(job.grid, [&](double r, double) { return a * (r - 31.25); }));
  const double helix = job.setup.face.helixAngle();
  const double expected = -a * 1e-3 * kRelief / kRack.pitchRadius * std::sin(kAlpha) * std::cos(kAlpha) / std::cos(helix);
  for (const ToothEdges& t : g.teeth) {
    EXPECT_NEAR(t.left.pressureAngle, expected, 0.05 * std::abs(expected));
    EXPECT_NEAR(t.right.pressureAngle, t.left.pressureAngle, 1e-9 * std::abs(expected));
  }
  EXPECT_LT(expected, 0);
  // More material toward the hob's tip is a thicker rack tooth at its tip: a smaller pressure
  // angle on the rack and the gear, so fH_alpha is plus.
  EXPECT_GT(g.left.slope, 0);
  EXPECT_LT(g.left.pressureAngle, 0);
  std::printf("tilt 1 µm/mm about r_p: fH_alpha %.4f µm, pressure angle %.4f arc-min (estimate %.4f)\n", g.left.slope,
              g.left.pressureAngle * kDegPerRad * 60, expected * kDegPerRad * 60);
  // A face moved parallel to itself meets the relief at an angle that falls as 1/r: a pressure-
  // angle error too (of the opposite sign for excess material), while a turn of the face about the
  // hob axis (the same angle at every radius) only lowers the whole profile.
  const GearEffect shifted = effectOf(job, faceOn(job.grid, [](double, double) { return 10.0; }));
  EXPECT_LT(shifted.left.slope, -0.1);
  const GearEffect turned = effectOf(job, faceOn(job.grid, [&](double r, double) {
    return 10.0 * r / 31.25 / std::sqrt(1 + r * r / (job.setup.face.screwParameter * job.setup.face.screwParameter));
  }));
  EXPECT_NEAR(turned.left.slope, 0, 0.01 * std::abs(shifted.left.slope)) << "a turn about the axis: no slope";
  // It turns 10 µm of arc at r_p: the profile drops k sin(alpha_n) 10 / r_p everywhere (the gear gets more).
  for (double d : turned.teeth[2].leftProfile) EXPECT_NEAR(d, -kRelief * std::sin(kAlpha) * 10 / 31.25, 0.01);
}

TEST(GearEffect, FiniteDifferencesOfTheFullComputationGiveTheFirstOrderEstimate) {
  // A rake offset of 3 mm (the face is no longer radial) and a face the splines do not reproduce
  // exactly: the derivative of fH_alpha by the error's amplitude, by central differences of the
  // full computation, against the estimate applied to the same interpolated face.
  CaseInput c = test::paperCase();
  c.hob.rakeOffset = 3;
  const SharpeningJob job = test::jobOf(test::withDerivedSetup(c));
  auto shape = [](double r, double x) { return 0.02 * (r - 28) * (r - 28) + 0.05 * x + 0.3 * std::sin(x / 30); };
  const Eigen::MatrixXd unit = faceOn(job.grid, shape);
  const double eps = 1e-3;
  const GearEffect plus = effectOf(job, eps * unit), minus = effectOf(job, -eps * unit);
  const GearEffect big = effectOf(job, 10 * unit);
  // The estimate on the interpolated face: the same face read through the same splines.
  const ActualRakeFace interpolated(job.setup.face, job.setup.normalSign, job.grid.r, job.grid.x, unit);
  auto onGrid = [&](double r, double x) { return interpolated.deviation(r, x) * 1e3; };
  for (std::size_t t = 0; t < big.teeth.size(); ++t) {
    for (const double s : {-1.0, 1.0}) {
      const std::vector<double> estimate = firstOrderProfile(job.setup.face, big, big.teeth[t].x, s, onGrid);
      const double perUnit = rise(big.height, estimate);
      const double fd = ((s < 0 ? plus.teeth[t].left.slope : plus.teeth[t].right.slope) -
                         (s < 0 ? minus.teeth[t].left.slope : minus.teeth[t].right.slope)) / (2 * eps);
      EXPECT_NEAR(fd, perUnit, 1e-4 * std::abs(perUnit) + 1e-7) << "tooth " << t << ", flank " << s;
      // And at 10 times the shape (up to 35 µm on the face): what is not linear stays within
      // 0.2 % of the profile's size, of second order.
      const std::vector<double>& profile = s < 0 ? big.teeth[t].leftProfile : big.teeth[t].rightProfile;
      double size = 0;
      for (double d : profile) size = std::max(size, std::abs(d));
      EXPECT_NEAR((s < 0 ? big.teeth[t].left.slope : big.teeth[t].right.slope), 10 * perUnit, 2e-3 * size);
    }
  }
}

TEST(GearEffect, AGashLeadErrorTiltsTheFlanksOppositelyAndScattersAlongTheHob) {
  const SharpeningJob job = test::jobOf(test::paperCase());
  // 10 µm per 100 mm along the hob axis.
  const GearEffect g = effectOf(job, faceOn(job.grid, [](double, double x) { return 0.1 * x; }));
  const ToothEdges& middle = g.teeth[2];
  EXPECT_NEAR(middle.x, 0, 1e-12);
  EXPECT_GT(std::abs(middle.left.slope), 0.01);
  EXPECT_NEAR(middle.left.slope, -middle.right.slope, 2e-3 * std::abs(middle.left.slope));
  // Along the hob the teeth see different deviations: fH_alpha changes from tooth to tooth.
  EXPECT_GT(g.leftScatter, 0.01);
  double lo = 1e9, hi = -1e9;
  for (const ToothEdges& t : g.teeth) lo = std::min(lo, t.left.slope), hi = std::max(hi, t.left.slope);
  EXPECT_NEAR(g.leftScatter, hi - lo, 1e-12);
}

TEST(GearEffect, AnErrorSymmetricAboutTheToothGivesBothFlanksTheSameProfile) {
  const SharpeningJob job = test::jobOf(test::paperCase());
  // Even in x about the middle tooth, and any shape along the radius. On a straight gash the plane
  // face is itself symmetric: exactly the same. On a helical one the helicoid is not (its mirror
  // image is the other hand): the same to second order, 1e-4 of the profile.
  auto f = [](double r, double x) { return 0.03 * (r - 30) * (r - 30) - 0.002 * x * x + 1; };
  const SharpeningJob plane = test::jobOf(test::straightGashCase());
  for (const auto& [j, tolerance] : {std::pair{&plane, 1e-9}, std::pair{&job, 1e-4}}) {
    const GearEffect g = effectOf(*j, faceOn(j->grid, f));
    const ToothEdges& middle = g.teeth[2];
    ASSERT_NEAR(middle.x, 0, 1e-12);
    double scale = 0;
    for (double d : middle.leftProfile) scale = std::max(scale, std::abs(d));
    ASSERT_GT(scale, 0.1);
    for (std::size_t k = 0; k < middle.leftProfile.size(); ++k)
      EXPECT_NEAR(middle.leftProfile[k], middle.rightProfile[k], tolerance * scale) << k;
    EXPECT_NEAR(middle.left.slope, middle.right.slope, tolerance * scale);
    // The teeth either side mirror each other: tooth -1's left flank is tooth +1's right flank.
    for (std::size_t k = 0; k < middle.leftProfile.size(); ++k)
      EXPECT_NEAR(g.teeth[1].leftProfile[k], g.teeth[3].rightProfile[k], tolerance * scale) << k;
  }
}

TEST(GearEffect, ALeftHandHobIsTheMirrorImageOfTheRightHandOne) {
  // The left-hand hob is the right-hand one mirrored in x_1 -> -x_1 (docs/conventions.md §Hand):
  // its topography is mirrored along the gash, its left flanks are the right flanks mirrored.
  CaseInput c = test::paperCase();
  const SharpeningJob right = test::jobOf(c);
  c.hob.hand = Hand::Left;
  c.settingAngle = -*c.settingAngle;
  const SharpeningJob left = test::jobOf(c);
  auto f = [](double r, double x) { return 0.4 * (r - 29) + 0.08 * x + 0.002 * (r - 30) * x; };
  const GearEffect gr = effectOf(right, faceOn(right.grid, f));
  const GearEffect gl = effectOf(left, faceOn(left.grid, [&](double r, double x) { return f(r, -x); }));
  ASSERT_EQ(gr.teeth.size(), gl.teeth.size());
  const std::size_t n = gr.teeth.size();
  for (std::size_t t = 0; t < n; ++t) {
    const ToothEdges &a = gr.teeth[t], &b = gl.teeth[n - 1 - t];
    EXPECT_NEAR(a.x, -b.x, 1e-12);
    EXPECT_NEAR(a.left.slope, b.right.slope, 1e-9);
    EXPECT_NEAR(a.right.slope, b.left.slope, 1e-9);
    EXPECT_NEAR(a.left.form, b.right.form, 1e-9);
    for (std::size_t k = 0; k < a.leftProfile.size(); ++k) EXPECT_NEAR(a.leftProfile[k], b.rightProfile[k], 1e-9);
  }
  EXPECT_GT(std::abs(gr.left.slope - gr.right.slope), 0.01) << "the case tells the flanks apart";
}

TEST(GearEffect, TheReliefIsTheCamDropOrTheSideReliefAngle) {
  // tan(side relief) = K z sin(alpha_n) / (pi d_p): 4.5 mm x 12 gashes on d_p 62.5 at 20 deg.
  const double k = reliefPerRadianFromCam(4.5, 12);
  EXPECT_NEAR(k, 4.5 * 12 / (2 * kPi), 1e-12);
  const double side = sideReliefAngleAt(k, 31.25, kAlpha);
  EXPECT_NEAR(std::tan(side), 4.5 * 12 * std::sin(kAlpha) / (kPi * 62.5), 1e-12);
  EXPECT_NEAR(reliefPerRadianFromSideAngle(side, 31.25, kAlpha), k, 1e-12);
  HobReliefInput in;
  EXPECT_FALSE(reliefPerRadian(in, 31.25, kAlpha).value);
  // What is missing, in the hob form's words (issue 22), never the case's names (hob.gashes).
  const std::string none = reliefPerRadian(in, 31.25, kAlpha).missing;
  EXPECT_NE(none.find("the side relief angle"), std::string::npos) << none;
  EXPECT_NE(none.find("the number of gashes z and the relief K"), std::string::npos) << none;
  EXPECT_EQ(none.find("hob."), std::string::npos) << none;
  in.relief = 4.5;
  const std::string noGashes = reliefPerRadian(in, 31.25, kAlpha).missing;
  EXPECT_NE(noGashes.find("the number of gashes z"), std::string::npos) << noGashes;
  EXPECT_EQ(noGashes.find("hob."), std::string::npos) << noGashes;
  in.gashes = 12;
  EXPECT_NEAR(*reliefPerRadian(in, 31.25, kAlpha).value, k, 1e-12);
}

Json paperJson() { return Json::parse(test::readFile("tab1.json")); }

Outcome<Evaluation> evaluateJson(const Json& j) { return evaluateCase(j.dump()); }

TEST(GearEffect, TheCaseGivesTheReliefAndTheResultHoldsTheEffect) {
  Json j = paperJson();
  // Without the relief: the reason, no figures.
  auto none = evaluateJson(j);
  ASSERT_TRUE(none.ok()) << none.error().message;
  EXPECT_FALSE(none->gearEffect);
  const Json plain = Json::parse(resultJson(*none));
  EXPECT_NE(plain["gearEffect"]["reason"].get<std::string>().find("no relief"), std::string::npos);
  EXPECT_FALSE(plain["gearEffect"].contains("left"));
  // With a measured radial tilt: the measured face's effect, as gearEffect() gives it.
  j["hob"]["gashes"] = 12;
  j["hob"]["relief"] = 4.5;
  Json rows = Json::array();
  const std::vector<double> r{19, 24.25, 29.5, 34.75, 40};
  for (double ri : r) rows.push_back(std::vector<double>(9, 0.8 * (ri - 29.5)));
  j["measured"] = rows;
  auto e = evaluateJson(j);
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->gearEffect);
  const GearEffect direct = effectOf(e->job, faceOn(e->job.grid, [](double ri, double) { return 0.8 * (ri - 29.5); }));
  EXPECT_NEAR(e->gearEffect->left.slope, direct.left.slope, 1e-12);
  const Json out = Json::parse(resultJson(*e));
  const Json& g = out["gearEffect"];
  EXPECT_EQ(g["reason"], "");
  EXPECT_EQ(g["source"], "measured");
  EXPECT_NEAR(g["left"]["profileSlope"].get<double>(), direct.left.slope, 1e-12);
  EXPECT_NEAR(g["left"]["pressureAngleError"].get<double>(), direct.left.pressureAngle * kDegPerRad * 60, 1e-12);
  EXPECT_EQ(g["alongHob"]["x"].size(), 5u);
  EXPECT_EQ(g["alongHob"]["right"]["profileForm"].size(), 5u);
  EXPECT_EQ(g["profile"]["left"].size(), 5u);
  EXPECT_EQ(g["profile"]["left"][0].size(), g["profile"]["height"].size());
  EXPECT_NEAR(g["sideReliefAngle"].get<double>(), sideReliefAngleAt(kRelief, 31.25, kAlpha) * kDegPerRad, 1e-12);
  // The same through the side relief angle alone.
  j["hob"].erase("gashes");
  j["hob"].erase("relief");
  j["hob"]["sideReliefAngle"] = sideReliefAngleAt(kRelief, 31.25, kAlpha) * kDegPerRad;
  auto side = evaluateJson(j);
  ASSERT_TRUE(side.ok()) << side.error().message;
  EXPECT_NEAR(side->gearEffect->right.slope, direct.right.slope, 1e-9);
}

TEST(GearEffect, TheSimulatedFaceOfThePaperCaseHasNoGearEffect) {
  Json j = paperJson();
  j["hob"]["sideReliefAngle"] = 3.5;
  auto e = evaluateJson(j);
  ASSERT_TRUE(e.ok()) << e.error().message;
  ASSERT_TRUE(e->gearEffect);
  EXPECT_LT(std::abs(e->gearEffect->left.slope), 1e-6);
  EXPECT_LT(e->gearEffect->right.form, 1e-6);
}

TEST(GearEffect, AGridWithNoWholeToothSaysWhy) {
  Json j = paperJson();
  j["hob"]["sideReliefAngle"] = 3.5;
  j["grid"]["xMin"] = -5;
  j["grid"]["xMax"] = 5;
  auto e = evaluateJson(j);
  ASSERT_TRUE(e.ok()) << e.error().message;
  EXPECT_FALSE(e->gearEffect);
  EXPECT_NE(e->gearEffectReason.find("narrower than one tooth"), std::string::npos) << e->gearEffectReason;
}

void expectRefused(Json j, const std::string& field, const std::string& words) {
  auto c = parseCase(j.dump());
  ASSERT_FALSE(c.ok()) << field;
  EXPECT_EQ(c.error().field, field);
  EXPECT_EQ(c.error().message.rfind(field + ": ", 0), 0u) << c.error().message;
  EXPECT_NE(c.error().message.find(words), std::string::npos) << c.error().message;
}

TEST(GearEffect, AFinePitchHobIsEvaluatedOnItsMiddle101Teeth) {
  // Module 0.2: 222 teeth of pi m_n = 0.63 mm would fit on 140 mm; the middle 101 are taken.
  const SharpeningJob job = test::jobOf(test::paperCase());
  const BasicRack fine{0.2, kAlpha, 31.25};
  auto g = gearEffect(job.setup.face, job.setup.normalSign, job.grid.r, job.grid.x,
                      faceOn(job.grid, [](double r, double) { return r - 31.25; }), fine, kRelief);
  ASSERT_TRUE(g.ok()) << g.error().message;
  ASSERT_EQ(g->teeth.size(), 101u);
  EXPECT_NEAR(g->teeth.front().x, -50 * kPi * 0.2, 1e-9);
  EXPECT_GT(g->left.slope, 0);
}

TEST(GearEffect, BadReliefIsRefusedNamingTheField) {
  Json j = paperJson();
  j["hob"]["gashes"] = 0;
  expectRefused(j, "hob.gashes", "whole number from 1 to 100");
  j["hob"]["gashes"] = 12.5;
  expectRefused(j, "hob.gashes", "whole number");
  j["hob"]["gashes"] = 12;
  j["hob"]["relief"] = -1;
  expectRefused(j, "hob.relief", "positive");
  j["hob"]["relief"] = "4.5";
  expectRefused(j, "hob.relief", "must be a number");
  j["hob"]["relief"] = 4.5;
  j["hob"]["sideReliefAngle"] = 45;
  expectRefused(j, "hob.sideReliefAngle", "up to 30 deg");
  j["hob"]["sideReliefAngle"] = 3.0;
  expectRefused(j, "hob.sideReliefAngle", "disagrees with hob.relief and hob.gashes");
  const double agreeing = sideReliefAngleAt(kRelief, 31.25, kAlpha) * kDegPerRad;
  j["hob"]["sideReliefAngle"] = agreeing + 0.005;
  EXPECT_TRUE(parseCase(j.dump()).ok());
  j["hob"].erase("gashes");
  expectRefused(j, "hob.gashes", "needed to check");
  // The relief and the gashes alone are held to the side relief angle's limit too (an independent
  // review, 2026-12-07: 39 mm, a slipped digit for 3.9, was taken as a side relief of 39.2 deg).
  j["hob"].erase("sideReliefAngle");
  j["hob"]["gashes"] = 12;
  j["hob"]["relief"] = 39;
  expectRefused(j, "hob.relief", "with 12 gashes gives a side relief angle of 39.19 deg at the pitch diameter, more than "
                                 "the 30 deg a hob has");
  j["hob"]["relief"] = 3.9;
  EXPECT_TRUE(parseCase(j.dump()).ok());
  // With the side relief angle given too, the relief is held to the same limit: a relief of 30.005
  // deg beside a side relief angle of 30 agrees to 0.01 deg and was accepted (2026-12-07).
  j["hob"]["relief"] = reliefPerRadianFromSideAngle(30.005 * kRadPerDeg, 31.25, kAlpha) * 2 * kPi / 12;
  j["hob"]["sideReliefAngle"] = 30.0;
  expectRefused(j, "hob.relief", "with 12 gashes gives a side relief angle of 30.01 deg at the pitch diameter");
  j["hob"]["relief"] = reliefPerRadianFromSideAngle(29.995 * kRadPerDeg, 31.25, kAlpha) * 2 * kPi / 12;
  EXPECT_TRUE(parseCase(j.dump()).ok());
}

}  // namespace
}  // namespace hobsharp
