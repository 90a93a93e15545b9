#include "sensitivity_matrix.h"

#include <algorithm>
#include <cmath>

#include "topography.h"

namespace hobsharp {

Eigen::MatrixXd SensitivityMatrix::topography(int j) const {
  Eigen::MatrixXd t(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < cols; ++k) t(i, k) = normal(i * cols + k, j);
  return t;
}

SensitivityMatrix sensitivityMatrix(const GroundFace& face, const std::vector<Coefficient>& coefficients) {
  constexpr double kMicrometresPerMm = 1000.0;
  SensitivityMatrix S;
  S.coefficients = coefficients;
  S.rows = face.grid.rows();
  S.cols = face.grid.cols();
  const int q = static_cast<int>(coefficients.size());
  S.normal.resize(face.grid.size(), q);
  S.thickness.resize(q);
  S.motionRange = 0;
  for (const EnvelopePoint& e : face.envelope) S.motionRange = std::max(S.motionRange, std::abs(e.phi));
  if (S.motionRange == 0) S.motionRange = 1;
  for (int j = 0; j < q; ++j) {
    const Coefficient& c = coefficients[j];
    for (int p = 0; p < face.grid.size(); ++p)
      S.normal(p, j) = kMicrometresPerMm * face.envelope[p].sensitivity(c.axis, c.degree);
    S.thickness(j) =
        kMicrometresPerMm * face.meanEnvelope.sensitivity(c.axis, c.degree) * thicknessFactor(face);
  }
  return S;
}

}  // namespace hobsharp
