// The solvers' options structs: their defaults are the figures the results were pinned with, and
// each member that the tests can reach changes what the solver does.
#include <cmath>
#include <cstdio>

#include "correction.h"
#include "solve_report.h"
#include "test_support.h"
#include "wheel_profile.h"

namespace hobsharp::test {
namespace {

// A run with an error of the paper's size, so that every grid point takes several Newton steps.
AxisPolynomials runWithError(const AxisPolynomials& nominal) {
  AxisPolynomials a = nominal;
  a[Axis::Y].a[0] += 0.01;
  a[Axis::Z].a[1] += 0.003;
  a[Axis::A].a[0] += 0.0002;
  a[Axis::B].a[2] += 0.001;
  return a;
}

int totalIterations(const GroundFace& f) {
  int n = 0;
  for (const EnvelopePoint& e : f.envelope) n += e.iterations;
  return n;
}

TEST(SolverOptions, DefaultEnvelopeOptionsAreTheDefaultSolve) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials run = runWithError(job.nominalAxes);
  auto implicit = simulateGroundFace(job.setup, run, job.grid);
  auto explicitDefaults =
      simulateGroundFace(job.setup, run, job.grid, Sensitivities::Compute, EnvelopeSolverOptions{});
  ASSERT_TRUE(implicit.ok() && explicitDefaults.ok());
  for (size_t k = 0; k < implicit->envelope.size(); ++k) {
    EXPECT_EQ(implicit->envelope[k].t, explicitDefaults->envelope[k].t);
    EXPECT_EQ(implicit->envelope[k].iterations, explicitDefaults->envelope[k].iterations);
  }
  EXPECT_GT(totalIterations(*implicit), 2 * static_cast<int>(implicit->envelope.size()));
}

// The solve may end on a chord step (the last Newton step's LU, envelope.cpp) where quadratic
// convergence predicts the next step below the tolerance. Its point must be where Newton's method
// ends: started there, one full Newton step, below the tolerance, moves it no further.
TEST(SolverOptions, AnEnvelopeSolveEndsWhereNewtonsMethodWould) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials run = runWithError(job.nominalAxes);
  auto f = simulateGroundFace(job.setup, run, job.grid, Sensitivities::Skip);
  ASSERT_TRUE(f.ok());
  const EnvelopeSolverOptions o;
  for (size_t k = 0; k < f->envelope.size(); ++k) {
    const EnvelopePoint& e = f->envelope[k];
    auto again = solveEnvelopePoint(job.setup, run, f->points[k], EnvelopeGuess{e.t, e.phi, e.u, e.w},
                                    Sensitivities::Skip);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->iterations, 1) << "grid point " << k;
    // Within the step tolerance, each unknown in the tolerance's own measure (mm, motion weighted).
    EXPECT_LT(std::abs(again->t - e.t) + std::abs(again->u - e.u) +
                  o.helicalMotionWeight * (std::abs(again->phi - e.phi) + std::abs(again->w - e.w)),
              o.stepTolerance)
        << "grid point " << k;
  }
}

// The first-order start (solveEnvelopePointNear, as the identification's faces are solved from
// the run face): the same points as Newton's method started from the nearby face's solutions,
// with fewer Jacobians formed.
TEST(SolverOptions, AFirstOrderStartFromANearbyFaceEndsWhereTheColdStartDoes) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials run = runWithError(job.nominalAxes);
  auto nominal = simulateGroundFace(job.setup, job.nominalAxes, job.grid, Sensitivities::Skip);
  ASSERT_TRUE(nominal.ok());
  const EnvelopeSolverOptions o;
  int nearJacobians = 0, coldJacobians = 0;
  for (size_t k = 0; k < nominal->envelope.size(); ++k) {
    const EnvelopePoint& from = nominal->envelope[k];
    auto near = solveEnvelopePointNear(job.setup, run, nominal->points[k], from, Sensitivities::Skip);
    auto cold = solveEnvelopePoint(job.setup, run, nominal->points[k], EnvelopeGuess{from.t, from.phi, from.u, from.w},
                                   Sensitivities::Skip);
    ASSERT_TRUE(near.ok() && cold.ok());
    // Within the step tolerance, each unknown in the tolerance's own measure (mm, motion weighted).
    EXPECT_LT(std::abs(near->t - cold->t) + std::abs(near->u - cold->u) +
                  o.helicalMotionWeight * (std::abs(near->phi - cold->phi) + std::abs(near->w - cold->w)),
              o.stepTolerance)
        << "grid point " << k;
    nearJacobians += near->jacobians;
    coldJacobians += cold->jacobians;
  }
  std::printf("[ figures  ] Jacobians over %zu points: %d from the first-order start, %d from the solutions\n",
              nominal->envelope.size(), nearJacobians, coldJacobians);
  EXPECT_LT(nearJacobians, coldJacobians);
}

