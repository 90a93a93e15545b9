// The options and the summary of the nonlinear least-squares identification of the machine error,
// in the manner of Ceres' Solver::Options and Solver::Summary. The solver is Eigen's
// LevenbergMarquardt (MINPACK's lmder); each tolerance says what it tests.
#pragma once

#include <string>

namespace hobsharp {

struct LeastSquaresOptions {
  // Iterations (Jacobian evaluations, each one re-simulated face with its sensitivities) before
  // the solve stops as not converged.
  int maxIterations = 50;
  // The same for the search over every free coefficient (machine_error.h): over the pass history's
  // faces, or on one face with the structural null space freed; the directions one face barely
  // shows are among them. On the campaign's second passes (seed 20261125) 50 left 16 of 95 joined
  // solves unfinished; 200 left none (9 end above the noise, 1 stalls), and 400 or 1000 change no
  // outcome. On one face freed, 50 in place of 200 leaves 5 more of the 150 µm class above 0.1 µm.
  int maxIterationsEveryCoefficient = 200;
  // Converged when both the actual and the predicted relative reductions of the sum of squares
  // in one step are at most this (MINPACK's ftol).
  double functionTolerance = 1e-10;
  // Converged when the trust region, relative to the scaled parameters, is at most this: the
  // steps have become negligible next to the estimate (MINPACK's xtol).
  double parameterTolerance = 1e-10;
  // Converged when the largest cosine between the residual and a Jacobian column is at most this:
  // the residual is orthogonal to every direction the axes can move the face (MINPACK's gtol).
  double gradientTolerance = 1e-12;
  // With trial faces the wheel could not grind (rejected steps): an end by the function or the
  // parameter tolerance is convergence only when the largest cosine between the residual and a
  // Jacobian column is at most this; above it the residual still leans on a direction the solve
  // could move along but for the faces it could not simulate, so the solve stalled.
  double stalledGradientCosine = 1e-3;
  // The first trust region, times the scaled norm of the start (or this value itself when the
  // start is zero), in the units of stepScale (MINPACK's factor).
  double initialTrustRegion = 1000;
  // What the trust region measures a step in.
  //   FaceMoved: each parameter by how much its Jacobian column moves the face (MINPACK's scaling,
  //     the largest column norm seen), so initialTrustRegion is in µm of face. A direction the face
  //     barely shows (X, Y, B on a straight gash: second order only) is then nearly free to move.
  //   Parameters: each parameter in its own units (a machine step of each coefficient), so a step
  //     along a direction the face barely shows costs as much as along any other.
  enum class StepScale { FaceMoved, Parameters };
  StepScale stepScale = StepScale::FaceMoved;
};

enum class SolveStatus {
  Converged,     // one of the tolerances above was met, and the misfit is within the probe noise
  AboveNoise,    // a tolerance was met, but the misfit left is above the noise floor: a shape the
                 // identified directions do not make (the reason says how much)
  NoConvergence, // maxIterations ran out; the best iterate is returned
  Stalled,       // no step reduces the sum of squares further (the reason says why)
  Failed,        // the solve could not start
};

const char* statusName(SolveStatus s);  // "converged", "aboveNoise", "notConverged", "stalled", "failed"

struct LeastSquaresSummary {
  SolveStatus status = SolveStatus::Converged;
  std::string reason;        // a sentence: which tolerance was met, or why it stopped
  int iterations = 0;        // Jacobian evaluations (0: nothing to identify)
  int faceEvaluations = 0;   // re-simulated faces, trial steps included
  int unsolvableFaces = 0;   // trial steps whose face the wheel cannot grind: rejected, not an error
  double initialCost = 0;    // sum of squares at the start, µm²
  double finalCost = 0;      // sum of squares at the best iterate, µm²
  // The last solve met the function or the parameter tolerance with trial faces rejected and the
  // residual still leaning on an identified direction (stalledGradientCosine): if the misfit is
  // above the probe noise, the solve stalled there (judgeMisfit) rather than ended above it.
  bool blockedByUnsolvable = false;
  std::string blockedReason;  // the sentence for that stall

  // As Ceres: the best iterate may be used unless the solve failed to start.
  bool IsSolutionUsable() const { return status != SolveStatus::Failed; }
};

}  // namespace hobsharp
