// The rake face as DIN 3968's indicator sees it (docs/inspection.md, "Radial alignment"): in the
// plane square to the hob axis at an axial grid position the nominal face is a straight line, the
// generating line of Eq. 1 at the rake offset e from the axis (Eq. 2 at fixed beta; for a straight
// gash at fixed x). An indicator run along that line reads the face's offset across it, in that plane.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "face_grid.h"
#include "sharpening_setup.h"

namespace hobsharp {

struct FaceLines {
  std::vector<double> r, x;       // the grid, mm: rows root to tip, columns along the hob
  std::vector<double> alongLine;  // per row: the distance along the line from its foot (the point
                                  // nearest the hob axis), sqrt(r^2 - e^2), mm
  // Per grid point: n . t, n the outward unit normal, t the unit normal of the line within the
  // transverse plane (turned to n). A normal deviation divided by it is the offset across the line.
  Eigen::MatrixXd acrossLine;

  // The lines of a hob's nominal face on the grid.
  static FaceLines of(const SharpeningSetup& setup, const FaceGrid& grid);
  // A zero-rake face whose normal lies in the transverse plane (a straight gash): for tests and for
  // faces given without a setup.
  static FaceLines radial(const std::vector<double>& r, const std::vector<double>& x);
};

}  // namespace hobsharp
