// The simulated ground face on a measuring grid: an envelope point (Eqs. 7, 10, 11) at every grid
// point, and one more at the mean point for the circular thickness.
#pragma once

#include <vector>

#include "envelope.h"
#include "face_grid.h"
#include "outcome.h"

namespace hobsharp {

struct GroundFace {
  GashKind gash = GashKind::Helical;  // the motion parameter is rad (helical) or mm (straight)
  FaceGrid grid;
  std::vector<GridPoint> points;         // row-major: index = row * cols + col
  std::vector<EnvelopePoint> envelope;   // same order
  GridPoint meanPoint;                   // the grid centre (rMean, xMean)
  EnvelopePoint meanEnvelope;
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

}  // namespace hobsharp
