// fold_margin.h on the paper's example: the margin from one Newton step per point against the one
// from each point solved again with the moved axes (a second method), and its first order.
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "envelope.h"
#include "fold_margin.h"
#include "test_support.h"

namespace hobsharp::test {
namespace {

// Two changes of the axes: Y's constant term by `scale` times 10 µm, B's slope by `scale` times 20 µrad
// per unit of the motion.
std::vector<AxisPolynomials> movedBy(const AxisPolynomials& axes, double scale) {
  AxisPolynomials y = axes, b = axes;
  y[Axis::Y].a[0] += scale * 0.010;
  b[Axis::B].a[1] += scale * 2e-5;
  return {y, b};
}

// The margin with each point solved again (Newton's method from the face's solution) for each moved axes.
FoldMargin resolvedMargin(const GroundFace& face, const SharpeningSetup& setup, const AxisPolynomials& axes,
                          const std::vector<AxisPolynomials>& moved) {
  const SetupRotations rotations = setupRotations(setup);
  FoldMargin out;
  for (int i = 0; i < face.size(); ++i) {
    const GridPoint& point = face.points[static_cast<size_t>(i)];
    const double det = envelopeJacobian(setup, rotations, axes, point, face.envelope[static_cast<size_t>(i)]).determinant();
    double squares = 0;
    for (const AxisPolynomials& a : moved) {
      auto e = solveEnvelopePointNear(setup, a, point, face.envelope[static_cast<size_t>(i)], Sensitivities::Skip);
      EXPECT_TRUE(e.ok()) << i;
      if (!e) return out;
      const double change = envelopeJacobian(setup, rotations, a, point, *e).determinant() - det;
      squares += change * change;
    }
    if (std::abs(det) < out.margin * std::sqrt(squares)) out = FoldMargin{std::abs(det) / std::sqrt(squares), i};
  }
  return out;
}

TEST(FoldMargin, OneNewtonStepAgreesWithThePointsSolvedAgain) {
  const SharpeningJob job = jobOf(paperCase());
  const GroundFace face = groundFaceOf(job, job.runAxes);
  const std::vector<AxisPolynomials> moved = movedBy(job.runAxes, 1);
  const FoldMargin m = foldMargin(face, job.setup, job.runAxes, moved);
  const FoldMargin r = resolvedMargin(face, job.setup, job.runAxes, moved);
  ASSERT_GE(m.at, 0);
  ASSERT_LT(m.at, face.size());
  EXPECT_TRUE(std::isfinite(m.margin));
  EXPECT_GT(m.margin, 1) << "the paper's face is far from a fold";
  EXPECT_EQ(m.at, r.at);
  EXPECT_NEAR(m.margin, r.margin, 0.02 * r.margin);
}

TEST(FoldMargin, IsOfFirstOrderInTheChange) {
  const SharpeningJob job = jobOf(paperCase());
  const GroundFace face = groundFaceOf(job, job.runAxes);
  const FoldMargin whole = foldMargin(face, job.setup, job.runAxes, movedBy(job.runAxes, 1));
  const FoldMargin half = foldMargin(face, job.setup, job.runAxes, movedBy(job.runAxes, 0.5));
  EXPECT_NEAR(half.margin, 2 * whole.margin, 0.03 * 2 * whole.margin);
  // No change, no margin to speak of.
  const FoldMargin none = foldMargin(face, job.setup, job.runAxes, {});
  EXPECT_EQ(none.at, -1);
  EXPECT_EQ(none.margin, std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace hobsharp::test
