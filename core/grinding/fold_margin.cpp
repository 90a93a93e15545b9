#include "fold_margin.h"

#include <cmath>

#include <Eigen/LU>

#include "envelope.h"

namespace hobsharp {

FoldMargin foldMargin(const GroundFace& face, const SharpeningSetup& setup, const AxisPolynomials& axes,
                      const std::vector<AxisPolynomials>& moved) {
  FoldMargin out;
  if (moved.empty()) return out;
  const SetupRotations rotations = setupRotations(setup);
  for (int i = 0; i < face.size(); ++i) {
    const GridPoint& point = face.points[static_cast<size_t>(i)];
    const EnvelopePoint& e = face.envelope[static_cast<size_t>(i)];
    const Eigen::Matrix4d J = envelopeJacobian(setup, rotations, axes, point, e);
    const double det = J.determinant();
    const Eigen::Matrix4d inverse = J.inverse();
    double squares = 0;
    for (const AxisPolynomials& a : moved) {
      // The point moved to first order: one Newton step from the solution with the moved axes. (The
      // residual named: `inverse * envelopeResidual(...)` in one expression took a wrong step in
      // Emscripten 3.1.6's build, the same one for every residual; the native build's was right.)
      const Eigen::Vector4d residual = envelopeResidual(setup, rotations, a, point, e);
      const Eigen::Vector4d step = inverse * residual;
      EnvelopePoint m = e;
      m.t -= step(0);
      m.phi -= step(1);
      m.u -= step(2);
      m.w -= step(3);
      const double change = envelopeJacobian(setup, rotations, a, point, m).determinant() - det;
      squares += change * change;
    }
    if (!std::isfinite(squares) || !std::isfinite(det)) return FoldMargin{0.0, i};  // cannot say: at a fold
    if (squares > 0 && std::abs(det) < out.margin * std::sqrt(squares)) out = FoldMargin{std::abs(det) / std::sqrt(squares), i};
  }
  return out;
}

}  // namespace hobsharp
