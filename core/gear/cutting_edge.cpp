#include "cutting_edge.h"

#include <cmath>

#include <Eigen/Dense>

#include "number_text.h"
#include "units.h"

namespace hobsharp {
namespace {

constexpr int kMaxIterations = 30;
constexpr double kStepTolerance = 1e-11;  // mm
constexpr double kDifferenceStep = 1e-6;  // mm, forward differences of the Jacobian
constexpr int kJacobianAge = 8;           // steps between two Jacobians

struct Residual {
  Eigen::Vector2d F;
  double behind = 0;
};

}  // namespace

double BasicRack::toothThickness() const { return kPi * module / 2; }

double flankAxial(const BasicRack& rack, double toothCentre, Flank flank, double R) {
  const double s = flank == Flank::Right ? 1.0 : -1.0;
  return toothCentre + s * (rack.toothThickness() / 2 - (R - rack.pitchRadius) * std::tan(rack.pressureAngle));
}

Outcome<EdgePoint> cuttingEdgePoint(const ActualRakeFace& face, const BasicRack& rack, double reliefPerRadian,
                                    double toothCentre, Flank flank, double R) {
  auto residual = [&](const Eigen::Vector2d& v) {
    const Eigen::Vector3d p = face.point(v(0), v(1));
    const double radius = std::hypot(p.y(), p.z());
    const double angle = std::atan2(p.z(), p.y());
    Residual out;
    out.behind = face.cuttingSense() * std::remainder(face.nominalAngle(radius, p.x()) - angle, 2 * kPi);
    out.F(0) = radius - R;
    out.F(1) = p.x() - flankAxial(rack, toothCentre, flank, R + reliefPerRadian * out.behind);
    return out;
  };
  // Start at the nominal edge point: on the nominal face its radius is R and psi is 0.
  // The Jacobian changes little over the few micrometres the edge moves: it is formed at the start
  // and every kJacobianAge steps after (a chord Newton method; each step then costs one residual).
  Eigen::Vector2d v(R, flankAxial(rack, toothCentre, flank, R));
  Eigen::Matrix2d J;
  for (int it = 1; it <= kMaxIterations; ++it) {
    const Residual f = residual(v);
    if ((it - 1) % kJacobianAge == 0) {
      for (int k = 0; k < 2; ++k) {
        Eigen::Vector2d w = v;
        w(k) += kDifferenceStep;
        J.col(k) = (residual(w).F - f.F) / kDifferenceStep;
      }
    }
    const Eigen::Vector2d step = J.fullPivLu().solve(-f.F);
    if (!step.allFinite()) break;
    v += step;
    if (step.norm() < kStepTolerance) {
      const Residual g = residual(v);
      EdgePoint e;
      e.r = v(0);
      e.x = v(1);
      e.behind = g.behind;
      e.deviation = -reliefPerRadian * g.behind * std::sin(rack.pressureAngle);
      e.iterations = it;
      return e;
    }
  }
  return refuse("gearEffect", "the cutting edge at radius " + mmText(R) + " of the tooth at x = " + mmText(toothCentre) +
                                  " could not be found on the actual rake face.",
                ErrorCode::Unsolvable);
}

}  // namespace hobsharp
