// How a Levenberg-Marquardt solve of the identification ended, in the engineer's words
// (least_squares_options.h): the status and a sentence naming the tolerance that stopped it.
#pragma once

#include <string>

#include <unsupported/Eigen/LevenbergMarquardt>

#include "least_squares_options.h"

namespace hobsharp {

// `unsolvable`: trial faces the wheel could not grind over the solve; `gradientCosine`: the largest
// cosine between the residual and a Jacobian column at the start of the last iteration (MINPACK's
// gnorm: at the final estimate unless that iteration's step was taken; on the five blocked solves
// of the tests it equals the cosine at the final estimate to 3 digits); `makes`: what cannot
// make the rest, for the gradient's sentence ("no identified axis direction").
void describeSolve(LeastSquaresSummary& s, Eigen::LevenbergMarquardtSpace::Status st, int unsolvable,
                   double gradientCosine, const LeastSquaresOptions& o, const std::string& makes);

// The largest sum of squares (µm²) the probe noise sigma alone gives over `points` values, to 3
// standard deviations of its chi-square: points sigma² (1 + 3 sqrt(2 / points)).
double noiseCeiling(int points, double sigma);

// A solve that met a tolerance is "converged" only when the misfit left (µm²) is within the
// noiseCeiling of `points` values of the probe noise sigma; otherwise it ended above the noise,
// and the reason says how much is left.
void judgeMisfit(LeastSquaresSummary& s, double misfit, int points, double sigma);

}  // namespace hobsharp
