// The one Levenberg-Marquardt solve of the identification (identification.cpp): Eigen's
// LevenbergMarquardt (MINPACK's lmder) with the tolerances of LeastSquaresOptions, from theta, for
// at most the iterations the summary has left. The residual functor counts in `unsolvable` the
// trial faces the wheel cannot grind (rejected steps).
#pragma once

#include <string>

#include <Eigen/Core>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "least_squares_options.h"
#include "solve_report.h"

namespace hobsharp {

// Runs the solve; theta becomes the best iterate (the solver accepts only steps that lower the sum
// of squares). Returns false, with theta as given, when the solve cannot start: at the start's face
// the residual or its Jacobian cannot be formed (`refused` says whether the solver refused its
// inputs). Otherwise adds the iterations to the summary and says how the solve ended (`makes`: what
// the identified directions are, for the reason's words).
template <class Residual>
bool solveLeastSquares(Residual& residual, Eigen::VectorXd& theta, const LeastSquaresOptions& o,
                       LeastSquaresSummary& summary, const std::string& makes, bool* refused = nullptr) {
  using namespace Eigen::LevenbergMarquardtSpace;
  Eigen::LevenbergMarquardt<Residual> lm(residual);
  lm.setFtol(o.functionTolerance);
  lm.setXtol(o.parameterTolerance);
  lm.setGtol(o.gradientTolerance);
  lm.setFactor(o.initialTrustRegion);
  lm.setMaxfev(1000000);  // the iterations are counted here
  if (o.stepScale == LeastSquaresOptions::StepScale::Parameters) {
    lm.setExternalScaling(true);
    lm.diag() = Eigen::VectorXd::Ones(theta.size());
  }
  Status status = lm.minimizeInit(theta);
  if (status != NotStarted) {
    if (refused) *refused = status == ImproperInputParameters;
    return false;
  }
  int iterations = 0;
  const int left = o.maxIterations - summary.iterations;
  do {
    status = lm.minimizeOneStep(theta);
    ++iterations;
  } while (status == Running && iterations < left);
  summary.iterations += iterations;
  describeSolve(summary, status, residual.unsolvable, lm.gnorm(), o, makes);
  return true;
}

}  // namespace hobsharp
