// A validated job: the case input checked against every rule of docs/case-format.md, with every
// missing setting derived (setting angle, centre distance, grid, axes).
#pragma once

#include <optional>

#include "case_input.h"
#include "correction.h"
#include "face_grid.h"
#include "outcome.h"
#include "sharpening_setup.h"

namespace hobsharp {

struct SharpeningJob {
  CaseInput input;
  SharpeningSetup setup;      // angles in rad
  double rootRadius = 0;      // mm
  double outerRadius = 0;     // mm
  double wheelRadius = 0;     // mm
  bool settingAngleDerived = false;
  bool centerDistanceDerived = false;
  AxisPolynomials nominalAxes;  // Eq. 9 from the setup (Tab. 2 left)
  AxisPolynomials runAxes;      // case.axes, or the nominal ones
  FaceGrid grid;
  CorrectionOptions correction;
  // measuredPoints off the grid's positions (docs/measured-points.md): the points and their
  // deviations (µm), corrected as points; empty when there are none or they are the grid.
  ProbePoints probes;
  Eigen::VectorXd probeMeasured;
};

Outcome<SharpeningJob> resolveJob(const CaseInput& input);

}  // namespace hobsharp
