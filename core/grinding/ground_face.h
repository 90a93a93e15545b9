// The simulated ground face on a measuring grid, or at a measuring machine's probe points: an
// envelope point (Eqs. 7, 10, 11) at every grid point (or probe point), and one more at the grid's
// mean point for the circular thickness.
#pragma once

#include <vector>

#include "envelope.h"
#include "face_grid.h"
#include "outcome.h"
#include "probe_points.h"

namespace hobsharp {

struct GroundFace {
  GashKind gash = GashKind::Helical;  // the motion parameter is rad (helical) or mm (straight)
  FaceGrid grid;
  std::vector<GridPoint> points;         // row-major: index = row * cols + col
  std::vector<EnvelopePoint> envelope;   // same order
  GridPoint meanPoint;                   // the grid centre (rMean, xMean)
  EnvelopePoint meanEnvelope;
  // At probe points (simulateGroundFace with ProbePoints): the points, in the caller's order;
  // `points` and `envelope` follow it, and `grid` only gives the mean point. Empty on the grid.
  ProbePoints probes;

  bool atProbes() const { return !probes.empty(); }
  // The shape of a deviation matrix on this face: the grid's, or one column of the probe points.
  int rows() const { return atProbes() ? static_cast<int>(probes.size()) : grid.rows(); }
  int cols() const { return atProbes() ? 1 : grid.cols(); }
  int size() const { return static_cast<int>(envelope.size()); }
};

// The range of the motion parameter phi over the grid's envelope points, widened to include 0
// (the pitch point): rad, or mm for a straight gash.
struct MotionRange {
  double min = 0, max = 0;
};
MotionRange motionRange(const GroundFace& face);

// With Sensitivities::Skip the envelope points carry no derivatives (a plot-only topography).
Outcome<GroundFace> simulateGroundFace(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                       const FaceGrid& grid, Sensitivities sensitivities = Sensitivities::Compute,
                                       const EnvelopeSolverOptions& options = {});

// The same at probe points: one envelope point at each (r, x), each solve started from the nominal
// screw motion at its own radius; `grid` gives the mean point. A point the wheel does not grind
// is refused as measuredPoints[k] (k its index in `probes`).
Outcome<GroundFace> simulateGroundFace(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                       const ProbePoints& probes, const FaceGrid& grid,
                                       Sensitivities sensitivities = Sensitivities::Compute,
                                       const EnvelopeSolverOptions& options = {});

// Where simulateGroundFaceLike starts each point's solve. At probe points always from `like`'s
// solution at the point, moved to first order (solveEnvelopePointNear). On a grid, by default as
// the first simulation did (from the row's neighbour): the same figures as simulating the face
// afresh, which the identification's decisions (a step taken, convergence) rest on, as they turn on
// the last bits; with FaceStart::Near from `like`'s solutions, as at probe points (the same
// solutions to within the solver's tolerance, in fewer Newton steps: the prediction's bound).
enum class FaceStart { AsSimulated, Near };

// The face ground with `axes` at the points `like` was simulated at (its grid, or its probes).
Outcome<GroundFace> simulateGroundFaceLike(const GroundFace& like, const SharpeningSetup& setup,
                                           const AxisPolynomials& axes,
                                           Sensitivities sensitivities = Sensitivities::Compute,
                                           FaceStart start = FaceStart::AsSimulated);

// Gives a face simulated with Sensitivities::Skip its sensitivities at the same solutions, in
// place: equal to simulating it with Sensitivities::Compute (the identification's trial steps need
// no sensitivities; machine_error.cpp). Refused as a face that cannot be solved where the envelope
// equations are singular.
Outcome<void> addSensitivities(GroundFace& face, const SharpeningSetup& setup, const AxisPolynomials& axes);

}  // namespace hobsharp
