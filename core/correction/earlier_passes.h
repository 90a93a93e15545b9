// The earlier passes an identification explains together with the face measured now (docs/method.md
// §Correction from the pass history; issue 20, item 3). The machine's error E is the same in every
// pass (the correction proposes nominal - E for the next pass on that premise), so each earlier
// face is the face its axes grind with E: faces measured at different operating points show
// directions that no single face shows (an error along the structural null space, null at one
// operating point only, structural_null_space.h).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "probe_points.h"

namespace hobsharp {

struct EarlierPass {
  AxisPolynomials axes;      // the axes the machine ran
  Eigen::MatrixXd measured;  // the face measured after it, µm, on the job's grid
};

struct PassHistory {
  AxisPolynomials nominal;          // the axes every run aims at: run = nominal - E of the pass before
  std::vector<EarlierPass> passes;  // on the same machine and wheel, oldest first
  // A pass in the case, or the case, corrects the wheel: no pass joins (joinsLaterPasses), this
  // one's face neither, as the next case keeps that pass.
  bool wheelCorrected = false;
  // The last pass measured at the measuring machine's own points (its deviations one column, in
  // the points' order), with its points: no identification joins it, but the sign check
  // (history_sign.h) reads it against a face measured now at the same points. None where the
  // wheel may have changed (wheelCorrected).
  std::optional<EarlierPass> lastAtPoints;
  ProbePoints lastPoints;

  bool empty() const { return passes.empty(); }  // no pass measured on the grid
};

// Whether a pass's face is in the history later passes are identified with (identifyMachineError):
// it was measured on the grid, and no pass corrects the wheel (a dressing changes the wheel the
// faces are ground with). The case's passes (pass_history.h) and the verdict's offer to keep this
// pass in the case (correction.h) both read it from here.
inline bool joinsLaterPasses(bool measuredOnGrid, bool wheelCorrected) { return measuredOnGrid && !wheelCorrected; }

}  // namespace hobsharp
