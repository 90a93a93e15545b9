#include "wheel_offset_sensitivity.h"

#include "topography.h"

namespace hobsharp {

WheelOffsetSensitivity wheelOffsetSensitivity(const GroundFace& face, const WheelSurface& wheel) {
  if (!wheel.offset) return {};
  return wheelOffsetSensitivity(face, *wheel.offset);
}

WheelOffsetSensitivity wheelOffsetSensitivity(const GroundFace& face, const CubicSpline& spline) {
  WheelOffsetSensitivity S;
  const int knots = static_cast<int>(spline.size()), n = face.size();  // grid points, or probe points
  auto row = [&](const EnvelopePoint& e) {
    // delta = sum_k y_k B_k(R): dt/dy_k = dt/d(delta) B_k(R) + dt/d(delta') B_k'(R); mm per mm is
    // µm per µm.
    const CubicSpline::Basis b = spline.basis(e.wheelRadius);
    return Eigen::RowVectorXd(e.dtdOffset * b.B.transpose() + e.dtdOffsetSlope * b.dB.transpose());
  };
  S.normal.resize(n, knots);
  for (int p = 0; p < n; ++p) S.normal.row(p) = row(face.envelope[p]);
  S.thickness = row(face.meanEnvelope) * thicknessFactor(face);
  return S;
}

}  // namespace hobsharp
