// Hands, gashes and rake offsets: nominal settings reproduce every face, a left-hand hob is the
// mirror of a right-hand one, and a straight gash behaves as docs/conventions.md §Straight gash says.
#include <cmath>
#include <random>

#include "test_support.h"
#include "wheel_profile.h"

namespace hobsharp::test {
namespace {

AxisPolynomials perturbed(const AxisPolynomials& nominal, unsigned seed, double scaleMm, double scaleRad) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  AxisPolynomials a = nominal;
  for (Axis axis : kAxes)
    for (double& c : a[axis].a) c += u(rng) * (isRotary(axis) ? scaleRad : scaleMm);
  return a;
}

TEST(Faces, LeftHandIsTheMirrorOfRightHand) {
  const CaseInput rightCase = paperCase();
  CaseInput leftCase = rightCase;
  leftCase.hob.hand = Hand::Left;
  leftCase.settingAngle = -*rightCase.settingAngle;  // signed by hand
  const SharpeningJob right = jobOf(rightCase), left = jobOf(leftCase);
  EXPECT_LT(left.setup.face.screwParameter, 0);
  // Mirror x1 -> -x1: X and B change sign, Y, Z and A stay.
  for (Axis a : kAxes)
    for (int k = 0; k <= 4; ++k) {
      const double sign = (a == Axis::X || a == Axis::B) ? -1 : 1;
      EXPECT_NEAR(left.nominalAxes[a].a[k], sign * right.nominalAxes[a].a[k], 1e-12) << axisName(a) << k;
    }
  EXPECT_LT(topographyFor(left, left.nominalAxes).max, 1e-6);

  // The same machine error, mirrored, grinds the mirrored topography.
  const AxisPolynomials rightRun = perturbed(right.nominalAxes, 7, 0.01, 1e-4);
  AxisPolynomials leftRun = rightRun;
  for (Axis a : {Axis::X, Axis::B})
    for (double& c : leftRun[a].a) c = -c;
  const Topography tr = topographyFor(right, rightRun), tl = topographyFor(left, leftRun);
  EXPECT_GT(tr.max, 1.0);
  const int n = tr.normal.cols();
  for (int i = 0; i < tr.normal.rows(); ++i)
    for (int j = 0; j < n; ++j) EXPECT_NEAR(tl.normal(i, n - 1 - j), tr.normal(i, j), 1e-8) << i << "," << j;
  EXPECT_NEAR(tl.thickness, tr.thickness, 1e-8);
}

TEST(Faces, LeftHandDefaultsFollowTheHand) {
  CaseInput c = paperCase();
  c.settingAngle = 12.0;  // off the helix angle, so that the contact line leaves x = 0
  c.centerDistance.reset();
  c.grid = GridInput{};
  const SharpeningJob right = jobOf(c);
  c.hob.hand = Hand::Left;
  c.settingAngle = -12.0;
  const SharpeningJob job = jobOf(c);
  c.settingAngle.reset();
  EXPECT_NEAR(jobOf(c).setup.universal.settingAngle.coefficient(0) * 180 / M_PI, -12.625843, 1e-6);
  EXPECT_NEAR(job.setup.universal.centerDistance.coefficient(0),
              right.setup.universal.centerDistance.coefficient(0), 1e-9);
  EXPECT_EQ(right.setup.normalSign, 1.0);
  EXPECT_EQ(job.setup.normalSign, -1.0);  // the outward normal flips with the hand
  EXPECT_GT(std::abs(right.grid.xMean()), 0.1);
  EXPECT_NEAR(job.grid.xMean(), -right.grid.xMean(), 1e-9);  // the default grid is mirrored too
}

TEST(Faces, RakeOffsetsPositiveZeroNegative) {
  for (double e : {-3.0, 0.0, 4.0}) {
    CaseInput c = paperCase();
    c.hob.rakeOffset = e;
    c.centerDistance.reset();
    c.grid = GridInput{};  // the default grid, centred on the contact line
    const SharpeningJob job = jobOf(c);
    EXPECT_NEAR(job.setup.face.rakeAngle(), std::asin(e / 31.25), 1e-15);
    // Each grid point lies on the face at its radius.
    const GridPoint g = gridPoint(job.setup, 23.0, 12.0);
    EXPECT_NEAR(std::hypot(g.p.y(), g.p.z()), 23.0, 1e-12);
    EXPECT_NEAR(g.p.x(), 12.0, 1e-12);
    const Topography t = topographyFor(job, job.nominalAxes);
    EXPECT_LT(t.max, 1e-6) << "e = " << e;
    EXPECT_LT(std::abs(t.thickness), 1e-6) << "e = " << e;
  }
}

TEST(Faces, HelixAngleInsteadOfLead) {
  CaseInput c = paperCase();
  c.hob.gashLead.reset();
  c.hob.gashHelixAngle = std::atan(31.25 / (876.56 / (2 * M_PI))) * 180 / M_PI;
  const SharpeningJob job = jobOf(c);
  EXPECT_NEAR(job.setup.face.screwParameter, 876.56 / (2 * M_PI), 1e-9);
}

TEST(Faces, StraightGash) {
  const SharpeningJob job = jobOf(straightGashCase());
  EXPECT_FALSE(job.setup.face.helical());
  const AxisPolynomials& a = job.nominalAxes;
  // docs/conventions.md §Straight gash: A stays constant, X = s + K1 tan(0), gamma_m = 0.
  EXPECT_EQ(a[Axis::A].a[0], 0.0);
  EXPECT_EQ(a[Axis::A].a[1], 0.0);
  EXPECT_EQ(a[Axis::X].a[0], 0.0);
  EXPECT_EQ(a[Axis::X].a[1], 1.0);
  EXPECT_EQ(a[Axis::B].a[0], 0.0);
  EXPECT_NEAR(a[Axis::Z].a[0], -110 / std::cos(15 * M_PI / 180), 1e-12);

  // The wheel's axial profile is a straight line.
  auto p = wheelProfile(job.setup.face, job.setup.universal, job.setup.normalSign, evenRadii(19, 40, 8));
  ASSERT_TRUE(p.ok());
  EXPECT_NEAR(p->R.front(), 50.0, 1e-9);  // rim at the root
  for (size_t k = 1; k + 1 < p->R.size(); ++k) {
    const double cross = (p->R[k] - p->R[0]) * (p->Z.back() - p->Z[0]) - (p->Z[k] - p->Z[0]) * (p->R.back() - p->R[0]);
    EXPECT_NEAR(cross, 0.0, 1e-9);
  }
  EXPECT_GT(std::abs(p->Z.back() - p->Z.front()), 1.0);  // inclined by the tilt, not degenerate

  EXPECT_LT(topographyFor(job, job.nominalAxes).max, 1e-6);

  // Moving along the gash (X) changes nothing; Z does.
  AxisPolynomials moved = job.nominalAxes;
  moved[Axis::X].a[0] += 0.5;
  EXPECT_LT(topographyFor(job, moved).max, 1e-6);
  moved = job.nominalAxes;
  moved[Axis::Z].a[0] += 0.01;
  EXPECT_GT(topographyFor(job, moved).max, 1.0);
}

}  // namespace
}  // namespace hobsharp::test

