#include "envelope.h"

#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "autodiff.h"
#include "machine_kinematics.h"
#include "wheel_contact.h"
#include "wheel_profile.h"
#include "wheel_surface.h"

namespace hobsharp {
namespace {

// Independent variables of the full derivative: t, u, w, five axis values, five axis rates, and
// with a wheel profile offset the shifts of the offset's value and slope (wheel_surface.h).
constexpr int kVars = 3 + 2 * kAxisCount;
constexpr int kVarsWithOffset = kVars + 2;

// The wheel surface point is (R, Z) of the dressed wheel (wheel_surface.h) at the conjugate point
// (u, w); for the conjugate wheel (no offset) these are c.R(), c.Z() and the normal n_t itself.
template <class T>
Eigen::Matrix<T, 4, 1> residual(const SharpeningSetup& s, const GridPoint& g, const T& t, const T& u,
                                const T& w, const AxisState<T>& axes, const T& offsetShift = T(0),
                                const T& slopeShift = T(0)) {
  using std::sqrt;
  const Vec3<T> G = g.p.cast<T>() + g.n.cast<T>() * t;
  const WheelFramePoint<T> h = hobPointInWheelFrame(G, axes, s.machine, s.psiC());
  const WheelContact<T> c =
      wheelContact(s.face, s.universal, s.normalSign, s.universal.centerDistance.coefficient(0), u, w);
  const WheelMeridian<T> m = wheelMeridian(s.wheel, c, offsetShift, slopeShift);
  const T rho = sqrt(h.q.x() * h.q.x() + h.q.y() * h.q.y());
  Eigen::Matrix<T, 4, 1> F;
  F(0) = c.meshing;
  F(1) = rho - m.R;
  F(2) = h.q.z() - m.Z;
  F(3) = m.nR * (h.q.x() * h.qDot.x() + h.q.y() * h.qDot.y()) / rho + m.nZ * h.qDot.z();
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
  Eigen::Vector4d dOffset = Eigen::Vector4d::Zero();   // d F / d(offset value), with an offset
  Eigen::Vector4d dSlope = Eigen::Vector4d::Zero();    // d F / d(offset slope), with an offset
};

template <int N>
FullLinearisation lineariseFully(const SharpeningSetup& s, const AxisPolynomials& axes, const GridPoint& g,
                                 const EnvelopeGuess& v) {
  using D = Dual<N>;
  AxisState<D> state;
  std::array<PolynomialValue, kAxisCount> p;
  for (int i = 0; i < kAxisCount; ++i) {
    p[i] = axes.axis[i].at(v.phi);
    state.value[i] = variable<N>(p[i].value, 3 + i);
    state.rate[i] = variable<N>(p[i].d1, 3 + kAxisCount + i);
  }
  const bool offset = N == kVarsWithOffset;
  const D offsetShift = offset ? variable<N>(0.0, kVars) : D(0.0);
  const D slopeShift = offset ? variable<N>(0.0, kVars + 1) : D(0.0);
  const Eigen::Matrix<D, 4, 1> F = residual<D>(s, g, variable<N>(v.t, 0), variable<N>(v.u, 1),
                                               variable<N>(v.w, 2), state, offsetShift, slopeShift);
  FullLinearisation L;
  for (int r = 0; r < 4; ++r) {
    const auto& d = F(r).derivatives();
    if (offset) L.dOffset(r) = d(kVars), L.dSlope(r) = d(kVars + 1);
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

// Where the wheel at the fixed motion phi = v.phi crosses the normal line of g: Eqs. 5-6 alone,
// solved for (t, u, w) from v; nothing when Newton's method does not settle.
std::optional<double> crossingAt(const SharpeningSetup& s, const AxisPolynomials& axes, const GridPoint& g,
                                 EnvelopeGuess v) {
  for (int it = 0; it < 30; ++it) {
    const Linearisation L = linearise(s, axes, g, v);
    Eigen::Matrix3d J;
    J << L.J(0, 0), L.J(0, 2), L.J(0, 3), L.J(1, 0), L.J(1, 2), L.J(1, 3), L.J(2, 0), L.J(2, 2), L.J(2, 3);
    const Eigen::Vector3d step = J.partialPivLu().solve(L.F.head<3>());
    if (!step.allFinite()) return std::nullopt;
    v.t -= step(0), v.u -= step(1), v.w -= step(2);
    if (step.cwiseAbs().maxCoeff() < 1e-13) return v.t;
  }
  return std::nullopt;
}

// The second-order condition of the envelope for a dressed wheel. Along the motion the wheel's
// crossing t(phi) of the normal line touches the face from one side: for the conjugate wheel the
// envelope point is the crossing's maximum (Tab. 1: t'' about -69 mm/rad^2 at every point), and
// the face is ground where that holds. An offset that curves so sharply that a crossing a small
// motion step away lies beyond the envelope point has taken the wheel past the envelope's edge
// (the two sheets of the envelope meet there): the point found is no longer what the wheel grinds.
bool pastEnvelopeEdge(const SharpeningSetup& s, const AxisPolynomials& axes, const GridPoint& g,
                      const EnvelopeGuess& v, double motionStep) {
  constexpr double kBeyond = 1e-9;  // mm: beyond the solver's noise
  for (double step : {-motionStep, motionStep}) {
    EnvelopeGuess moved = v;
    moved.phi += step;
    const std::optional<double> t = crossingAt(s, axes, g, moved);
    if (t && *t > v.t + kBeyond) return true;
  }
  return false;
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

bool addSensitivities(const SharpeningSetup& setup, const AxisPolynomials& axes, const GridPoint& point,
                      EnvelopePoint& e) {
  // Linearise once more at the solution (Eqs. 13-15): dt by each axis value and rate, by
  // the implicit-function theorem on the four envelope equations.
  const EnvelopeGuess v{e.t, e.phi, e.u, e.w};
  const FullLinearisation S = setup.wheel.hasOffset()
                                  ? lineariseFully<kVarsWithOffset>(setup, axes, point, v)
                                  : lineariseFully<kVars>(setup, axes, point, v);
  const Eigen::Vector4d lambda = S.J.transpose().partialPivLu().solve(Eigen::Vector4d::UnitX());
  if (!lambda.allFinite()) return false;
  for (int i = 0; i < kAxisCount; ++i) {
    e.dtdValue[i] = -lambda.dot(S.dValue.col(i));
    e.dtdRate[i] = -lambda.dot(S.dRate.col(i));
  }
  if (setup.wheel.hasOffset()) {
    e.dtdOffset = -lambda.dot(S.dOffset);
    e.dtdOffsetSlope = -lambda.dot(S.dSlope);
    e.wheelRadius = wheelContact(setup.face, setup.universal, setup.normalSign,
                                 setup.universal.centerDistance.coefficient(0), v.u, v.w).R();
  }
  return true;
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
      if (setup.wheel.hasOffset() && pastEnvelopeEdge(setup, axes, point, v, o.edgeStep(helical)))
        return refuse("grid", "the ground face cannot be solved at the grid point " + where(point) +
                                 ": the dressed wheel's profile offset curves too sharply there, so the "
                                 "wheel no longer envelops the face (Eq. 11 holds past the envelope's "
                                 "edge). Check wheel.profileOffset or wheel.measuredProfile.",
                      ErrorCode::Unsolvable);
      if (sensitivities == Sensitivities::Skip) return e;
      if (!addSensitivities(setup, axes, point, e)) break;
      return e;
    }
  }
  return refuse("grid", "the ground face cannot be solved at the grid point " + where(point) +
                           ": the wheel does not envelop the tooth face there (Eq. 11 has no "
                           "solution). Check the axis polynomials and the grid.",
                ErrorCode::Unsolvable);
}

}  // namespace hobsharp
