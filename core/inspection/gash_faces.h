// One measured topography per gash (`inspection.gashTopographies`, docs/inspection.md):
// each gash's mean deviation at the pitch radius, which gives the spacing checks and the indexing
// correction, and each gash's own face checks; the hob's face checks are the worst over its gashes.
//   deviation at the pitch radius - the least-squares straight line over the radius through the
//       deviations averaged along the gash (the mean of every axial line's fitted line), at r_p.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "face_checks.h"

namespace hobsharp {

struct GashFaces {
  std::vector<double> deviations;  // µm at the pitch radius, gash 1 .. z
  std::vector<FaceChecks> faces;   // gash 1 .. z
  FaceChecks worst;                // the largest form; alignment, rake error and lead of largest magnitude, signed
};

// `normal` in µm, rows at radii r (mm, root to tip).
double deviationAtRadius(const Eigen::MatrixXd& normal, const std::vector<double>& r, double radius);

GashFaces inspectGashFaces(const std::vector<Eigen::MatrixXd>& gashes, const FaceLines& lines, bool helical,
                           double pitchRadius);

}  // namespace hobsharp
