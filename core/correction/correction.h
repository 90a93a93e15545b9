// The correction step of Eq. 17: the changes of the chosen polynomial coefficients that cancel a
// measured topography in the least-squares sense, by a truncated SVD of the column-scaled
// sensitivity matrix. The thickness error at the mean point is one more equation (Eq. 16).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "ground_face.h"
#include "outcome.h"
#include "sensitivity_matrix.h"
#include "topography.h"

namespace hobsharp {

// How the correction step treats the sensitivity matrix. The ratios are dimensionless.
struct CorrectionOptions {
  // Singular values below truncation * (largest) are dropped; the combinations they belong to
  // are reported as unobservable.
  double truncation = 1e-6;
  // With unit columns, one coefficient of size |data| makes a topography of size |data|. A singular
  // direction whose step would exceed amplification * |data| is left out: the data there is a shape
  // the axes make only with wild coefficients (a second-degree radial shape, say).
  double amplification = 1;
  // Before scaling, a column whose norm is below negligible * (largest) is unobservable on its own
  // (moving along a straight gash, say), so that scaling does not blow noise up to unit norm.
  double negligible = 1e-9;
  // An unobservable combination is described by the coefficients whose share of its (scaled)
  // direction is at least listedShare * (the largest share); the others are left out of the words.
  double listedShare = 1e-3;
  // The verdict is "correctable" when the predicted sum of squares is at most
  // correctableShare * (the measured one).
  double correctableShare = 1e-3;
  // Coefficients left as they are. A locked axis is all of its coefficients.
  std::vector<Coefficient> locked;
  std::vector<Axis> lockedAxes;
};

// Coefficients whose effects on the face cancel: the combination sum(amount_i * coefficient_i),
// in each coefficient's unit, changes nothing the grid can see.
struct UnobservableCombination {
  std::vector<Coefficient> coefficients;
  std::vector<double> amounts;
  std::string description;
};

struct Correction {
  AxisPolynomials axes;                  // the axes that were run plus the correction (Tab. 2 right)
  std::vector<Coefficient> coefficients; // the free coefficients
  Eigen::VectorXd change;                // their changes, in their units
  Topography before;                     // the measured topography
  Topography after;                      // the predicted residual
  Eigen::VectorXd singularValues;        // of the scaled matrix, largest first
  int rank = 0;                          // directions used in the step
  int amplifyingDropped = 0;             // directions above the truncation left out (see options)
  std::vector<UnobservableCombination> unobservable;
  // The share of the sum of squares that no coefficient change can produce, 0..1.
  double uncorrectableShare = 0;
  std::string verdict;                   // one sentence for the engineer
};

Outcome<Correction> correctionStep(const GroundFace& run, const AxisPolynomials& runAxes,
                                   const Eigen::MatrixXd& measured, const CorrectionOptions& options);

}  // namespace hobsharp