namespace hobsharp::test {
namespace {

// The headline figures of a face (issue 11): the sum of squares grows with the grid's density,
// the rms and the peak-to-valley do not. The same machine error on 5 x 9 and on 51 x 51.
TEST(Topography, RmsAndPeakToValleyDoNotGrowWithTheGrid) {
  Topography t[2];
  int k = 0;
  for (int lines : {0, 51}) {
    CaseInput in = paperCase();
    if (lines) {
      in.grid = GridInput{};
      in.grid.radial = lines;
      in.grid.axial = lines;
    }
    const SharpeningJob job = jobOf(in);
    AxisPolynomials axes = job.nominalAxes;
    axes[Axis::Z].a[0] += 0.01;  // mm
    axes[Axis::B].a[1] += 1e-4;  // rad per rad
    t[k] = topographyFor(job, axes);
    const Eigen::MatrixXd& n = t[k].normal;
    EXPECT_DOUBLE_EQ(t[k].rms, std::sqrt(n.squaredNorm() / static_cast<double>(n.size())));
    EXPECT_DOUBLE_EQ(t[k].peakToValley, n.maxCoeff() - n.minCoeff());
    ++k;
  }
  EXPECT_GT(t[1].sse / t[0].sse, 30.0);  // 2601 points against 45
  EXPECT_NEAR(t[1].rms / t[0].rms, 1.0, 0.1);
  EXPECT_NEAR(t[1].peakToValley / t[0].peakToValley, 1.0, 1e-3);  // the extremes lie at the face's corners
  std::printf("[ figures  ] 5 x 9: SSE %.1f µm², rms %.3f µm, PV %.3f µm; 51 x 51: SSE %.1f µm², rms %.3f µm, PV %.3f µm\n",
              t[0].sse, t[0].rms, t[0].peakToValley, t[1].sse, t[1].rms, t[1].peakToValley);
}

}  // namespace
}  // namespace hobsharp::test
