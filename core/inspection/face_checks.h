// What DIN 3968 checks on one cutting (rake) face, from its normal deviations on the grid, each as
// its measuring method reads it (docs/inspection.md, where each is derived):
//   radial alignment  - per axial line, an indicator run along the nominal face line in the plane
//                       square to the hob axis, zeroed on the face at the tip (the line turned about
//                       the hob axis through the face's tip point) and run down to the root: the
//                       reading of largest magnitude, signed; the largest over the axial lines;
//   rake error        - per axial line, the least-squares straight line of the face across the nominal
//                       line: how far it lies moved into the tooth at the line's foot (mm; a turn about
//                       the hob axis moves the foot by nothing), and the rake angle at the tip that
//                       changes by; the mean over the axial lines; plus = hook;
//   cutting-face form - per axial line, the spread (largest minus smallest) of the normal deviation
//                       about its least-squares straight line over the radius; the largest;
//   gash lead         - per radial line (helical gash), the least-squares slope of the deviation
//                       along the hob axis, per 100 mm of hob length; the one of largest magnitude, signed.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "face_lines.h"

namespace hobsharp {

struct FaceChecks {
  double cuttingFaceForm = 0;      // µm, >= 0
  double radialAlignment = 0;      // µm, the indicator's reading below the tip; plus = excess material
  double rakeOffset = 0;           // mm, the face line moved into the tooth, parallel; plus = hook
  double rakeAngle = 0;            // rad, at the tip radius; plus = hook (positive rake error)
  std::optional<double> gashLead;  // µm per 100 mm along the hob axis; helical gash only
};

// `normal` in µm on the grid of `lines` (rows root to tip, the last row the indicator's zero).
FaceChecks checkFace(const Eigen::MatrixXd& normal, const FaceLines& lines, bool helical);

// The face a rake error alone leaves (µm, normal deviations on the grid of `lines`): every face line
// moved parallel to itself, `rakeOffset` mm into the tooth (plus = hook, material taken off).
// checkFace() reads it back as that rake error.
Eigen::MatrixXd rakeErrorFace(const FaceLines& lines, double rakeOffset);

}  // namespace hobsharp
