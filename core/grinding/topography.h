// The deviation topography of the ground face (docs/conventions.md §Sign, §Thickness), in µm:
//   normal   - signed distance from the nominal face along its outward normal, plus = excess material;
//   circular - the same deviation measured along the circle about the hob axis, as an angle
//              expressed in µm of arc at the mean radius (so a rigid turn of the face is uniform);
//   thickness - the circular flank thickness error at the mean point.
#pragma once

#include <Eigen/Core>

#include "ground_face.h"

namespace hobsharp {

struct Topography {
  FaceGrid grid;             // at probe points: the grid whose mean point gives the thickness
  Eigen::MatrixXd normal;    // rows root to tip, columns xMin to xMax, µm
  Eigen::MatrixXd circular;  // µm of arc at the mean radius
  double thickness = 0;      // µm
  double sse = 0;            // sum of squares of `normal`, µm^2 (the paper's figure; grows with the grid)
  double max = 0;            // largest |normal|, µm
  double rms = 0;            // root mean square of `normal`, µm: comparable between grids
  double peakToValley = 0;   // largest minus smallest `normal`, µm
};

// The factor that turns a normal deviation at grid point (i, j) into the circular view.
double circularFactor(const GroundFace& face, int i, int j);
// The factor that turns a normal deviation at the mean point into the thickness error.
double thicknessFactor(const GroundFace& face);

Topography topographyOf(const GroundFace& face);

// A topography from normal deviations given on the grid of `face` (a measured one, or a residual).
// The thickness at the mean point is interpolated bilinearly from the grid. On a face at probe
// points `normal` is one column, a value per point, and the thickness is the deviation of the
// point nearest the mean point (nothing interpolated).
Topography topographyFromNormal(const GroundFace& face, const Eigen::MatrixXd& normal);

// The thickness error topographyFromNormal reads from those normal deviations (µm): linear in
// them, so the same reading of a sensitivity column is the thickness's sensitivity.
double thicknessFromNormal(const GroundFace& face, const Eigen::MatrixXd& normal);

}  // namespace hobsharp
