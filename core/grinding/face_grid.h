// The measuring grid on the nominal tooth face (docs/conventions.md §Grid): rows run radially from root to
// tip, columns axially from xMin to xMax, both evenly spaced with the ends included.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sharpening_setup.h"

namespace hobsharp {

struct FaceGrid {
  std::vector<double> r;  // radius from the hob axis, mm
  std::vector<double> x;  // axial position, mm

  static FaceGrid even(int radial, int axial, double rMin, double rMax, double xMin, double xMax);
  int rows() const { return static_cast<int>(r.size()); }
  int cols() const { return static_cast<int>(x.size()); }
  int size() const { return rows() * cols(); }
  double rMean() const { return 0.5 * (r.front() + r.back()); }
  double xMean() const { return 0.5 * (x.front() + x.back()); }
};

// A point of the nominal face with its outward unit normal.
struct GridPoint {
  double r = 0, x = 0;  // radius and axial position, mm
  double u = 0, w = 0;  // face coordinates (Eq. 2)
  Eigen::Vector3d p;    // position in S_1, mm
  Eigen::Vector3d n;    // outward unit normal in S_1
  // Cosine between the normal and the tangent of the circle about the hob axis through p;
  // a normal deviation divided by it is the displacement along that circle.
  double cosCircle = 1;
};

GridPoint gridPoint(const SharpeningSetup& setup, double r, double x);

}  // namespace hobsharp
