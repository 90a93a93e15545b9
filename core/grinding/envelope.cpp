#include "envelope.h"

#include <algorithm>
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

// One envelope point's equations: the setup, the axes, the grid point, and the cosines and sines
// of the setup's fixed angles (setupRotations), formed once for the face rather than at every
// point or Newton step.
struct PointEquations {
  PointEquations(const SharpeningSetup& setup, const SetupRotations& r, const AxisPolynomials& a,
                 const GridPoint& point)
      : s(setup), axes(a), g(point), contact(r.contact), psiC(r.psiC) {}
  const SharpeningSetup& s;
  const AxisPolynomials& axes;
  const GridPoint& g;
  const ContactRotations& contact;
  const CosSin<double>& psiC;
};

// The wheel's side of Eqs. 5-6 at the face coordinates (u, w) of its contact line: the equation
// of meshing and the dressed meridian there (for the conjugate wheel c.R(), c.Z() and n_t itself).
// It depends on u and w (and the offset's shifts) only, so its derivatives need those directions alone.
template <class T>
struct WheelSide {
  T meshing;
  WheelMeridian<T> m;
};

template <class T>
WheelSide<T> wheelSide(const PointEquations& q, const T& u, const T& w, const T& offsetShift = T(0),
                       const T& slopeShift = T(0)) {
  const SharpeningSetup& s = q.s;
  const WheelContact<T> c = wheelContact(s.face, s.universal, q.contact, s.normalSign,
                                         s.universal.centerDistance.coefficient(0), u, w);
  return {c.meshing, wheelMeridian(s.wheel, c, offsetShift, slopeShift)};
}

// The hob's side: q and q-dot (Eq. 7) of the point G = P + t n on the normal line, with the axes
// at the motion phi. It depends on t and the axes only.
template <class T>
WheelFramePoint<T> hobSide(const PointEquations& q, const T& t, const AxisState<T>& axes) {
  const Vec3<T> G = q.g.p.cast<T>() + q.g.n.cast<T>() * t;
  return hobPointInWheelFrame(G, axes, q.s.machine, q.psiC);
}

// Eqs. 5, 6 and 11 from the two sides.
template <class T>
Eigen::Matrix<T, 4, 1> envelopeEquations(const WheelSide<T>& wheel, const WheelFramePoint<T>& h) {
  using std::sqrt;
  const WheelMeridian<T>& m = wheel.m;
  const T rho = sqrt(h.q.x() * h.q.x() + h.q.y() * h.q.y());
  Eigen::Matrix<T, 4, 1> F;
  F(0) = wheel.meshing;
  F(1) = rho - m.R;
  F(2) = h.q.z() - m.Z;
  F(3) = m.nR * (h.q.x() * h.qDot.x() + h.q.y() * h.qDot.y()) / rho + m.nZ * h.qDot.z();
  return F;
}

// The two sides, differentiated each in its own directions, carried into the N directions of the
// whole: the hob's from direction 0 on, the wheel's from direction `wheelFirst` on.
template <int N, int H, int W>
Eigen::Matrix<Dual<N>, 4, 1> joinedEquations(const WheelSide<Dual<W>>& wheel, const WheelFramePoint<Dual<H>>& h,
                                             int wheelFirst) {
  static_assert(H + W <= N, "the sides' directions must fit the whole's");
  const auto fromHob = [](const Dual<H>& x) { return embedded<N>(x, 0); };
  const auto fromWheel = [wheelFirst](const Dual<W>& x) { return embedded<N>(x, wheelFirst); };
  const WheelFramePoint<Dual<N>> hN{h.q.unaryExpr(fromHob), h.qDot.unaryExpr(fromHob)};
  const WheelSide<Dual<N>> wN{fromWheel(wheel.meshing), {fromWheel(wheel.m.R), fromWheel(wheel.m.Z),
                                                          fromWheel(wheel.m.nR), fromWheel(wheel.m.nZ)}};
  return envelopeEquations(wN, hN);
}

template <class T>
Eigen::Matrix<T, 4, 1> residual(const PointEquations& q, const T& t, const T& u, const T& w,
                                const AxisState<T>& axes) {
  return envelopeEquations(wheelSide(q, u, w), hobSide(q, t, axes));
}