// On a grid simulateGroundFaceLike simulates afresh by default (the identification's figures rest
// on the cold start's last bits), and with FaceStart::Near starts each point from the nearby
// face's solution (the prediction's bound): the same face to within the solver's tolerance, with
// fewer Jacobians, and the default the same to the bit as simulating the face.
TEST(SolverOptions, AGridFaceStartsFromANearbyFaceOnlyWhenAsked) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials run = runWithError(job.nominalAxes);
  auto nominal = simulateGroundFace(job.setup, job.nominalAxes, job.grid, Sensitivities::Skip);
  auto cold = simulateGroundFace(job.setup, run, job.grid, Sensitivities::Skip);
  auto asSimulated = simulateGroundFaceLike(*nominal, job.setup, run, Sensitivities::Skip);
  auto near = simulateGroundFaceLike(*nominal, job.setup, run, Sensitivities::Skip, FaceStart::Near);
  ASSERT_TRUE(nominal.ok() && cold.ok() && asSimulated.ok() && near.ok());
  ASSERT_EQ(near->size(), cold->size());
  int nearJacobians = 0, coldJacobians = 0;
  for (int k = 0; k < cold->size(); ++k) {
    const EnvelopePoint &c = cold->envelope[static_cast<size_t>(k)], &n = near->envelope[static_cast<size_t>(k)];
    EXPECT_EQ(asSimulated->envelope[static_cast<size_t>(k)].t, c.t) << "grid point " << k;
    EXPECT_LT(std::abs(n.t - c.t), 1e-12) << "grid point " << k;  // mm
    EXPECT_NE(n.jacobians, 0) << "grid point " << k;
    nearJacobians += n.jacobians;
    coldJacobians += c.jacobians;
  }
  EXPECT_LT(std::abs(near->meanEnvelope.t - cold->meanEnvelope.t), 1e-12);
  EXPECT_LT(nearJacobians, coldJacobians);
}

TEST(SolverOptions, EnvelopeIterationLimitAndStepLimitsAreHonoured) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials run = runWithError(job.nominalAxes);
  EnvelopeSolverOptions once;
  once.maxIterations = 1;
  auto f = simulateGroundFace(job.setup, run, job.grid, Sensitivities::Skip, once);
  ASSERT_FALSE(f.ok());
  EXPECT_EQ(f.error().field, "grid");

  // Steps cut to 1e-9 mm in t cannot reach a deviation of some µm within the default 40 steps.
  EnvelopeSolverOptions crawling;
  crawling.offsetStepLimit = 1e-9;
  auto g = simulateGroundFace(job.setup, run, job.grid, Sensitivities::Skip, crawling);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.error().field, "grid");
}

TEST(SolverOptions, ALooserEnvelopeToleranceStopsSoonerNearTheSameFace) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials run = runWithError(job.nominalAxes);
  EnvelopeSolverOptions loose;
  loose.stepTolerance = 1e-4;  // mm
  auto tight = simulateGroundFace(job.setup, run, job.grid, Sensitivities::Skip);
  auto rough = simulateGroundFace(job.setup, run, job.grid, Sensitivities::Skip, loose);
  ASSERT_TRUE(tight.ok() && rough.ok());
  EXPECT_LT(totalIterations(*rough), totalIterations(*tight));
  for (size_t k = 0; k < tight->envelope.size(); ++k)
    EXPECT_NEAR(rough->envelope[k].t, tight->envelope[k].t, 1e-4) << "grid point " << k;
}

TEST(SolverOptions, ContactAndRimIterationLimitsAreHonoured) {
  const SharpeningJob job = jobOf(paperCase());
  const SharpeningSetup& s = job.setup;
  ContactSolverOptions once;
  once.maxIterations = 1;
  auto p = wheelProfile(s.face, s.universal, s.normalSign, {19.0, 40.0}, once);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("no contact"), std::string::npos) << p.error().message;
  ASSERT_TRUE(wheelProfile(s.face, s.universal, s.normalSign, {19.0, 40.0}).ok());

  RimSolverOptions twice;
  twice.maxIterations = 2;
  auto E = centerDistanceFromWheelRim(s.face, s.universal, s.normalSign, 19.0, 50.0, twice);
  ASSERT_FALSE(E.ok());
  EXPECT_EQ(E.error().field, "wheel.outerDiameter");
  auto exact = centerDistanceFromWheelRim(s.face, s.universal, s.normalSign, 19.0, 50.0);
  ASSERT_TRUE(exact.ok());
  EXPECT_NEAR(*exact, 69.446175, 5e-7);  // docs/conventions.md §Centre distance
}

