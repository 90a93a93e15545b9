// Eqs. 3, 7, 8, 9 and 12: the CNC axes reproduce the universal machine exactly, and the Maclaurin
// coefficients are the exact derivatives.
#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "axis_polynomials.h"
#include "machine_kinematics.h"
#include "polynomial.h"
#include "taylor_series.h"

namespace hobsharp {
namespace {

using Eigen::Affine3d;
using Eigen::AngleAxisd;
using Eigen::Translation3d;
using Eigen::Vector3d;

// The paper's matrices of Eq. 3 (with the fixes of docs/errata.md), typed in independently.
Affine3d paperMt1(double eta, double gamma, double E, double L, double phi) {
  Affine3d Mtc = Affine3d::Identity(), Mcb = Affine3d::Identity(), Ma1 = Affine3d::Identity();
  Mtc.linear() << 1, 0, 0, 0, std::cos(eta), std::sin(eta), 0, -std::sin(eta), std::cos(eta);
  Mcb.linear() << std::cos(gamma), 0, std::sin(gamma), 0, 1, 0, -std::sin(gamma), 0, std::cos(gamma);
  const Affine3d Mba(Translation3d(L, -E, 0));
  Ma1.linear() << 1, 0, 0, 0, std::cos(phi), -std::sin(phi), 0, std::sin(phi), std::cos(phi);
  return Mtc * Mcb * Mba * Ma1;
}

UniversalSettings afmSettings() {
  // Auxiliary flank modification: gamma_m, E_t and L_t all vary with phi.
  UniversalSettings s;
  s.tilt = 15 * M_PI / 180;
  s.settingAngle = Polynomial{{0.2203, 0.003, -0.002}};
  s.centerDistance = Polynomial{{69.446, 0.05, 0.02, -0.01}};
  s.axialMovement = Polynomial{{0.0, 139.5, 0.3}};
  s.rotation = Polynomial{{0.0, 1.0}};
  return s;
}

TEST(Kinematics, CncAxesPlaceTheWheelExactlyAsTheUniversalMachine) {
  const UniversalSettings s = afmSettings();
  const MachineConstants m{100, 10};
  // Degree 6 polynomials of smooth functions: exact to O(phi^7) near phi = 0.
  const AxisPolynomials p = cncAxisPolynomials(s, m, 6);
  const Vector3d G(3.0, 30.0, -4.0);
  for (double phi : {-0.02, -0.005, 0.0, 0.01, 0.03}) {
    AxisState<double> state;
    for (int i = 0; i < kAxisCount; ++i) {
      state.value[i] = p.axis[i].at(phi).value;
      state.rate[i] = p.axis[i].at(phi).d1;
    }
    const Vector3d expected =
        paperMt1(s.tilt, s.settingAngle.at(phi).value, s.centerDistance.at(phi).value,
                 s.axialMovement.at(phi).value, s.rotation.at(phi).value) * G;
    const WheelFramePoint<double> q = hobPointInWheelFrame(G, state, m, s.tilt);
    EXPECT_LT((q.q - expected).norm(), 1e-12 + 1e3 * std::pow(std::abs(phi), 7)) << "phi " << phi;
    // The rate of the wheel-frame point against central differences of the paper's matrices.
    const double h = 1e-6;
    auto at = [&](double f) {
      return paperMt1(s.tilt, s.settingAngle.at(f).value, s.centerDistance.at(f).value,
                      s.axialMovement.at(f).value, s.rotation.at(f).value) * G;
    };
    const Vector3d rate = (at(phi + h) - at(phi - h)) / (2 * h);
    EXPECT_LT((q.qDot - rate).norm(), 1e-6 + 1e4 * std::pow(std::abs(phi), 6)) << "phi " << phi;
  }
}

TEST(Kinematics, ConstantSettingsGiveEquation9) {
  UniversalSettings s;
  s.tilt = 0.3;
  s.settingAngle = Polynomial::constant(0.2);
  s.centerDistance = Polynomial::constant(70);
  s.axialMovement = Polynomial{{0, 140}};
  s.rotation = Polynomial{{0, 1}};
  const MachineConstants m{100, 10};
  const AxisPolynomials p = cncAxisPolynomials(s, m, 4);
  EXPECT_DOUBLE_EQ(p[Axis::X].a[0], 100 * std::tan(0.2));
  EXPECT_DOUBLE_EQ(p[Axis::X].a[1], 140);
  EXPECT_NEAR(p[Axis::Y].a[0], 70 - (100 / std::cos(0.2) + 10) * std::tan(0.3), 1e-12);
  EXPECT_NEAR(p[Axis::Z].a[0], -(100 + 10 * std::cos(0.2)) / (std::cos(0.3) * std::cos(0.2)), 1e-12);
  EXPECT_DOUBLE_EQ(p[Axis::A].a[1], 1);
  EXPECT_DOUBLE_EQ(p[Axis::B].a[0], 0.2);
  for (int k = 2; k <= 4; ++k)
    for (Axis a : kAxes) EXPECT_EQ(p[a].a[k], 0.0);
}

TEST(Kinematics, MaclaurinCoefficientsAreTheExactDerivatives) {
  // X = L_t + K1 tan(gamma(phi)) with gamma = g0 + g1 phi: the derivatives of tan in closed form.
  UniversalSettings s = afmSettings();
  const double g0 = 0.2, g1 = 0.05;
  s.settingAngle = Polynomial{{g0, g1}};
  s.axialMovement = Polynomial{{0, 139.5}};
  const AxisPolynomials p = cncAxisPolynomials(s, MachineConstants{100, 10}, 4);
  const double t = std::tan(g0), sec2 = 1 + t * t;
  EXPECT_NEAR(p[Axis::X].a[1], 139.5 + 100 * g1 * sec2, 1e-12);
  EXPECT_NEAR(p[Axis::X].a[2], 100 * g1 * g1 * sec2 * t, 1e-12);                       // f''/2!
  EXPECT_NEAR(p[Axis::X].a[3], 100 * g1 * g1 * g1 * sec2 * (1 + 3 * t * t) / 3, 1e-12);  // f'''/3!
  // B follows gamma_m itself; A the rotation.
  EXPECT_DOUBLE_EQ(p[Axis::B].a[1], g1);
  EXPECT_DOUBLE_EQ(p[Axis::B].a[2], 0.0);
}

TEST(Kinematics, PolynomialCarriesTwoDerivatives) {
  const Polynomial p{{1, -2, 3, 0.5}};
  const double w = 0.7;
  const PolynomialValue v = p.at(w);
  EXPECT_NEAR(v.value, 1 - 2 * w + 3 * w * w + 0.5 * w * w * w, 1e-14);
  EXPECT_NEAR(v.d1, -2 + 6 * w + 1.5 * w * w, 1e-14);
  EXPECT_NEAR(v.d2, 6 + 3 * w, 1e-14);
}

TEST(Kinematics, TaylorSeriesOfSineAndCosine) {
  TaylorSeries s({}, 6), c({}, 6);
  sinCos(TaylorSeries({0.0, 1.0}, 6), &s, &c);  // sin(w), cos(w)
  const double fact[] = {1, 1, 2, 6, 24, 120, 720};
  for (int k = 0; k <= 6; ++k) {
    const double sk = k % 2 == 1 ? ((k / 2) % 2 ? -1 : 1) / fact[k] : 0;
    const double ck = k % 2 == 0 ? ((k / 2) % 2 ? -1 : 1) / fact[k] : 0;
    EXPECT_NEAR(s.coefficients()[k], sk, 1e-15) << k;
    EXPECT_NEAR(c.coefficients()[k], ck, 1e-15) << k;
  }
}

}  // namespace
}  // namespace hobsharp
