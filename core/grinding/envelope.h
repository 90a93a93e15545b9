// One point of the ground face: the envelope of the wheel moved by the axis polynomials
// (Eqs. 7, 10, 11), found on the normal line through a grid point of the nominal face.
//
// Unknowns: t (mm, along the outward normal from the nominal point), the motion parameter phi,
// and the wheel point given by the face coordinates (u, w) of the contact line it was dressed from.
// Equations, with q = the hob point P + t n in the wheel frame S_t:
//   Eq. 5   f_t(u, w) = 0                     (the wheel point lies on the wheel's contact line)
//   Eq. 6   |q_xy| = R(u, w), q_z = Z(u, w)    (q lies on the wheel surface of revolution)
//   Eq. 11  n_wheel . dq/dphi = 0             (meshing: envelope of the moving wheel)
#pragma once

#include <array>
#include <optional>

#include "axis_polynomials.h"
#include "face_grid.h"
#include "outcome.h"
#include "sharpening_setup.h"
#include "wheel_contact.h"

namespace hobsharp {

enum class Sensitivities { Compute, Skip };

struct EnvelopeGuess {
  double t = 0, phi = 0, u = 0, w = 0;
};

struct EnvelopePoint {
  double t = 0;    // normal deviation, mm (plus = excess material)
  double phi = 0;  // motion parameter at which the wheel grinds this point: rad, or mm (straight)
  double u = 0, w = 0;
  int iterations = 0;  // steps taken
  int jacobians = 0;   // of them, Newton steps with a new Jacobian; the others are chord steps
  // The inverse of the Jacobian d(Eqs. 5, 6, 11) / d(t, phi, u, w) the last step was taken with:
  // for the first-order start of solveEnvelopePointNear.
  Eigen::Matrix4d jacobianInverse = Eigen::Matrix4d::Zero();
  // Implicit function theorem: dt / d(axis value) and dt / d(axis rate) at phi, X Y Z A B order.
  std::array<double, kAxisCount> dtdValue{};
  std::array<double, kAxisCount> dtdRate{};
  // With a wheel profile offset delta(R) (wheel_surface.h): dt / d(delta) and dt / d(delta') at the
  // conjugate wheel radius R of the contact (mm); the sensitivity to a knot value y_k of the
  // offset's spline is dtdOffset B_k(R) + dtdOffsetSlope B_k'(R) (wheel_offset_sensitivity.h).
  double dtdOffset = 0, dtdOffsetSlope = 0, wheelRadius = 0;

