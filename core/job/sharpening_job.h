// A checked job: the case input checked against every rule of docs/case-format.md and resolved
// into what the evaluation (evaluation.h) runs, with every missing setting derived (setting angle,
// centre distance, grid, axes). The job keeps no raw input: each part is made from the case's own
// part by a named function in its own file, which refuses it naming the field.
#pragma once

#include "case_input.h"
#include "correction_options.h"
#include "face_grid.h"
#include "gear_plan.h"
#include "inspection_plan.h"
#include "measured_face.h"
#include "outcome.h"
#include "earlier_passes.h"
#include "sharpening_setup.h"
#include "wheel_profile.h"

namespace hobsharp {

// The points of the wheel's axial profile, root to tip: the result's wheelProfile, and the
// profile the setup's wheelEdge is found on.
constexpr int kWheelProfilePoints = 41;

struct SharpeningJob {
  SharpeningSetup setup;      // angles in rad; setup.wheel the case's wheel (wheel_input.h)
  double rootRadius = 0;      // mm
  double outerRadius = 0;     // mm
  double wheelRadius = 0;     // mm
  WheelProfile wheelProfile;  // the conjugate wheel's profile (Eq. 6), kWheelProfilePoints radii, root to tip
  bool settingAngleDerived = false;
  bool centerDistanceDerived = false;
  bool wheelMeasured = false;    // setup.wheel is the case's wheel.measuredProfile
  AxisPolynomials nominalAxes;   // Eq. 9 from the setup (Tab. 2 left)
  AxisPolynomials runAxes;       // case.axes, or the nominal ones (run_axes.h)
  FaceGrid grid;                 // grid_input.h
  CorrectionOptions correction;  // correction_input.h
  MeasuredFace measured;         // the measured grid or points (measured_face.h)
  PassHistory history;           // the earlier passes measured on the grid (pass_history.h)
  InspectionPlan inspection;     // inspection_plan.h
  GearPlan gear;                 // gear_plan.h
};

Outcome<SharpeningJob> resolveJob(const CaseInput& input);

}  // namespace hobsharp
