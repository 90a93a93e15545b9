#include "envelope.h"

#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "autodiff.h"
#include "machine_kinematics.h"
#include "wheel_contact.h"
#include "wheel_profile.h"

namespace hobsharp {
namespace {

// Independent variables of the full derivative: t, u, w, five axis values, five axis rates.
constexpr int kVars = 3 + 2 * kAxisCount;
using D = Dual<kVars>;

template <class T>
Eigen::Matrix<T, 4, 1> residual(const SharpeningSetup& s, const GridPoint& g, const T& t, const T& u,
                                const T& w, const AxisState<T>& axes) {
  using std::sqrt;
  const Vec3<T> G = g.p.cast<T>() + g.n.cast<T>() * t;
  const WheelFramePoint<T> h = hobPointInWheelFrame(G, axes, s.machine, s.psiC());
  const WheelContact<T> c =
      wheelContact(s.face, s.universal, s.normalSign, s.universal.centerDistance.coefficient(0), u, w);
  const T rho = sqrt(h.q.x() * h.q.x() + h.q.y() * h.q.y());
  Eigen::Matrix<T, 4, 1> F;
  F(0) = c.meshing;
  F(1) = rho - c.R();
  F(2) = h.q.z() - c.Z();
  F(3) = c.nRadial() * (h.q.x() * h.qDot.x() + h.q.y() * h.qDot.y()) / rho + c.n.z() * h.qDot.z();
  return F;
}

struct Linearisation {
  Eigen::Vector4d F;
  Eigen::Matrix4d J;  // d F / d(t, phi, u, w)
};

// For Newton's method: four directions, phi entering through the axis values and rates.
Linearisation linearise(const SharpeningSetup& s, const AxisPolynomials& axes, const GridPoint& g,
                        const EnvelopeGuess& v) {
  using D4 = Dual<4>;
  AxisState<D4> state;
  for (int i = 0; i < kAxisCount; ++i) {
    const PolynomialValue p = axes.axis[i].at(v.phi);
    state.value[i] = seeded<4>(p.value, Eigen::Vector4d(0, p.d1, 0, 0));
    state.rate[i] = seeded<4>(p.d1, Eigen::Vector4d(0, p.d2, 0, 0));
  }
  const Eigen::Matrix<D4, 4, 1> F =
      residual<D4>(s, g, variable<4>(v.t, 0), variable<4>(v.u, 2), variable<4>(v.w, 3), state);
  Linearisation L;
  for (int r = 0; r < 4; ++r) {
    L.F(r) = F(r).value();
    L.J.row(r) = F(r).derivatives().transpose();
  }
  return L;
}

// At the solution, with respect to everything: (t, u, w), the axis values and the axis rates.
struct FullLinearisation {
  Eigen::Matrix4d J;                                   // d F / d(t, phi, u, w)
  Eigen::Matrix<double, 4, kAxisCount> dValue, dRate;  // d F / d(axis values), d(axis rates)
};

FullLinearisation lineariseFully(const SharpeningSetup& s, const AxisPolynomials& axes, const GridPoint& g,
                                 const EnvelopeGuess& v) {
  AxisState<D> state;
  std::array<PolynomialValue, kAxisCount> p;
  for (int i = 0; i < kAxisCount; ++i) {
    p[i] = axes.axis[i].at(v.phi);
    state.value[i] = variable<kVars>(p[i].value, 3 + i);
    state.rate[i] = variable<kVars>(p[i].d1, 3 + kAxisCount + i);
  }
  const Eigen::Matrix<D, 4, 1> F =
      residual<D>(s, g, variable<kVars>(v.t, 0), variable<kVars>(v.u, 1), variable<kVars>(v.w, 2), state);
  FullLinearisation L;
  for (int r = 0; r < 4; ++r) {
    const auto& d = F(r).derivatives();
    L.J(r, 0) = d(0);
    L.J(r, 2) = d(1);
    L.J(r, 3) = d(2);
    double dphi = 0;
    for (int i = 0; i < kAxisCount; ++i) {
      L.dValue(r, i) = d(3 + i);
      L.dRate(r, i) = d(3 + kAxisCount + i);
      dphi += d(3 + i) * p[i].d1 + d(3 + kAxisCount + i) * p[i].d2;  // chain rule through phi
    }
    L.J(r, 1) = dphi;
  }
  return L;
}

std::string where(const GridPoint& g) {
  std::ostringstream s;
  s.precision(6);
  s << "r = " << g.r << " mm, x = " << g.x << " mm";
  return s.str();
}

}  // namespace

double EnvelopePoint::sensitivity(Axis axis, int k) const {
  const int i = static_cast<int>(axis);
  // d C(phi) / d a_k = phi^k, d C'(phi) / d a_k = k phi^(k-1).
  const double value = std::pow(phi, k);
  const double rate = k == 0 ? 0.0 : k * std::pow(phi, k - 1);
  return dtdValue[i] * value + dtdRate[i] * rate;
}

EnvelopeGuess nominalGuess(const GridPoint& point, double contactW) {
  EnvelopeGuess g;
  g.u = point.u;
  g.w = contactW;
  g.phi = contactW - point.w;
  return g;
}

Outcome<EnvelopePoint> solveEnvelopePoint(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                          const GridPoint& point, const EnvelopeGuess& guess,
                                          Sensitivities sensitivities, const EnvelopeSolverOptions& o) {
  EnvelopeGuess v = guess;
  const bool helical = setup.face.helical();
  const double motionLimit = helical ? o.helicalMotionStepLimit : o.straightMotionStepLimit;
  const double motionWeight = helical ? o.helicalMotionWeight : o.straightMotionWeight;
  for (int it = 1; it <= o.maxIterations; ++it) {
    const Linearisation L = linearise(setup, axes, point, v);
    if (!L.F.allFinite() || !L.J.allFinite()) break;
    const Eigen::PartialPivLU<Eigen::Matrix4d> lu(L.J);
    Eigen::Vector4d step = lu.solve(L.F);
    if (!step.allFinite()) break;
    const double scale = std::max({std::abs(step(0)) / o.offsetStepLimit, std::abs(step(1)) / motionLimit,
                                   std::abs(step(2)) / o.lineStepLimit, std::abs(step(3)) / motionLimit, 1.0});
    step /= scale;
    v.t -= step(0);
    v.phi -= step(1);
    v.u -= step(2);
    v.w -= step(3);
    const double size =
        std::abs(step(0)) + std::abs(step(2)) + (std::abs(step(1)) + std::abs(step(3))) * motionWeight;
    if (scale == 1.0 && size < o.stepTolerance) {
      EnvelopePoint e;
      e.t = v.t;
      e.phi = v.phi;
      e.u = v.u;
      e.w = v.w;
      e.iterations = it;
      if (sensitivities == Sensitivities::Skip) return e;
      // Converged: linearise once more at the solution for the sensitivities (Eqs. 13-15).
      const FullLinearisation S = lineariseFully(setup, axes, point, v);
      const Eigen::Vector4d lambda = S.J.transpose().partialPivLu().solve(Eigen::Vector4d::UnitX());
      if (!lambda.allFinite()) break;
      for (int i = 0; i < kAxisCount; ++i) {
        e.dtdValue[i] = -lambda.dot(S.dValue.col(i));
        e.dtdRate[i] = -lambda.dot(S.dRate.col(i));
      }
      return e;
    }
  }
  return refuse("grid", "the ground face cannot be solved at the grid point " + where(point) +
                           ": the wheel does not envelop the tooth face there (Eq. 11 has no "
                           "solution). Check the axis polynomials and the grid.",
                ErrorCode::Unsolvable);
}

}  // namespace hobsharp
