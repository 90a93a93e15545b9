#include "wheel_profile.h"
#include "number_text.h"

#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "autodiff.h"
#include "wheel_contact.h"

namespace hobsharp {
Outcome<double> contactCoordinate(const ToothFace& face, const UniversalSettings& s,
                                  double normalSign, double u, double wGuess,
                                  const ContactSolverOptions& options) {
  const double E = s.centerDistance.coefficient(0);
  const ContactRotations rotations = contactRotations(s);  // fixed: formed once, not per step
  double w = wGuess;
  for (int i = 0; i < options.maxIterations; ++i) {
    const WheelContact<Dual<1>> c = wheelContact(face, s, rotations, normalSign, E, Dual<1>(u), variable<1>(w, 0));
    const double f = c.meshing.value(), df = c.meshing.derivatives()(0);
    if (!std::isfinite(f) || !std::isfinite(df) || df == 0.0) break;
    double step = f / df;
    const double limit = face.helical() ? options.helicalStepLimit : options.straightStepLimit;
    if (std::abs(step) > limit) step = std::copysign(limit, step);
    w -= step;
    if (std::abs(step) < options.relativeStepTolerance * (1.0 + std::abs(w))) return w;
  }
  const double radius = std::hypot(u + face.y0Pitch(), face.rakeOffset);
  return refuse("setup", "no contact between the wheel and the tooth face at radius r = " + mmText(radius) +
                           ": the equation of meshing (Eq. 5) has no solution there. Check the "
                           "setting angle, tilt and centre distance.",
                ErrorCode::Unsolvable);
}

std::vector<double> evenRadii(double rootRadius, double outerRadius, int points) {
  std::vector<double> radii(points);
  for (int k = 0; k < points; ++k)
    radii[k] = rootRadius + (outerRadius - rootRadius) * k / (points - 1);
  return radii;
}

Outcome<WheelProfile> wheelProfile(const ToothFace& face, const UniversalSettings& s,
                                   double normalSign, const std::vector<double>& radii,
                                   const ContactSolverOptions& options) {
  WheelProfile p;
  const double E = s.centerDistance.coefficient(0);
  const int points = static_cast<int>(radii.size());
  // Start at the pitch radius, where the contact coordinate is near zero, and continue outwards.
  auto pitchStart = contactCoordinate(face, s, normalSign, 0.0, 0.0, options);
  if (!pitchStart) return pitchStart.error();
  p.r = radii;
  p.w.assign(points, 0.0);
  p.R.assign(points, 0.0);
  p.Z.assign(points, 0.0);
  const WheelContact<double> pitch = wheelContact(face, s, normalSign, E, 0.0, *pitchStart);
  const Eigen::Vector2d side(pitch.r.x(), pitch.r.y());
  int start = 0;
  while (start + 1 < points && radii[start + 1] <= face.pitchRadius) ++start;
  for (int dir : {+1, -1}) {
    double guess = *pitchStart;
    for (int k = dir > 0 ? start : start - 1; k >= 0 && k < points; k += dir) {
      const double u = face.uAtRadius(radii[k]);
      auto w = contactCoordinate(face, s, normalSign, u, guess, options);
      if (!w) return w.error();
      const WheelContact<double> c = wheelContact(face, s, normalSign, E, u, *w);
      // Every contact point lies on the same side of the wheel axis as the pitch point.
      if (!(c.r.x() * side.x() + c.r.y() * side.y() > 0.0))
        return refuse("wheel.outerDiameter",
                      "the wheel is too small for this gash depth: its axis would pass "
                      "through the tooth face at radius r = " + mmText(radii[k]) + ".");
      p.w[k] = *w;
      p.R[k] = c.R();
      p.Z[k] = c.Z();
      guess = *w;
    }
  }
  return p;
}

Outcome<double> centerDistanceFromWheelRim(const ToothFace& face, const UniversalSettings& s,
                                           double normalSign, double rootRadius,
                                           double wheelRadius, const RimSolverOptions& options) {
  const double u = face.uAtRadius(rootRadius);
  // Start from the wheel radius plus the root radius: the exact answer for eta = gamma_m = 0.
  Eigen::Vector2d x(0.0, wheelRadius + rootRadius);
  for (int i = 0; i < options.maxIterations; ++i) {
    const Dual<2> w = variable<2>(x(0), 0), E = variable<2>(x(1), 1);
    const WheelContact<Dual<2>> c = wheelContact(face, s, normalSign, E, Dual<2>(u), w);
    const Dual<2> rim = c.R() - wheelRadius;
    Eigen::Matrix2d J;
    J.row(0) = c.meshing.derivatives().transpose();
    J.row(1) = rim.derivatives().transpose();
    const Eigen::Vector2d F(c.meshing.value(), rim.value());
    if (!F.allFinite() || !J.allFinite()) break;
    const Eigen::Vector2d step = J.fullPivLu().solve(F);
    if (!step.allFinite()) break;
    x -= step;
    if (step.norm() < options.relativeStepTolerance * (1.0 + x.norm())) {
      if (x(1) > 0.0) return x(1);
      break;
    }
  }
  return refuse("wheel.outerDiameter",
                "the wheel rim (radius " + mmText(wheelRadius) + ") cannot be brought to touch the gash root "
               "(radius " + mmText(rootRadius) + "): no centre distance solves the boundary equation. "
               "Give setup.centerDistance or change the wheel.",
                ErrorCode::Unsolvable);
}

}  // namespace hobsharp
