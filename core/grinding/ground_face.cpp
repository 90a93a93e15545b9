#include "ground_face.h"

#include <algorithm>
#include <optional>
#include <string>

#include "wheel_profile.h"

namespace hobsharp {
namespace {

// w*(u) of the wheel's contact line at radius r: where the nominal screw motion grinds that radius.
Outcome<double> contactAt(const SharpeningSetup& s, double r) {
  return contactCoordinate(s.face, s.universal, s.normalSign, s.face.uAtRadius(r));
}

}  // namespace

Outcome<GroundFace> simulateGroundFace(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                       const FaceGrid& grid, Sensitivities sensitivities,
                                       const EnvelopeSolverOptions& options) {
  GroundFace f;
  f.gash = setup.face.gash;
  f.grid = grid;
  f.points.reserve(grid.size());
  f.envelope.reserve(grid.size());
  const SetupRotations rotations = setupRotations(setup);
  for (int i = 0; i < grid.rows(); ++i) {
    auto contactW = contactAt(setup, grid.r[i]);
    if (!contactW) return contactW.error();
    // Each solve starts from its neighbour's solution, moved along the nominal screw motion
    // (phi + w = const), or from the nominal motion at the start of a row.
    std::optional<EnvelopePoint> last;
    for (int j = 0; j < grid.cols(); ++j) {
      const GridPoint g = gridPoint(setup, grid.r[i], grid.x[j]);
      const EnvelopeGuess guess =
          last ? EnvelopeGuess{last->t, last->phi - (g.w - f.points.back().w), last->u, last->w}
               : nominalGuess(g, *contactW);
      auto e = solveEnvelopePoint(setup, rotations, axes, g, guess, sensitivities, options);
      if (!e) return e.error();
      last = *e;
      f.points.push_back(g);
      f.envelope.push_back(*e);
    }
  }
  auto contactW = contactAt(setup, grid.rMean());
  if (!contactW) return contactW.error();
  f.meanPoint = gridPoint(setup, grid.rMean(), grid.xMean());
  auto e = solveEnvelopePoint(setup, rotations, axes, f.meanPoint, nominalGuess(f.meanPoint, *contactW),
                              sensitivities, options);
  if (!e) return e.error();
  f.meanEnvelope = *e;
  return f;
}

Outcome<GroundFace> simulateGroundFace(const SharpeningSetup& setup, const AxisPolynomials& axes,
                                       const ProbePoints& probes, const FaceGrid& grid, Sensitivities sensitivities,
                                       const EnvelopeSolverOptions& options) {
  GroundFace f;
  f.gash = setup.face.gash;
  f.grid = grid;
  f.probes = probes;
  f.points.reserve(probes.size());
  f.envelope.reserve(probes.size());
  const SetupRotations rotations = setupRotations(setup);
  double lastR = 0, contactW = 0;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const GridPoint g = gridPoint(setup, probes[k].r, probes[k].x);
    // A machine probes along lines: a point at the previous one's radius starts from its solution
    // moved along the nominal screw motion (as along a grid row), any other from the nominal motion.
    const bool sameLine = k > 0 && probes[k].r == lastR;
    if (!sameLine) {
      auto w = contactAt(setup, probes[k].r);
      if (!w) return refusePoint("measuredPoints", k, w.error().message, w.error().code);
      contactW = *w;
    }
    const EnvelopeGuess guess =
        sameLine ? EnvelopeGuess{f.envelope.back().t, f.envelope.back().phi - (g.w - f.points.back().w),
                                 f.envelope.back().u, f.envelope.back().w}
                 : nominalGuess(g, contactW);
    auto e = solveEnvelopePoint(setup, rotations, axes, g, guess, sensitivities, options);
    if (!e) {
      // The wheel's fault or the setup's, not the point's.
      if (e.error().field == kWildWheelField || e.error().field == kWheelEdgeField) return e.error();
      std::string why = e.error().message;
      const std::string gridWords = "grid: the ground face cannot be solved at the grid point";
      if (why.rfind(gridWords, 0) == 0) why = "the ground face cannot be solved at the point" + why.substr(gridWords.size());
      return refusePoint("measuredPoints", k, why, e.error().code);
    }
    lastR = probes[k].r;
    f.points.push_back(g);
    f.envelope.push_back(*e);
  }
  auto meanW = contactAt(setup, grid.rMean());
  if (!meanW) return meanW.error();
  f.meanPoint = gridPoint(setup, grid.rMean(), grid.xMean());
  auto e = solveEnvelopePoint(setup, rotations, axes, f.meanPoint, nominalGuess(f.meanPoint, *meanW), sensitivities,
                              options);
  if (!e) return e.error();
  f.meanEnvelope = *e;
  return f;
}

Outcome<GroundFace> simulateGroundFaceLike(const GroundFace& like, const SharpeningSetup& setup,
                                           const AxisPolynomials& axes, Sensitivities sensitivities, FaceStart start) {
  const auto fresh = [&] {
    return like.atProbes() ? simulateGroundFace(setup, axes, like.probes, like.grid, sensitivities)
                           : simulateGroundFace(setup, axes, like.grid, sensitivities);
  };
  if (!like.atProbes() && start == FaceStart::AsSimulated) return fresh();
  // Each solve starts from `like`'s solution at the same point, moved to first order
  // (solveEnvelopePointNear): axes that differ by a correction move the envelope point little, so
  // Newton's method needs a few steps, and no contact line is solved for.
  GroundFace f;
  f.gash = like.gash;
  f.grid = like.grid;
  f.probes = like.probes;
  f.points = like.points;
  f.envelope.reserve(like.envelope.size());
  const SetupRotations rotations = setupRotations(setup);
  for (std::size_t k = 0; k < like.points.size(); ++k) {
    auto e = solveEnvelopePointNear(setup, rotations, axes, like.points[k], like.envelope[k], sensitivities);
    if (!e) return fresh();  // too far for the warm start: from the nominal motion, as the first simulation did
    f.envelope.push_back(*e);
  }
  f.meanPoint = like.meanPoint;
  auto e = solveEnvelopePointNear(setup, rotations, axes, f.meanPoint, like.meanEnvelope, sensitivities);
  if (!e) return fresh();
  f.meanEnvelope = *e;
  return f;
}

MotionRange motionRange(const GroundFace& face) {
  MotionRange m;
  for (const EnvelopePoint& e : face.envelope) m.min = std::min(m.min, e.phi), m.max = std::max(m.max, e.phi);
  return m;
}

Outcome<void> addSensitivities(GroundFace& face, const SharpeningSetup& setup, const AxisPolynomials& axes) {
  const SetupRotations rotations = setupRotations(setup);
  for (std::size_t k = 0; k < face.envelope.size(); ++k)
    if (!addSensitivities(setup, rotations, axes, face.points[k], face.envelope[k]))
    {
      const std::string why = "the ground face's sensitivities cannot be formed at a point: the envelope equations are singular there.";
      return face.atProbes() ? refusePoint("measuredPoints", k, why, ErrorCode::Unsolvable) : refuse("grid", why, ErrorCode::Unsolvable);
    }
  if (!addSensitivities(setup, rotations, axes, face.meanPoint, face.meanEnvelope))
    return refuse("grid", "the ground face's sensitivities cannot be formed at the grid's mean point.", ErrorCode::Unsolvable);
  return success();
}

}  // namespace hobsharp