  // dt / d(a_k) for the coefficient of phi^k of `axis` (Eqs. 13-15).
  double sensitivity(Axis axis, int k) const;
};

// How Newton's method solves the four equations above for (t, phi, u, w) at one grid point.
// "Motion" means phi and w: angles in rad for a helical gash, travels in mm for a straight one.
struct EnvelopeSolverOptions {
  // Newton steps tried before the grid point is reported as not solvable.
  int maxIterations = 40;
  // Step limits: a Newton step that exceeds any of them is shortened, all four unknowns together,
  // until none is exceeded; a shortened step never ends the solve.
  double offsetStepLimit = 1.0;           // mm, on t
  double lineStepLimit = 5.0;             // mm, on u
  double helicalMotionStepLimit = 0.1;    // rad, on phi and on w (helical gash)
  double straightMotionStepLimit = 5.0;   // mm, on phi and on w (straight gash)
  // The solve ends when a full step is small: |dt| + |du| + weight * (|dphi| + |dw|) below
  // stepTolerance, in mm. The weight turns the motion steps into mm.
  double helicalMotionWeight = 50.0;      // mm/rad (helical gash)
  double straightMotionWeight = 1.0;      // mm/mm (straight gash)
  double stepTolerance = 1e-11;           // mm
  // With a dressed wheel (wheel_surface.h): the motion step either side of an envelope point at
  // which the wheel's crossing of the normal line must not lie beyond it (the second-order
  // condition of Eq. 11, envelope.cpp).
  double helicalEdgeStep = 1e-3;          // rad (helical gash)
  double straightEdgeStep = 0.05;         // mm (straight gash)
  double edgeStep(bool helical) const { return helical ? helicalEdgeStep : straightEdgeStep; }
};

// The field of a refusal that blames the dressed wheel (its profile curves past the envelope's edge).
inline constexpr const char* kWildWheelField = "wheel.profileOffset";
// The field of a refusal at a point past the edge of any wheel's envelope (the setup's wheelEdge):
// the tilt, which moves the edge.
inline constexpr const char* kWheelEdgeField = "setup.tilt";

// The setup's fixed angles by their cosines and sines (phi_1, gamma_m, eta of Eq. 3; psi_c of
// Eq. 7): the same at every point of a face, so a face forms them once and hands them to each
// point's solve (the overloads below; the others form them for their one point).
struct SetupRotations {
  ContactRotations contact;
  CosSin<double> psiC;
};
SetupRotations setupRotations(const SharpeningSetup& setup);

Outcome<EnvelopePoint> solveEnvelopePoint(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                          const GridPoint& point, const EnvelopeGuess& guess,
                                          Sensitivities sensitivities = Sensitivities::Compute,
                                          const EnvelopeSolverOptions& options = {});
Outcome<EnvelopePoint> solveEnvelopePoint(const SharpeningSetup& setup, const SetupRotations& rotations,
                                          const AxisPolynomials& axes, const GridPoint& point,
                                          const EnvelopeGuess& guess, Sensitivities sensitivities,
                                          const EnvelopeSolverOptions& options = {});

// The same grid point on a face ground with axes near those `near` was solved with: started from
// its solution with a first-order step, the chord step with its Jacobian, which is the
// implicit-function change of all four unknowns (t, phi, u, w) for the change of the axes
// (Eqs. 13-15 for t), then Newton's method as above. One Newton step fewer than starting from
// `near`'s solution alone, for the same point.
Outcome<EnvelopePoint> solveEnvelopePointNear(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                              const GridPoint& point, const EnvelopePoint& near,
                                              Sensitivities sensitivities = Sensitivities::Compute,
                                              const EnvelopeSolverOptions& options = {});
Outcome<EnvelopePoint> solveEnvelopePointNear(const SharpeningSetup& setup, const SetupRotations& rotations,
                                              const AxisPolynomials& axes, const GridPoint& point,
                                              const EnvelopePoint& near, Sensitivities sensitivities,
                                              const EnvelopeSolverOptions& options = {});

// The sensitivities (Eqs. 13-15) of a solved envelope point `e` (as solveEnvelopePoint returned it
// with Sensitivities::Skip): the same figures as solving with Sensitivities::Compute; false where
// the envelope equations are singular there.
bool addSensitivities(const SharpeningSetup& setup, const AxisPolynomials& axes, const GridPoint& point,
                      EnvelopePoint& e);
bool addSensitivities(const SharpeningSetup& setup, const SetupRotations& rotations, const AxisPolynomials& axes,
                      const GridPoint& point, EnvelopePoint& e);

// Eqs. 5, 6, 11 at the unknowns (t, phi, u, w) of `at`, with the axes `axes`: their residual, and
// their Jacobian d / d(t, phi, u, w) formed afresh there. Where the Jacobian's determinant reaches 0,
// the point's solution meets another one and both vanish (a fold: the wheel stops enveloping the
// face at the point); its unit is the unknowns' product, so only its ratios mean anything.
Eigen::Vector4d envelopeResidual(const SharpeningSetup& setup, const SetupRotations& rotations,
                                 const AxisPolynomials& axes, const GridPoint& point, const EnvelopePoint& at);
Eigen::Matrix4d envelopeJacobian(const SharpeningSetup& setup, const SetupRotations& rotations,
                                 const AxisPolynomials& axes, const GridPoint& point, const EnvelopePoint& at);

// The guess from the nominal screw motion: the wheel touches (u, w) when w + phi = w*(u).
EnvelopeGuess nominalGuess(const GridPoint& point, double contactW);

}  // namespace hobsharp
