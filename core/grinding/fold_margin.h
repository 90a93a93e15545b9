// How near each point of a ground face is to a fold of the envelope: the point where its solution
// (Eqs. 5, 6, 11) meets another one and both vanish, so the wheel stops enveloping the face there
// and part of the face stays unground. At a fold the Jacobian d(Eqs. 5, 6, 11) / d(t, phi, u, w)
// is singular; the margin compares its determinant with the change that other axes would make of
// it, each point moved to first order (one Newton step from the face's solution).
#pragma once

#include <limits>
#include <vector>

#include "axis_polynomials.h"
#include "ground_face.h"
#include "sharpening_setup.h"

namespace hobsharp {

struct FoldMargin {
  // The smallest over the points of |det J| / |(det J with each of `moved`) - det J| (the norm over
  // the moved axes): below 1, the determinant may reach 0 between the axes and the moved ones, to
  // first order in the change.
  double margin = std::numeric_limits<double>::infinity();
  int at = -1;  // the point where it is smallest (face.points' index), -1 without one
};

// `face` was simulated with `axes` and `setup`; each of `moved` is the axes changed in one
// direction, by the size of change to be checked (the directions orthogonal: their worst
// combination of that size changes det J by the norm of their changes, to first order).
FoldMargin foldMargin(const GroundFace& face, const SharpeningSetup& setup, const AxisPolynomials& axes,
                      const std::vector<AxisPolynomials>& moved);

}  // namespace hobsharp
