// How a Levenberg-Marquardt solve of the identification ended, in the engineer's words
// (least_squares_options.h): the status and a sentence naming the tolerance that stopped it.
#pragma once

#include <string>

#include <unsupported/Eigen/LevenbergMarquardt>

#include "least_squares_options.h"

namespace hobsharp {

// `unsolvable`: trial faces the wheel could not grind; `makes`: what cannot make the rest, for the
// gradient's sentence ("no identified axis direction").
void describeSolve(LeastSquaresSummary& s, Eigen::LevenbergMarquardtSpace::Status st, int unsolvable,
                   const LeastSquaresOptions& o, const std::string& makes);

}  // namespace hobsharp
