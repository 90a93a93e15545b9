// The coefficient changes no measurement can show, known from the geometry before any data
// (docs/conventions.md §What the grid can see), and the directions left to identify:
//   - helical gash: X a_k against A a_k of the same degree (an axial shift of a helicoid is a
//     turn of it), exactly, for every k;
//   - straight gash: X, Y and B, whose first-order effects on the plane face are zero (X and Y
//     move the wheel within the face plane, B turns it about the face normal);
//   - locked axes and coefficients, which are not changed at all.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "coefficient.h"
#include "correction_options.h"
#include "tooth_face.h"
#include "unobservable.h"

namespace hobsharp {

struct IdentifiableSpace {
  std::vector<Coefficient> coefficients;  // the free (not locked) coefficients, axis by axis
  // Each free coefficient's machine step (coefficientStep): the unit of the scaled coordinates
  // z_j = a_j / step_j, in which lengths are machine steps at the end of the motion range.
  Eigen::VectorXd step;
  // q x m, orthonormal in z: the directions left to identify (the complement of the null space).
  Eigen::MatrixXd basis;
  // What is left out, in words, by degree then axis.
  std::vector<UnobservableCombination> structural;
};

IdentifiableSpace identifiableSpace(const ToothFace& face, int degree, const CorrectionOptions& options,
                                    double motionRange);

}  // namespace hobsharp