TEST(SolverOptions, CorrectableShareDecidesTheVerdict) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  const FaceGrid& g = job.grid;
  Eigen::MatrixXd shape(g.rows(), g.cols());  // a second-degree radial shape: partly uncorrectable
  for (int i = 0; i < g.rows(); ++i) {
    const double z = (g.r[i] - g.rMean()) / (0.5 * (g.r.back() - g.r.front()));
    shape.row(i).setConstant(10.0 * z * z);
  }
  const GroundFace face = groundFaceOf(job, nominal);
  auto strict = correctionStep(face, nominal, shape, CorrectionOptions{});
  CorrectionOptions lenient;
  lenient.correctableShare = 0.99;
  auto relaxed = correctionStep(face, nominal, shape, lenient);
  ASSERT_TRUE(strict.ok() && relaxed.ok());
  EXPECT_NE(strict->verdict.find("uncorrectable"), std::string::npos) << strict->verdict;
  EXPECT_NE(relaxed->verdict.find("Correctable"), std::string::npos) << relaxed->verdict;
  EXPECT_EQ(relaxed->uncorrectableShare, strict->uncorrectableShare);
}

TEST(SolverOptions, ListedShareDecidesWhichCoefficientsDescribeACombination) {
  const SharpeningJob job = jobOf(paperCase());
  const AxisPolynomials& nominal = job.nominalAxes;
  const Eigen::MatrixXd measured = topographyFor(job, runWithError(nominal)).normal;
  const GroundFace face = groundFaceOf(job, nominal);
  auto usual = correctionStep(face, nominal, measured, CorrectionOptions{});
  CorrectionOptions everything;
  everything.listedShare = 0;  // every coefficient of the direction, however small its share
  auto all = correctionStep(face, nominal, measured, everything);
  ASSERT_TRUE(usual.ok() && all.ok());
  ASSERT_EQ(usual->unobservable.size(), all->unobservable.size());
  size_t usualCount = 0, allCount = 0;
  for (size_t k = 0; k < usual->unobservable.size(); ++k) {
    usualCount += usual->unobservable[k].coefficients.size();
    allCount += all->unobservable[k].coefficients.size();
  }
  EXPECT_GT(allCount, usualCount);
}

// stalledGradientCosine (least_squares_options.h): a solve ended by the function tolerance after
// trial faces were rejected is convergence if the misfit is within the probe noise, a stall if it
// is above it with the residual still leaning on an identified direction (cosine above the
// option), and above the noise otherwise.
TEST(SolverOptions, RejectedTrialFacesWithTheResidualLeaningOnADirectionAreAStall) {
  using Eigen::LevenbergMarquardtSpace::RelativeReductionTooSmall;
  LeastSquaresOptions o;
  const int points = 45;
  const double sigma = 0.01, within = 0.5 * points * sigma * sigma, above = 100 * points * sigma * sigma;
  const auto end = [&](int unsolvable, double cosine, double misfit) {
    LeastSquaresSummary s;
    describeSolve(s, RelativeReductionTooSmall, unsolvable, cosine, o, "no axis direction");
    judgeMisfit(s, misfit, points, sigma);
    return s;
  };
  EXPECT_EQ(end(309, 0.77, above).status, SolveStatus::Stalled);
  EXPECT_NE(end(309, 0.77, above).reason.find("309 trial faces rejected"), std::string::npos) << end(309, 0.77, above).reason;
  EXPECT_EQ(end(309, 0.77, within).status, SolveStatus::Converged);
  EXPECT_EQ(end(0, 0.77, above).status, SolveStatus::AboveNoise);
  EXPECT_EQ(end(309, 0.5 * o.stalledGradientCosine, above).status, SolveStatus::AboveNoise);
  o.stalledGradientCosine = 0.9;
  EXPECT_EQ(end(309, 0.77, above).status, SolveStatus::AboveNoise);
}

}  // namespace
}  // namespace hobsharp::test
