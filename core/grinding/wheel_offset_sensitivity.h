// The face's sensitivity to the wheel's profile offset (wheel_surface.h): the change of the normal
// deviation at every grid point, and of the thickness at the mean point, per µm of each knot value
// of the offset's spline, by the implicit function theorem on the solved envelope (as Eqs. 13-15
// for the axes).
#pragma once

#include <Eigen/Core>

#include "ground_face.h"
#include "wheel_surface.h"

namespace hobsharp {

struct WheelOffsetSensitivity {
  Eigen::MatrixXd normal;        // (rows * cols) x knots, row-major grid order, µm per µm
  Eigen::RowVectorXd thickness;  // 1 x knots, µm per µm
};

// `face` simulated with Sensitivities::Compute for a setup whose wheel has an offset, `wheel`
// that wheel. Empty matrices for a wheel without an offset.
WheelOffsetSensitivity wheelOffsetSensitivity(const GroundFace& face, const WheelSurface& wheel);

// The same per knot value of `spline`, one of the splines whose sum is the wheel's offset
// (WheelSurface::offset or ::added): delta is linear in each, so the columns are its cardinal
// functions' (`face` as above, simulated for that wheel).
WheelOffsetSensitivity wheelOffsetSensitivity(const GroundFace& face, const CubicSpline& spline);

}  // namespace hobsharp