struct Linearisation {
  Eigen::Vector4d F;
  Eigen::Matrix4d J;  // d F / d(t, phi, u, w)
};

// For Newton's method: four directions, the hob's side in (t, phi), phi entering through the axis
// values and rates, and the wheel's side in (u, w).
Linearisation linearise(const PointEquations& q, const EnvelopeGuess& v) {
  using D2 = Dual<2>;
  AxisState<D2> state;
  for (int i = 0; i < kAxisCount; ++i) {
    const PolynomialValue p = q.axes.axis[i].at(v.phi);
    state.value[i] = seeded<2>(p.value, Eigen::Vector2d(0, p.d1));
    state.rate[i] = seeded<2>(p.d1, Eigen::Vector2d(0, p.d2));
  }
  const Eigen::Matrix<Dual<4>, 4, 1> F = joinedEquations<4>(
      wheelSide<D2>(q, variable<2>(v.u, 0), variable<2>(v.w, 1)), hobSide<D2>(q, variable<2>(v.t, 0), state), 2);
  Linearisation L;
  for (int r = 0; r < 4; ++r) {
    L.F(r) = F(r).value();
    L.J.row(r) = F(r).derivatives().transpose();
  }
  return L;
}

// The residual alone, for a step with a Jacobian already factorised (inline: the solve's chord
// steps and the edge check's; not inlined, Tab. 1 takes 0.4 % more instructions, callgrind).
inline Eigen::Vector4d residualAt(const PointEquations& q, const EnvelopeGuess& v) {
  AxisState<double> state;
  for (int i = 0; i < kAxisCount; ++i) {
    const PolynomialValue p = q.axes.axis[i].at(v.phi);
    state.value[i] = p.value;
    state.rate[i] = p.d1;
  }
  return residual<double>(q, v.t, v.u, v.w, state);
}

// At the solution, with respect to everything: (t, u, w), the axis values and the axis rates.
struct FullLinearisation {
  Eigen::Matrix4d J;                                   // d F / d(t, phi, u, w)
  Eigen::Matrix<double, 4, kAxisCount> dValue, dRate;  // d F / d(axis values), d(axis rates)
  Eigen::Vector4d dOffset = Eigen::Vector4d::Zero();   // d F / d(offset value), with an offset
  Eigen::Vector4d dSlope = Eigen::Vector4d::Zero();    // d F / d(offset slope), with an offset
};

// The hob's side in t, the five axis values and the five rates (directions 0 to 10); the wheel's
// side in u, w and, with a wheel profile offset (W = 4), the shifts of the offset's value and
// slope (wheel_surface.h), from direction 11 on.
//
// The rates need no directions of their own: q-dot is dq/dphi = sum_i rate_i dq/d(value_i) (Eq. 7
// differentiated along the motion; machine_kinematics.h), so d q-dot / d rate_i = dq / d value_i,
// which the value directions give. The hob's side is differentiated in t and the values alone.
constexpr int kHobVars = 1 + 2 * kAxisCount;
constexpr int kHobDifferentiated = 1 + kAxisCount;

WheelFramePoint<Dual<kHobVars>> hobSideFully(const PointEquations& q, double t,
                                             const std::array<PolynomialValue, kAxisCount>& p) {
  constexpr int H = kHobDifferentiated;
  AxisState<Dual<H>> state;
  for (int i = 0; i < kAxisCount; ++i) {
    state.value[i] = variable<H>(p[i].value, 1 + i);
    state.rate[i] = Dual<H>(p[i].d1);
  }
  const WheelFramePoint<Dual<H>> h = hobSide<Dual<H>>(q, variable<H>(t, 0), state);
  WheelFramePoint<Dual<kHobVars>> full{h.q.unaryExpr([](const Dual<H>& x) { return embedded<kHobVars>(x, 0); }),
                                       h.qDot.unaryExpr([](const Dual<H>& x) { return embedded<kHobVars>(x, 0); })};
  for (int k = 0; k < 3; ++k)
    full.qDot(k).derivatives().template segment<kAxisCount>(H) = h.q(k).derivatives().template segment<kAxisCount>(1);
  return full;
}

