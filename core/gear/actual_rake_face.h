// The actual rake face: the nominal face (Eq. 2) moved along its outward unit normal by the
// deviation (docs/conventions.md §Sign: plus = excess material, the face stands further out of the
// tooth), between the grid's points by natural cubic splines: along the radius on every axial
// line, then along the hob axis through those values.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "cubic_spline.h"
#include "tooth_face.h"

namespace hobsharp {

class ActualRakeFace {
 public:
  // `deviation` in µm, rows at the radii r (mm, root to tip), columns at the axial positions x (mm);
  // at least 2 of each. `normalSign` orients r_u x r_w out of the tooth (docs/conventions.md §Sign).
  ActualRakeFace(const ToothFace& face, double normalSign, const std::vector<double>& r, const std::vector<double>& x,
                 const Eigen::MatrixXd& deviation);

  const ToothFace& face() const { return face_; }
  // The deviation at the nominal face point (r, x), mm.
  double deviation(double r, double x) const;
  // The actual face point over the nominal point (r, x), hob frame S_1, mm.
  Eigen::Vector3d point(double r, double x) const;
  // The polar angle about the hob axis of the nominal face at radius R and axial position X, rad.
  double nominalAngle(double R, double X) const;
  // +1 or -1: the sense of the polar angle in which the outward normal points (the cutting direction).
  double cuttingSense() const { return cuttingSense_; }

 private:
  ToothFace face_;
  double normalSign_ = 1;
  double cuttingSense_ = 1;
  std::vector<CubicSpline> columns_;  // per axial line, the deviation over the radius, mm
  CubicSpline axial_;                 // the knots along the hob axis (for its basis)
};

}  // namespace hobsharp
