#include "sensitivity_matrix.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "topography.h"
#include "units.h"

namespace hobsharp {

Eigen::MatrixXd SensitivityMatrix::topography(int j) const {
  Eigen::MatrixXd t(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < cols; ++k) t(i, k) = normal(i * cols + k, j);
  return t;
}

SensitivityMatrix sensitivityMatrix(const GroundFace& face, const std::vector<Coefficient>& coefficients) {
  SensitivityMatrix S;
  S.coefficients = coefficients;
  S.rows = face.rows();  // at probe points: one row per point, one column
  S.cols = face.cols();
  const int q = static_cast<int>(coefficients.size());
  S.normal.resize(face.size(), q);
  S.thickness.resize(q);
  S.motionRange = 0;
  for (const EnvelopePoint& e : face.envelope) S.motionRange = std::max(S.motionRange, std::abs(e.phi));
  if (S.motionRange == 0) S.motionRange = 1;
  // dt/da_k = dt/dC phi^k + dt/dC' k phi^(k-1) (Eqs. 13-15, EnvelopePoint::sensitivity), with
  // the powers of phi formed once per point and the matrix filled column by column.
  int degree = 0;
  for (const Coefficient& c : coefficients) degree = std::max(degree, c.degree);
  const int n = face.size();
  Eigen::MatrixXd power(n, degree + 1);
  Eigen::MatrixXd value(n, kAxisCount), rate(n, kAxisCount);
  for (int p = 0; p < n; ++p) {
    const EnvelopePoint& e = face.envelope[p];
    power(p, 0) = 1;
    for (int k = 1; k <= degree; ++k) power(p, k) = power(p, k - 1) * e.phi;
    for (int i = 0; i < kAxisCount; ++i) value(p, i) = e.dtdValue[i], rate(p, i) = e.dtdRate[i];
  }
  for (int j = 0; j < q; ++j) {
    const Coefficient& c = coefficients[j];
    const int i = static_cast<int>(c.axis), k = c.degree;
    if (k == 0)
      S.normal.col(j) = kMicrometresPerMm * value.col(i);
    else
      S.normal.col(j) = kMicrometresPerMm * (value.col(i).cwiseProduct(power.col(k)) +
                                             k * rate.col(i).cwiseProduct(power.col(k - 1)));
  }
  const EnvelopePoint& m = face.meanEnvelope;
  for (int j = 0; j < q; ++j) {
    const Coefficient& c = coefficients[j];
    const int i = static_cast<int>(c.axis), k = c.degree;
    const double phiK = std::pow(m.phi, k), phiK1 = k == 0 ? 0.0 : k * std::pow(m.phi, k - 1);
    S.thickness(j) = kMicrometresPerMm * (m.dtdValue[i] * phiK + m.dtdRate[i] * phiK1) * thicknessFactor(face);
  }
  return S;
}

}  // namespace hobsharp