template <int W>
FullLinearisation lineariseFully(const PointEquations& q, const EnvelopeGuess& v) {
  constexpr int H = kHobVars, N = H + W;
  std::array<PolynomialValue, kAxisCount> p;
  for (int i = 0; i < kAxisCount; ++i) p[i] = q.axes.axis[i].at(v.phi);
  const bool offset = W == 4;
  const Dual<W> offsetShift = offset ? variable<W>(0.0, 2) : Dual<W>(0.0);
  const Dual<W> slopeShift = offset ? variable<W>(0.0, 3) : Dual<W>(0.0);
  const Eigen::Matrix<Dual<N>, 4, 1> F = joinedEquations<N>(
      wheelSide<Dual<W>>(q, variable<W>(v.u, 0), variable<W>(v.w, 1), offsetShift, slopeShift),
      hobSideFully(q, v.t, p), H);
  FullLinearisation L;
  for (int r = 0; r < 4; ++r) {
    const auto& d = F(r).derivatives();
    if (offset) L.dOffset(r) = d(H + 2), L.dSlope(r) = d(H + 3);
    L.J(r, 0) = d(0);
    L.J(r, 2) = d(H);
    L.J(r, 3) = d(H + 1);
    double dphi = 0;
    for (int i = 0; i < kAxisCount; ++i) {
      L.dValue(r, i) = d(1 + i);
      L.dRate(r, i) = d(1 + kAxisCount + i);
      dphi += d(1 + i) * p[i].d1 + d(1 + kAxisCount + i) * p[i].d2;  // chain rule through phi
    }
    L.J(r, 1) = dphi;
  }
  return L;
}

// Eqs. 5-6's rows of a Jacobian d / d(t, phi, u, w), in the crossing's unknowns (t, u, w).
Eigen::Matrix3d crossingBlock(const Eigen::Matrix4d& J) {
  Eigen::Matrix3d B;
  B << J(0, 0), J(0, 2), J(0, 3), J(1, 0), J(1, 2), J(1, 3), J(2, 0), J(2, 2), J(2, 3);
  return B;
}

// Where the wheel at the fixed motion phi = v.phi crosses the normal line of g: Eqs. 5-6 alone,
// solved for (t, u, w) from v by Newton's method; nothing when it does not settle.
std::optional<EnvelopeGuess> crossingAt(const PointEquations& q, EnvelopeGuess v) {
  for (int it = 0; it < 30; ++it) {
    const Linearisation L = linearise(q, v);
    const Eigen::Vector3d step = crossingBlock(L.J).partialPivLu().solve(L.F.head<3>());
    if (!step.allFinite()) return std::nullopt;
    v.t -= step(0), v.u -= step(1), v.w -= step(2);
    if (step.cwiseAbs().maxCoeff() < 1e-13) return v;
  }
  return std::nullopt;
}

