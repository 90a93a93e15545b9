// What DIN 3968 checks on one cutting (rake) face, from its normal deviations on the grid
// (README, "Rake-face inspection", where each is defined):
//   radial alignment  - per axial line, the least-squares straight line of the deviation over the
//                       radius, its rise from root to tip; the one of largest magnitude, signed;
//   cutting-face form - per axial line, the spread (largest minus smallest) of the deviation
//                       about that line; the largest;
//   gash lead         - per radial line (helical gash), the least-squares slope of the deviation
//                       along the hob axis, per 100 mm of hob length; the one of largest magnitude, signed.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace hobsharp {

struct FaceChecks {
  double cuttingFaceForm = 0;      // µm, >= 0
  double radialAlignment = 0;      // µm, tip minus root of the fitted line; plus = more material at the tip
  std::optional<double> gashLead;  // µm per 100 mm along the hob axis; helical gash only
};

// `normal` in µm, rows at radii r (mm, root to tip), columns at axial positions x (mm).
FaceChecks checkFace(const Eigen::MatrixXd& normal, const std::vector<double>& r, const std::vector<double>& x,
                     bool helical);

}  // namespace hobsharp
