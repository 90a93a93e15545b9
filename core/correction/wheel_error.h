// Identify, then compensate, with the wheel (docs/method.md §Wheel-profile correction, `correction.wheel`):
// the machine error E and the wheel's deviation W from the case's wheel that together made the
// measured face when `run` was commanded: minimise |face(run + E; wheel + W) - measured|² over E
// and W by the identification (identification.h) with two parameter blocks, the axes and then the
// wheel, with the analytic Jacobian to both (Eqs. 13-16 for E, wheel_offset_sensitivity.h for W).
//
// W is a not-a-knot cubic spline through a few points over the wheel radii the grid is ground with
// (wheelKnots), in µm, added to the case's wheel along the profile normal (wheel_surface.h).
// The split between the two is decided, not left to the solver: the axes take every face
// direction they make, decided as machine_error.h decides them (machine steps, above
// significance * sigma of the probe noise, not wild); the wheel's columns are projected off the
// span of the directions the axes take, so W holds only the shape the axes cannot make, and its
// directions of that projection are decided by the same two rules. A constant or linear offset
// along the radius, which the axes make nearly as well, is so left to the axes.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "cubic_spline.h"
#include "correction_options.h"
#include "ground_face.h"
#include "machine_error.h"
#include "outcome.h"
#include "sharpening_setup.h"

namespace hobsharp {

// The points of W's spline: evenly in the tooth-face radius over the grid's radii within the
// face (so on an even grid of 4 to 12 lines, one point per radial grid line: the basis grows with
// the probe rows), at the conjugate wheel radius R that grinds each.
struct WheelKnots {
  std::vector<double> r;  // tooth-face radius, mm (decreasing: the wheel's rim grinds the root)
  std::vector<double> R;  // conjugate wheel radius, mm, increasing
};
// At most 12: a profile of 12 points holds any smooth radial shape a dressing leaves (the campaign's
// shapes are of degree 4); more rows than that only add equations.
constexpr int kFewestWheelKnots = 4, kMostWheelKnots = 12;

// clamp(grid rows, 4, 12) points from rLow to rHigh (tooth-face radii, mm; the grid's within the face).
Outcome<WheelKnots> wheelKnots(const SharpeningSetup& setup, const FaceGrid& grid, double rLow, double rHigh);

// W (µm at knots.R) as the spline the wheel adds, mm: not-a-knot, as a dressed wheel's offset
// reads (wheel_input.cpp). With W = 0 its basis gives the face's sensitivities to W
// (wheel_offset_sensitivity.h): the one spline for both, so the Jacobian is that of the model.
CubicSpline wheelDeviationSpline(const WheelKnots& knots, const Eigen::VectorXd& W);

// `setup` with its wheel's offset raised by W (µm at knots.R) along the profile normal, as its
// WheelSurface::added spline (replacing any there).
SharpeningSetup withWheelDeviation(const SharpeningSetup& setup, const WheelKnots& knots, const Eigen::VectorXd& W);

struct WheelErrorEstimate {
  // E as machine_error.h reports it, with W in the model: `face` is face(run + E; wheel + W),
  // `unexplained` what neither makes (the noise), `covariancePerNoise` E's with W free.
  MachineErrorEstimate axes;
  WheelKnots knots;
  Eigen::VectorXd deviation;  // W at knots.R, µm (+ = more wheel than the case's wheel)
  // The singular values of the wheel's columns off the axes' span (µm of face per µm of W),
  // largest first, and which of them the measurement shows above the noise and not wild.
  Eigen::VectorXd wheelSingularValues;
  std::vector<bool> wheelUsed;
  int wheelWithinNoise = 0, wheelAmplifying = 0;
  // p x k, orthonormal columns: the face directions the identified axis directions make, at the
  // solution (the split of what was removed, wheel_correction.h).
  Eigen::MatrixXd axesSpan;
};

// With `nominal`, the search starts at the error the run compensates (nominal - run, machine_error.h),
// within the identifiable space, where the face of run plus it can be simulated; otherwise at E = 0,
// and once more at E = 0 where the search from there runs out of iterations or stalls (the one that
// explains the face better is kept).
// A later pass's run is nominal - E of the pass before, and its face is what that E left: one face
// does not decide the error along the directions it barely shows (a wheel slope and the axis changes
// that mimic it), and a search from E = 0 (the whole error again) could end far from that E along
// them, which on the true machine left 3 to 8 µm where the face measured 0.02 to 0.16 µm
// (docs/validation.md, "Where a later wheel pass starts").
Outcome<WheelErrorEstimate> identifyMachineAndWheelError(const SharpeningSetup& setup, const AxisPolynomials& run,
                                                         const GroundFace& runFace, const Eigen::MatrixXd& measured,
                                                         const CorrectionOptions& options, const WheelKnots& knots,
                                                         const AxisPolynomials* nominal = nullptr);

}  // namespace hobsharp
