// Eqs. 13-16: the analytic (implicit-function) sensitivities against the paper's method,
// central differences of re-simulated topographies.
#include <cmath>

#include "sensitivity_matrix.h"
#include "test_support.h"

namespace hobsharp::test {
namespace {

// Compared per change at the ends of the motion range (a_k = b_k / range^k), column by column, to 1e-6
// of the column's largest entry. A column that is zero by geometry (a straight gash moved along
// its plane) is held to 1e-8 of the largest column instead: there only rounding and the
// difference quotient's O(h^2) error remain.
void expectMatchesCentralDifferences(const SharpeningJob& job, const AxisPolynomials& at) {
  const GroundFace face = groundFaceOf(job, at);
  const std::vector<Coefficient> coefficients = allCoefficients(at.degree());
  const SensitivityMatrix S = sensitivityMatrix(face, coefficients);
  ASSERT_EQ(S.normal.cols(), static_cast<int>(coefficients.size()));
  auto rangeScale = [&](const Coefficient& c) { return std::pow(S.motionRange, -c.degree); };
  double largest = 0;
  for (size_t j = 0; j < coefficients.size(); ++j)
    largest = std::max(largest, S.normal.col(j).cwiseAbs().maxCoeff() * rangeScale(coefficients[j]));
  ASSERT_GT(largest, 100.0);
  for (size_t j = 0; j < coefficients.size(); ++j) {
    const Coefficient& c = coefficients[j];
    const double h = 1e-5 * rangeScale(c);  // 1e-5 mm or rad at the ends of the motion range
    AxisPolynomials plus = at, minus = at;
    plus[c.axis].a[c.degree] += h;
    minus[c.axis].a[c.degree] -= h;
    const Topography tp = topographyFor(job, plus), tm = topographyFor(job, minus);
    const Eigen::MatrixXd cd = (tp.normal - tm.normal) / (2 * h) * rangeScale(c);
    const Eigen::MatrixXd analytic = S.topography(static_cast<int>(j)) * rangeScale(c);
    const double tol = 1e-6 * std::max(analytic.cwiseAbs().maxCoeff(), 1e-2 * largest);
    EXPECT_LT((cd - analytic).cwiseAbs().maxCoeff(), tol) << c.name();
    const double cdThickness = (tp.thickness - tm.thickness) / (2 * h) * rangeScale(c);
    EXPECT_LT(std::abs(cdThickness - S.thickness(j) * rangeScale(c)), tol) << c.name() << " thickness";
  }
}

TEST(Sensitivity, AnalyticEqualsCentralDifferencesAtNominal) {
  const SharpeningJob job = jobOf(paperCase());
  expectMatchesCentralDifferences(job, job.nominalAxes);
}

TEST(Sensitivity, AnalyticEqualsCentralDifferencesAwayFromNominal) {
  const SharpeningJob job = jobOf(paperCase());
  AxisPolynomials at = job.nominalAxes;
  at[Axis::Y].a[0] += 0.02;
  at[Axis::Z].a[2] -= 0.01;
  at[Axis::A].a[3] += 2e-4;
  at[Axis::B].a[1] += 1e-3;
  expectMatchesCentralDifferences(job, at);
}

TEST(Sensitivity, StraightGash) {
  const SharpeningJob job = jobOf(straightGashCase());
  expectMatchesCentralDifferences(job, job.nominalAxes);
  // docs/conventions.md §What the grid can see: X moves along the gash plane, so its columns vanish.
  const SensitivityMatrix S = sensitivityMatrix(groundFaceOf(job, job.nominalAxes), allCoefficients(4));
  for (int k = 0; k <= 4; ++k) EXPECT_LT(S.normal.col(k).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT(S.normal.col(10).cwiseAbs().maxCoeff(), 100.0);  // Z a0: about 1000 µm/mm
}

TEST(Sensitivity, XAndAColumnsOfTheSameDegreeAreParallel) {
  const SharpeningJob job = jobOf(paperCase());
  const SensitivityMatrix S = sensitivityMatrix(groundFaceOf(job, job.nominalAxes), allCoefficients(4));
  const double p = job.setup.face.screwParameter;
  for (int k = 0; k <= 4; ++k) {
    const Eigen::VectorXd x = S.normal.col(k), a = S.normal.col(15 + k);
    // An axial shift by p * delta equals a turn by -delta... in the sign of Eq. 7: X + p dA ~ 0.
    EXPECT_LT((x * p + a).norm(), 1e-9 * a.norm()) << "degree " << k;
  }
}

TEST(Sensitivity, ZeroDegreeTopographiesAreUniformAlongTheGash) {
  const SharpeningJob job = jobOf(paperCase());
  const SensitivityMatrix S = sensitivityMatrix(groundFaceOf(job, job.nominalAxes), allCoefficients(4));
  for (Axis a : kAxes) {
    const Eigen::MatrixXd t = S.topography(static_cast<int>(a) * 5);
    for (int i = 0; i < t.rows(); ++i)
      EXPECT_LT((t.row(i).array() - t(i, 0)).abs().maxCoeff(), 1e-9 * t.cwiseAbs().maxCoeff()) << axisName(a);
  }
}

}  // namespace
}  // namespace hobsharp::test
