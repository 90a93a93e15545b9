// The wheel-profile correction (docs/method.md §Wheel-profile correction, `correction.wheel: true`): the
// axes and a wheel-profile offset from one measured face. The machine error E and the wheel's
// deviation W are identified together (wheel_error.h); the proposal is to run nominal - E and to
// dress -(O + W) in addition to the wheel's current offset O (the case's), which brings the wheel
// back to the conjugate one that grinds the nominal face. Every figure of the axes' correction
// (correction.h) then holds with both applied: the face predicted after the pass is re-simulated
// with the true wheel plus the dressing and the true axes, i.e. the conjugate wheel plus what of O
// a spline through the dressing's points cannot take (none when O is such a spline, as an earlier
// pass's dressing is), plus what neither makes.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "correction.h"
#include "dressed_wheel.h"
#include "wheel_error.h"
#include "wheel_profile.h"

namespace hobsharp {

struct WheelCorrection {
  WheelKnots knots;
  std::vector<double> offset;     // µm at knots.R: what to dress in addition to the current offset O, -(O + W)
  std::vector<double> deviation;  // µm at knots.R: W, the wheel's identified deviation from the case's wheel
  // The corrected axial profile: the current profile (with the case's offset) plus `offset`, at the
  // conjugate profile's points given (Fig. 4's), for a CNC dresser.
  DressedProfile dresser;
  // The dressing's largest magnitude, µm: over the points and the dresser path (the spline between
  // the points may reach further than they do: 0.286 µm against 0.251 at the points, a review).
  double largestOffset = 0;
  // The measured face minus the face predicted after the pass, split: the part the axes' span
  // holds (at the solution), and the rest, the shape only the wheel makes. µm, grid-shaped.
  Eigen::MatrixXd removedByAxes, removedByWheel;
  // Their shares of the measured sum of squares, 0..1: with correction.uncorrectableShare they
  // sum to 1 (axes first: |m|² - |m - axes|², then |m - axes|² - |after|², over |m|²).
  double axesShare = 0, wheelShare = 0;
  Eigen::VectorXd singularValues;  // wheel_error.h's wheelSingularValues
  std::vector<bool> used;
  int withinNoise = 0, amplifying = 0;
};

struct AxesAndWheelCorrection {
  Correction correction;  // the axes' figures, with the wheel in the model
  WheelCorrection wheel;
};

// `runFace` simulated for `run` with setup's wheel; `conjugate` the conjugate profile's points the
// dresser path is given at; rLow and rHigh the tooth-face radii of the grid within the face, mm.
Outcome<AxesAndWheelCorrection> correctAxesAndWheel(const SharpeningSetup& setup, const AxisPolynomials& nominal,
                                                    const AxisPolynomials& run, const GroundFace& runFace,
                                                    const Eigen::MatrixXd& measured, const CorrectionOptions& options,
                                                    const WheelProfile& conjugate, double rLow, double rHigh,
                                                    const AxisPolynomials* linearisedAt = nullptr);

}  // namespace hobsharp
