#include "ground_face.h"

#include <algorithm>
#include <optional>

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
      auto e = solveEnvelopePoint(setup, axes, g, guess, sensitivities, options);
      if (!e) return e.error();
      last = *e;
      f.points.push_back(g);
      f.envelope.push_back(*e);
    }
  }
  auto contactW = contactAt(setup, grid.rMean());
  if (!contactW) return contactW.error();
  f.meanPoint = gridPoint(setup, grid.rMean(), grid.xMean());
  auto e = solveEnvelopePoint(setup, axes, f.meanPoint, nominalGuess(f.meanPoint, *contactW), sensitivities,
                              options);
  if (!e) return e.error();
  f.meanEnvelope = *e;
  return f;
}

MotionRange motionRange(const GroundFace& face) {
  MotionRange m;
  for (const EnvelopePoint& e : face.envelope) m.min = std::min(m.min, e.phi), m.max = std::max(m.max, e.phi);
  return m;
}

}  // namespace hobsharp
