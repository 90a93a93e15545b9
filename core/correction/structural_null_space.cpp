#include "structural_null_space.h"

#include <algorithm>

#include <Eigen/SVD>

namespace hobsharp {

IdentifiableSpace identifiableSpace(const ToothFace& face, int degree, const CorrectionOptions& o,
                                    double motionRange) {
  IdentifiableSpace s;
  const bool helical = face.gash == GashKind::Helical;
  for (const Coefficient& c : allCoefficients(degree))
    if (!isLocked(c, o)) s.coefficients.push_back(c);
  const int q = static_cast<int>(s.coefficients.size());
  s.step.resize(q);
  for (int j = 0; j < q; ++j) s.step(j) = coefficientStep(o.resolution, s.coefficients[j], motionRange);
  auto indexOf = [&](Axis a, int k) {
    const auto it = std::find(s.coefficients.begin(), s.coefficients.end(), Coefficient{a, k});
    return it == s.coefficients.end() ? -1 : static_cast<int>(it - s.coefficients.begin());
  };

  // The null directions, in z.
  std::vector<Eigen::VectorXd> nulls;
  for (int k = 0; k <= degree; ++k) {
    if (helical) {
      // 1 mm on X a_k and 1/p rad on A a_k cancel (docs/conventions.md §What the grid can see).
      const int x = indexOf(Axis::X, k), a = indexOf(Axis::A, k);
      if (x < 0 || a < 0) continue;
      const double p = face.screwParameter;
      Eigen::VectorXd n = Eigen::VectorXd::Zero(q);
      n(x) = 1.0 / s.step(x);
      n(a) = (1.0 / p) / s.step(a);
      nulls.push_back(n);
      s.structural.push_back(describedCombination({s.coefficients[x], s.coefficients[a]}, {1.0, 1.0 / p}, true));
    } else {
      for (Axis axis : {Axis::X, Axis::Y, Axis::B}) {
        const int j = indexOf(axis, k);
        if (j < 0) continue;
        nulls.push_back(Eigen::VectorXd::Unit(q, j));
        s.structural.push_back(describedCombination({s.coefficients[j]}, {1.0}, false));
      }
    }
  }
  const int t = static_cast<int>(nulls.size());
  if (t == 0) {
    s.basis = Eigen::MatrixXd::Identity(q, q);
    return s;
  }
  Eigen::MatrixXd N(t, q);
  for (int i = 0; i < t; ++i) N.row(i) = nulls[i].normalized().transpose();
  // The null directions are independent (disjoint coefficients), so the last q - t right
  // singular vectors span their orthogonal complement.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(N, Eigen::ComputeFullV);
  s.basis = svd.matrixV().rightCols(q - t);
  return s;
}

}  // namespace hobsharp
