// A natural cubic spline through knots (x_i, y_i): second derivative zero at both ends, and
// beyond the ends the straight line tangent there, which keeps it twice differentiable
// everywhere (README §The wheel's profile offset). Natural rather than not-a-knot: with 2 or 3
// knots it stays defined (a line, or the smoothest curve through 3 points), and its extension
// past the knots never curves away.
//
// The spline is linear in the y_i: value(x) = sum_i y_i B_i(x); `basis` gives the weights B_i(x)
// and B_i'(x), which the sensitivities to the knot values use.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace hobsharp {

class CubicSpline {
 public:
  CubicSpline() = default;
  // x strictly increasing, at least 2 knots, every value finite (the caller checks).
  CubicSpline(std::vector<double> x, std::vector<double> y);

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  std::size_t size() const { return x_.size(); }
  bool empty() const { return x_.empty(); }

  // The value and the first derivative at t (any number type with the arithmetic of double;
  // the segment is chosen by the value of t).
  template <class T>
  T value(const T& t) const { return evaluate(t, 0); }
  template <class T>
  T slope(const T& t) const { return evaluate(t, 1); }

  // Weights of the knot values: value(t) = B.dot(y), slope(t) = dB.dot(y).
  struct Basis {
    Eigen::VectorXd B, dB;
  };
  Basis basis(double t) const;

 private:
  std::vector<double> x_, y_;
  Eigen::VectorXd m_;  // second derivatives at the knots
  Eigen::MatrixXd s_;  // m = s y: the second derivatives per knot value (for `basis`)

  std::size_t segment(double t) const;
  template <class T>
  T evaluate(const T& t, int derivative) const;
};

inline double plainValue(double t) { return t; }
template <class T>
double plainValue(const T& t) { return t.value(); }

template <class T>
T CubicSpline::evaluate(const T& t, int derivative) const {
  const std::size_t n = x_.size();
  const double tv = plainValue(t);
  // Beyond the ends: the tangent line (m = 0 there).
  if (tv <= x_.front() || tv >= x_.back()) {
    const bool left = tv <= x_.front();
    const std::size_t a = left ? 0 : n - 2, b = a + 1;
    const double h = x_[b] - x_[a];
    const double slopeAtEnd = left ? (y_[b] - y_[a]) / h - h * (2 * m_(a) + m_(b)) / 6
                                   : (y_[b] - y_[a]) / h + h * (m_(a) + 2 * m_(b)) / 6;
    if (derivative == 1) return T(slopeAtEnd);
    const double xe = left ? x_.front() : x_.back(), ye = left ? y_.front() : y_.back();
    return ye + slopeAtEnd * (t - xe);
  }
  const std::size_t i = segment(tv);
  const double h = x_[i + 1] - x_[i];
  const T a = (x_[i + 1] - t) / h, b = (t - x_[i]) / h;
  if (derivative == 1)
    return (y_[i + 1] - y_[i]) / h + (-(3.0 * a * a - 1.0) * m_(i) + (3.0 * b * b - 1.0) * m_(i + 1)) * (h / 6);
  return a * y_[i] + b * y_[i + 1] + ((a * a * a - a) * m_(i) + (b * b * b - b) * m_(i + 1)) * (h * h / 6);
}

}  // namespace hobsharp