// The same crossing a motion step `dphi` from an envelope point v, with the Jacobian of Eqs. 5, 6,
// 11 there (`envelopeJacobian`, d / d(t, phi, u, w)): from the first-order prediction of the
// crossing, (t, u, w) moved by -J_tuw^-1 J_phi dphi, by chord steps with J_tuw (the residual alone,
// no new Jacobian; the same root, ended by the same 1e-13 as a Newton step). Where they do not
// contract by half a step (a Jacobian that does not hold so far), Newton's method from the moved
// point, as crossingAt.
//
// Only a crossing of the same sheet of the wheel's surface counts: one within kLocal times the
// first-order move of (t, u, w) from the predicted crossing. Newton's method from the moved point
// can land on another sheet: on seed 20261125's scenario 287 (a dressed wheel, the grid's tip
// corner) a crossing 42 mm along the normal line made a regular envelope point (t'' = -619
// mm/rad², the swept volume's) read as past the edge (docs/validation.md, the swept volume).
std::optional<double> crossingNear(const PointEquations& q, const EnvelopeGuess& v, double dphi,
                                   const Eigen::Matrix4d& envelopeJacobian) {
  constexpr double kLocal = 10;
  EnvelopeGuess moved = v;
  moved.phi += dphi;
  const Eigen::Matrix4d& E = envelopeJacobian;
  const Eigen::PartialPivLU<Eigen::Matrix3d> lu(crossingBlock(E));
  const Eigen::Vector3d predicted = lu.solve(E.block<3, 1>(0, 1) * dphi);
  if (!E.allFinite() || !predicted.allFinite()) {
    const std::optional<EnvelopeGuess> c = crossingAt(q, moved);
    return c ? std::optional<double>(c->t) : std::nullopt;
  }
  EnvelopeGuess c = moved;
  c.t -= predicted(0), c.u -= predicted(1), c.w -= predicted(2);
  const EnvelopeGuess expected = c;
  const auto local = [&](const EnvelopeGuess& x) {
    const double off = std::max({std::abs(x.t - expected.t), std::abs(x.u - expected.u), std::abs(x.w - expected.w)});
    return off <= kLocal * predicted.cwiseAbs().maxCoeff() + 1e-9;
  };
  double last = 0;
  for (int it = 0; it < 12; ++it) {
    const Eigen::Vector3d step = lu.solve(residualAt(q, c).head<3>());
    const double size = step.cwiseAbs().maxCoeff();
    if (!step.allFinite() || (it > 0 && !(size < 0.5 * last))) break;
    c.t -= step(0), c.u -= step(1), c.w -= step(2);
    if (size < 1e-13) return local(c) ? std::optional<double>(c.t) : std::nullopt;
    last = size;
  }
  const std::optional<EnvelopeGuess> n = crossingAt(q, moved);
  return n && local(*n) ? std::optional<double>(n->t) : std::nullopt;
}

