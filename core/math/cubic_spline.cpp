#include "cubic_spline.h"

#include <algorithm>
#include <utility>

#include <Eigen/LU>
#include <Eigen/Sparse>

namespace hobsharp {

namespace {

// The natural spline's equations for the interior second derivatives (i = 1 .. n-2):
//   h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 ((y_{i+1}-y_i)/h_i - (y_i-y_{i-1})/h_{i-1}),
// with m_0 = m_{n-1} = 0: symmetric, tridiagonal and diagonally dominant, solved by Eigen's sparse
// LDL^T once for the unit right-hand sides, so that m = s y.
Eigen::MatrixXd naturalWeights(const std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(n, n);
  if (n > 2) {
    const int k = n - 2;
    Eigen::SparseMatrix<double> A(k, k);
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(k, n);  // right-hand side per knot value
    for (int r = 0; r < k; ++r) {
      const int i = r + 1;
      const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
      entries.emplace_back(r, r, 2 * (h0 + h1));
      if (r > 0) entries.emplace_back(r, r - 1, h0);
      if (r + 1 < k) entries.emplace_back(r, r + 1, h1);
      C(r, i - 1) += 6 / h0;
      C(r, i) -= 6 / h0 + 6 / h1;
      C(r, i + 1) += 6 / h1;
    }
    A.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
    s.middleRows(1, k) = ldlt.solve(C);
  }
  return s;
}

// Not-a-knot: the same interior equations, and at each end the third derivative continuous across
// the first (last) interior knot, (m_1 - m_0)/h_0 = (m_2 - m_1)/h_1; a small dense system (the
// knots of a wheel profile: a few to a few dozen), solved by LU once for the unit right-hand sides.
// With 3 knots both end conditions are one: m_0 = m_1 = m_2, the parabola; with 2, the line.
Eigen::MatrixXd notAKnotWeights(const std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  if (n < 3) return Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n), C = Eigen::MatrixXd::Zero(n, n);
  for (int i = 1; i + 1 < n; ++i) {
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    A(i, i - 1) = h0;
    A(i, i) = 2 * (h0 + h1);
    A(i, i + 1) = h1;
    C(i, i - 1) += 6 / h0;
    C(i, i) -= 6 / h0 + 6 / h1;
    C(i, i + 1) += 6 / h1;
  }
  if (n == 3) {
    A(0, 0) = 1, A(0, 1) = -1;  // m_0 = m_1
    A(2, 1) = 1, A(2, 2) = -1;  // m_1 = m_2
  } else {
    const double a0 = x[1] - x[0], a1 = x[2] - x[1];
    A(0, 0) = -1 / a0, A(0, 1) = 1 / a0 + 1 / a1, A(0, 2) = -1 / a1;
    const int k = n - 1;
    const double b0 = x[k - 1] - x[k - 2], b1 = x[k] - x[k - 1];
    A(k, k - 2) = -1 / b0, A(k, k - 1) = 1 / b0 + 1 / b1, A(k, k) = -1 / b1;
  }
  return A.partialPivLu().solve(C);
}

}  // namespace

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y, Eigen::MatrixXd s)
    : x_(std::move(x)), y_(std::move(y)), s_(std::move(s)) {
  m_ = s_ * Eigen::Map<const Eigen::VectorXd>(y_.data(), static_cast<Eigen::Index>(y_.size()));
}

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y)
    : CubicSpline(x, std::move(y), naturalWeights(x)) {}

CubicSpline CubicSpline::notAKnot(std::vector<double> x, std::vector<double> y) {
  Eigen::MatrixXd s = notAKnotWeights(x);
  return CubicSpline(std::move(x), std::move(y), std::move(s));
}

std::size_t CubicSpline::segment(double t) const {
  const auto it = std::upper_bound(x_.begin(), x_.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - x_.begin());
  return std::min(std::max<std::size_t>(i, 1), x_.size() - 1) - 1;
}

CubicSpline::Point CubicSpline::at(double t) const {
  const std::size_t n = x_.size();
  // Beyond the ends: the tangent line (curvature 0 there).
  if (t <= x_.front() || t >= x_.back()) {
    const bool left = t <= x_.front();
    const std::size_t a = left ? 0 : n - 2, b = a + 1;
    const double h = x_[b] - x_[a];
    const double slopeAtEnd = left ? (y_[b] - y_[a]) / h - h * (2 * m_(a) + m_(b)) / 6
                                   : (y_[b] - y_[a]) / h + h * (m_(a) + 2 * m_(b)) / 6;
    const double xe = left ? x_.front() : x_.back(), ye = left ? y_.front() : y_.back();
    return {ye + slopeAtEnd * (t - xe), slopeAtEnd, 0.0};
  }
  const std::size_t i = segment(t);
  const double h = x_[i + 1] - x_[i];
  const double a = (x_[i + 1] - t) / h, b = (t - x_[i]) / h;
  return {a * y_[i] + b * y_[i + 1] + ((a * a * a - a) * m_(i) + (b * b * b - b) * m_(i + 1)) * (h * h / 6),
          (y_[i + 1] - y_[i]) / h + (-(3 * a * a - 1) * m_(i) + (3 * b * b - 1) * m_(i + 1)) * (h / 6),
          a * m_(i) + b * m_(i + 1)};
}

// The same formulas with y the unit vectors: the second derivatives of the j-th cardinal
// function are s_.col(j), so the weights of segment i are rows i and i + 1 of s_.
CubicSpline::Basis CubicSpline::basis(double t) const {
  const int n = static_cast<int>(x_.size());
  Basis out{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  if (t <= x_.front() || t >= x_.back()) {
    const bool left = t <= x_.front();
    const int a = left ? 0 : n - 2, b = a + 1, e = left ? 0 : n - 1;
    const double h = x_[b] - x_[a];
    // slopeAtEnd per knot value, then the tangent line from the end knot.
    out.dB = left ? Eigen::VectorXd(-h / 6 * (2 * s_.row(a) + s_.row(b)).transpose())
                  : Eigen::VectorXd(h / 6 * (s_.row(a) + 2 * s_.row(b)).transpose());
    out.dB(a) -= 1 / h;
    out.dB(b) += 1 / h;
    out.B = out.dB * (t - x_[e]);
    out.B(e) += 1;
    return out;
  }
  const int i = static_cast<int>(segment(t));
  const double h = x_[i + 1] - x_[i];
  const double a = (x_[i + 1] - t) / h, b = (t - x_[i]) / h;
  out.B = ((a * a * a - a) * s_.row(i) + (b * b * b - b) * s_.row(i + 1)).transpose() * (h * h / 6);
  out.B(i) += a;
  out.B(i + 1) += b;
  out.dB = (-(3 * a * a - 1) * s_.row(i) + (3 * b * b - 1) * s_.row(i + 1)).transpose() * (h / 6);
  out.dB(i) -= 1 / h;
  out.dB(i + 1) += 1 / h;
  return out;
}

}  // namespace hobsharp
