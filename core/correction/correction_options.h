// How the correction treats a measured face: the method, the probe noise and the machine's
// resolution (docs/case-format.md, correction.*), the solver, and the locks.
#pragma once

#include <algorithm>
#include <vector>

#include "coefficient.h"
#include "least_squares_options.h"
#include "machine_resolution.h"

namespace hobsharp {

enum class CorrectionMethod {
  Nonlinear,  // identify the machine error by nonlinear least squares, run nominal - error
  Linear,     // the paper's single step of Eq. 17 by truncated SVD
};

// How the identified machine error is put to the engineer per axis (identified_axes.h): which
// axes the face tells apart, and in what proportion it mixes the others. Each threshold tests one
// thing; all are judged over every direction the face shows (not only those the correction takes).
struct AxisReadingOptions {
  // Tests whether the face tells an axis from a mix of the others: its error is read on its own only
  // while the multiple correlation of its curve with the other axes' curves stays below this over
  // the whole motion range (0.9: knowing the others exactly would narrow it by less than 2.3 times).
  double maxCorrelation = 0.9;
  // Tests whether the figure is sharp enough to tell which axis is off: an axis is read on its own
  // only when its standard uncertainty at the probe noise is at most this many machine steps
  // (correction.resolution: 0.1 µm on X, Y, Z and 0.0001 deg on A, B by default) anywhere on the range.
  double maxUncertaintySteps = 50;
  // Tests which axes the face confuses with which: two axes not read on their own are one
  // combination when their curves' correlation reaches this somewhere on the range (or when a
  // combination of theirs has no effect on the face at all).
  double partnerCorrelation = 0.5;
  // Tests that "alike" is true before a proportion is given: the other axes of a combination must
  // reproduce at least this share of the face of +1 µm (or µrad) on the axis it is read as.
  double alikeShare = 0.7;
};

struct CorrectionOptions {
  CorrectionMethod method = CorrectionMethod::Nonlinear;
  // The probe's standard deviation sigma, µm. A direction of the face the axes can make is
  // identified only when the measured face holds more of it than significance * sigma, so the
  // correction does not fit noise (docs/method.md, "Correction").
  double probeNoise = 0.5;
  double significance = 3;
  // A direction of the face is left out when the step it needs, in machine steps, exceeds
  // spanAmplification times the step the strongest direction needs to make the whole measured
  // face: the measurement there is a shape the axes make only with wild moves (a second-degree
  // shape along the radius). The measured face is the whole machine error's, in every pass.
  double spanAmplification = 10;
  MachineResolution resolution;
  LeastSquaresOptions solver;

  // The linear method (and the sentences of both):
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
  // correctableShare * (the measured one), or within the probe noise.
  double correctableShare = 1e-3;
  // Coefficients left as they are. A locked axis is all of its coefficients.
  std::vector<Coefficient> locked;
  std::vector<Axis> lockedAxes;
  AxisReadingOptions reading;
  // Solve for the axes and a wheel-profile offset together (`correction.wheel`, wheel_correction.h).
  bool wheel = false;
};

inline bool isLocked(const Coefficient& c, const CorrectionOptions& o) {
  return std::find(o.lockedAxes.begin(), o.lockedAxes.end(), c.axis) != o.lockedAxes.end() ||
         std::find(o.locked.begin(), o.locked.end(), c) != o.locked.end();
}

// The coefficients of `degree` the correction seeks: all but the locked ones (one equation per
// measured value each needs; a measurement of fewer values is refused).
inline int freeCoefficients(int degree, const CorrectionOptions& o) {
  const std::vector<Coefficient> all = allCoefficients(degree);
  return static_cast<int>(std::count_if(all.begin(), all.end(), [&](const Coefficient& k) { return !isLocked(k, o); }));
}

}  // namespace hobsharp