// The second-order condition of the envelope for a dressed wheel. Along the motion the wheel's
// crossing t(phi) of the normal line touches the face from one side: for the conjugate wheel the
// envelope point is the crossing's maximum (Tab. 1: t'' about -69 mm/rad^2 at every point), and
// the face is ground where that holds. An offset that curves so sharply that a crossing a small
// motion step away lies beyond the envelope point has taken the wheel past the envelope's edge
// (the two sheets of the envelope meet there): the point found is no longer what the wheel grinds.
// `jacobianInverse`: the inverse Jacobian of Eqs. 5, 6, 11 the solve's last step was taken with.
bool pastEnvelopeEdge(const PointEquations& q, const EnvelopeGuess& v, double motionStep,
                      const Eigen::Matrix4d& jacobianInverse) {
  constexpr double kBeyond = 1e-9;  // mm: beyond the solver's noise
  // By an LU, not the closed-form 4 x 4 inverse of the solve's steps: a second use of that made the
  // compiler stop inlining it there (Tab. 1, which has no dressed wheel: 11.66 M instructions against
  // 11.43 M with the LU, callgrind).
  const Eigen::Matrix4d J = jacobianInverse.partialPivLu().inverse();
  for (double step : {-motionStep, motionStep}) {
    const std::optional<double> t = crossingNear(q, v, step, J);
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

namespace {

bool addSensitivities(const PointEquations& q, EnvelopePoint& e) {
  // Linearise once more at the solution (Eqs. 13-15): dt by each axis value and rate, by
  // the implicit-function theorem on the four envelope equations.
  const SharpeningSetup& setup = q.s;
  const EnvelopeGuess v{e.t, e.phi, e.u, e.w};
  const FullLinearisation S = setup.wheel.hasOffset() ? lineariseFully<4>(q, v) : lineariseFully<2>(q, v);
  const Eigen::Vector4d lambda = S.J.transpose().partialPivLu().solve(Eigen::Vector4d::UnitX());
  if (!lambda.allFinite()) return false;
  for (int i = 0; i < kAxisCount; ++i) {
    e.dtdValue[i] = -lambda.dot(S.dValue.col(i));
    e.dtdRate[i] = -lambda.dot(S.dRate.col(i));
  }
  if (setup.wheel.hasOffset()) {
    e.dtdOffset = -lambda.dot(S.dOffset);
    e.dtdOffsetSlope = -lambda.dot(S.dSlope);
    e.wheelRadius = wheelContact(setup.face, setup.universal, q.contact, setup.normalSign,
                                 setup.universal.centerDistance.coefficient(0), v.u, v.w).R();
  }
  return true;
}

}  // namespace

SetupRotations setupRotations(const SharpeningSetup& setup) {
  return {contactRotations(setup.universal), cosSin(setup.psiC())};
}

bool addSensitivities(const SharpeningSetup& setup, const SetupRotations& rotations, const AxisPolynomials& axes,
                      const GridPoint& point, EnvelopePoint& e) {
  return addSensitivities(PointEquations(setup, rotations, axes, point), e);
}

Eigen::Vector4d envelopeResidual(const SharpeningSetup& setup, const SetupRotations& rotations,
                                 const AxisPolynomials& axes, const GridPoint& point, const EnvelopePoint& at) {
  return residualAt(PointEquations(setup, rotations, axes, point), EnvelopeGuess{at.t, at.phi, at.u, at.w});
}

Eigen::Matrix4d envelopeJacobian(const SharpeningSetup& setup, const SetupRotations& rotations,
                                 const AxisPolynomials& axes, const GridPoint& point, const EnvelopePoint& at) {
  return linearise(PointEquations(setup, rotations, axes, point), EnvelopeGuess{at.t, at.phi, at.u, at.w}).J;
}

bool addSensitivities(const SharpeningSetup& setup, const AxisPolynomials& axes, const GridPoint& point,
                      EnvelopePoint& e) {
  return addSensitivities(setup, setupRotations(setup), axes, point, e);
}

namespace {

// The dressed wheel's fault, not the grid's nor the measurement's: its profile offset curves too
// sharply for the wheel to envelop the face at `point`. The field is the wheel's (the job names the
// measured profile instead when the case gives that, evaluation.cpp).
Error wildWheel(const SharpeningSetup& setup, const GridPoint& point) {
  // Past the edge of the conjugate wheel's envelope too: the setup's fault, not the wheel's.
  if (setup.wheelEdge && point.r >= setup.wheelEdge->turnRadius)
    return Error{kWheelEdgeField,
                 "Setup: a dressed wheel cannot be simulated near " + where(point) + ". " +
                     wheelEdgeText(*setup.wheelEdge) + " Until the edge is past the tip, use the conjugate wheel.",
                 ErrorCode::Unsolvable};
  return Error{kWildWheelField,
               "Wheel file: the dressed wheel's profile curves too sharply to grind the face near " + where(point) +
                   ": the wheel no longer envelops the face there (Eq. 11 holds past the envelope's edge). "
                   "Load a smoother wheel profile, or use the conjugate wheel.",
               ErrorCode::Unsolvable};
}

// Newton's method on Eqs. 5, 6, 11 from `guess`; with `startInverse`, the first step is a chord
// step with it (solveEnvelopePointNear).
Outcome<EnvelopePoint> solve(const SharpeningSetup& setup, const SetupRotations& rotations, const AxisPolynomials& axes,
                             const GridPoint& point, const EnvelopeGuess& guess, const Eigen::Matrix4d* startInverse,
                             Sensitivities sensitivities, const EnvelopeSolverOptions& o) {
  const auto fail = [&point, &setup] {
    return refuse("grid", "the ground face cannot be solved at the grid point " + where(point) +
                              ": the wheel does not envelop the tooth face there (Eq. 11 has no "
                              "solution). Check the axis polynomials and the grid" +
                              (setup.wheel.hasOffset() ? std::string(", and the wheel file.") : std::string(".")),
                  ErrorCode::Unsolvable);
  };
  const PointEquations q(setup, rotations, axes, point);
  EnvelopeGuess v = guess;
  const bool helical = setup.face.helical();
  const double motionLimit = helical ? o.helicalMotionStepLimit : o.straightMotionStepLimit;
  const double motionWeight = helical ? o.helicalMotionWeight : o.straightMotionWeight;
  const auto sizeOf = [motionWeight](const Eigen::Vector4d& step) {
    return std::abs(step(0)) + std::abs(step(2)) + (std::abs(step(1)) + std::abs(step(3))) * motionWeight;
  };
  // The inverse Jacobian the steps are taken with: a new one at each Newton step, kept for a chord step.
  Eigen::Matrix4d inverse = startInverse ? *startInverse : Eigen::Matrix4d::Zero();
  int jacobians = 0;
  const auto converged = [&](int it) -> Outcome<EnvelopePoint> {
    EnvelopePoint e;
    e.t = v.t;
    e.phi = v.phi;
    e.u = v.u;
    e.w = v.w;
    e.iterations = it;
    e.jacobians = jacobians;
    e.jacobianInverse = inverse;
    // With the Jacobian the last step was taken with: at an iterate within a step of the solution.
    if (setup.wheel.hasOffset() && pastEnvelopeEdge(q, v, o.edgeStep(helical), inverse))
      return wildWheel(setup, point);
    if (sensitivities == Sensitivities::Skip) return e;
    if (!addSensitivities(q, e)) return fail();
    return e;
  };
  double lastSize = 0;  // the last full step's size; 0 after a shortened one
  bool chord = startInverse != nullptr;  // the next step with `inverse` as it is
  for (int it = 1; it <= o.maxIterations; ++it) {
    Eigen::Vector4d step;
    if (chord) {
      step = inverse * residualAt(q, v);
    } else {
      const Linearisation L = linearise(q, v);
      if (!L.F.allFinite() || !L.J.allFinite()) break;
      // Eigen's closed-form 4 x 4 inverse (cofactors) is a fraction of the cost of a pivoted LU:
      // a Newton step needs the direction only to within rounding, the solution being where F = 0.
      inverse = L.J.inverse();
      ++jacobians;
      step = inverse * L.F;
    }
    if (!step.allFinite()) break;
    const double scale = std::max({std::abs(step(0)) / o.offsetStepLimit, std::abs(step(1)) / motionLimit,
                                   std::abs(step(2)) / o.lineStepLimit, std::abs(step(3)) / motionLimit, 1.0});
    step /= scale;
    v.t -= step(0);
    v.phi -= step(1);
    v.u -= step(2);
    v.w -= step(3);
    const double size = sizeOf(step);
    const bool full = scale == 1.0;
    if (full && size < o.stepTolerance) return converged(it);
    // Newton's method converging quadratically: the contraction theta = size / lastSize squares
    // from step to step, so the next step would be about size theta^2 (Deuflhard's estimate).
    // Where that is below the tolerance, the next step is taken with this step's inverse (a chord
    // step: the residual alone, no new Jacobian), and the solve ends when it is below the
    // tolerance, as a Newton step would be: the two differ by a share of the order of this step's size.
    chord = !chord && full && lastSize > 0 && size < lastSize &&
            size * (size / lastSize) * (size / lastSize) < o.stepTolerance;
    lastSize = full ? size : 0;
  }
  return fail();
}

}  // namespace

Outcome<EnvelopePoint> solveEnvelopePoint(const SharpeningSetup& setup, const SetupRotations& rotations,
                                          const AxisPolynomials& axes, const GridPoint& point,
                                          const EnvelopeGuess& guess, Sensitivities sensitivities,
                                          const EnvelopeSolverOptions& o) {
  return solve(setup, rotations, axes, point, guess, nullptr, sensitivities, o);
}

Outcome<EnvelopePoint> solveEnvelopePoint(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                          const GridPoint& point, const EnvelopeGuess& guess,
                                          Sensitivities sensitivities, const EnvelopeSolverOptions& o) {
  return solve(setup, setupRotations(setup), axes, point, guess, nullptr, sensitivities, o);
}

Outcome<EnvelopePoint> solveEnvelopePointNear(const SharpeningSetup& setup, const SetupRotations& rotations,
                                              const AxisPolynomials& axes, const GridPoint& point,
                                              const EnvelopePoint& near, Sensitivities sensitivities,
                                              const EnvelopeSolverOptions& o) {
  return solve(setup, rotations, axes, point, EnvelopeGuess{near.t, near.phi, near.u, near.w}, &near.jacobianInverse,
               sensitivities, o);
}

Outcome<EnvelopePoint> solveEnvelopePointNear(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                              const GridPoint& point, const EnvelopePoint& near,
                                              Sensitivities sensitivities, const EnvelopeSolverOptions& o) {
  return solveEnvelopePointNear(setup, setupRotations(setup), axes, point, near, sensitivities, o);
}

}  // namespace hobsharp
