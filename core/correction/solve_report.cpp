#include "solve_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hobsharp {
namespace {

// A tolerance as a share in words: 1e-10 -> "1 part in 1e+10".
std::string share(double tolerance) {
  std::ostringstream t;
  t.precision(2);
  t << "1 part in " << 1 / tolerance;
  return t.str();
}

}  // namespace

void describeSolve(LeastSquaresSummary& s, Eigen::LevenbergMarquardtSpace::Status st, int unsolvable,
                   double gradientCosine, const LeastSquaresOptions& o, const std::string& makes) {
  using namespace Eigen::LevenbergMarquardtSpace;
  // Steps rejected because their faces could not be simulated shrink the trust region as failed
  // steps do, until the function or the parameter tolerance ends the solve: convergence only if
  // the residual no longer leans on a direction the solve can move.
  s.blockedByUnsolvable = unsolvable > 0 && gradientCosine > o.stalledGradientCosine &&
                          (st == RelativeReductionTooSmall || st == RelativeErrorAndReductionTooSmall ||
                           st == RelativeErrorTooSmall);
  s.blockedReason.clear();
  if (s.blockedByUnsolvable) {
    std::ostringstream r;
    r.precision(2);
    r << "the steps that would lower the sum of squares further may lead to faces the wheel cannot grind ("
      << unsolvable << " trial " << (unsolvable == 1 ? "face" : "faces")
      << " rejected during the solve; the residual still leans on an identified direction, cosine " << gradientCosine
      << "); the best estimate is kept.";
    s.blockedReason = r.str();
  }
  switch (st) {
    case RelativeReductionTooSmall:
    case RelativeErrorAndReductionTooSmall:
      s.status = SolveStatus::Converged;
      s.reason = "converged: a further step would lower the sum of squares by less than " + share(o.functionTolerance) +
                 " of it (function tolerance).";
      break;
    case RelativeErrorTooSmall:
      s.status = SolveStatus::Converged;
      s.reason = "converged: the last steps changed the identified error by less than " + share(o.parameterTolerance) +
                 " of it (parameter tolerance).";
      break;
    case CosinusTooSmall:
      s.status = SolveStatus::Converged;
      s.reason = "converged: what is left of the measured face is a shape " + makes + " makes (gradient tolerance).";
      break;
    case FtolTooSmall:
    case XtolTooSmall:
    case GtolTooSmall:
      if (unsolvable > 0) {
        s.status = SolveStatus::Stalled;
        s.reason = "stalled: every further step leaves the face the wheel can grind; the best estimate is kept.";
      } else {
        s.status = SolveStatus::Converged;
        s.reason = "converged: no step can reduce the sum of squares at the precision of the face simulation.";
      }
      break;
    case TooManyFunctionEvaluation:
    case Running:
      s.status = SolveStatus::NoConvergence;
      s.reason = "not converged after " + std::to_string(o.maxIterations) +
                 " iterations (maxIterations); the best estimate is kept.";
      break;
    default:
      s.status = SolveStatus::Stalled;
      s.reason = "stalled: the Jacobian could not be factorised; the best estimate is kept.";
      break;
  }
}

double noiseCeiling(int points, double sigma) {
  const double n = std::max(1, points);
  return n * sigma * sigma * (1 + 3 * std::sqrt(2 / n));
}

void judgeMisfit(LeastSquaresSummary& s, double misfit, int points, double sigma) {
  if (s.status != SolveStatus::Converged || points <= 0) return;
  const double n = points;
  if (misfit <= noiseCeiling(points, sigma)) return;
  std::ostringstream r;
  r.precision(2);
  if (s.blockedByUnsolvable) {
    r.precision(3);  // as the verdict writes the face measured
    r << "stalled above the probe noise: " << std::sqrt(misfit / n) << " µm rms of the measured face is left (sigma "
      << sigma << " µm), and " << s.blockedReason;
    s.status = SolveStatus::Stalled;
    s.reason = r.str();
    return;
  }
  r << "ended above the probe noise: " << std::sqrt(misfit / n) << " µm rms of the measured face is left (sigma "
    << sigma << " µm), a shape the identified directions do not make; " << s.reason;
  s.status = SolveStatus::AboveNoise;
  s.reason = r.str();
}

}  // namespace hobsharp
