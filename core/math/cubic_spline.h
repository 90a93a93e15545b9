// A natural cubic spline through knots (x_i, y_i): second derivative zero at both ends, and
// beyond the ends the straight line tangent there, which keeps it twice differentiable
// everywhere (docs/method.md §The wheel's profile offset). Natural rather than not-a-knot: with 2 or 3
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

  // The value, the first and the second derivative at t.
  struct Point {
    double value = 0, slope = 0, curvature = 0;
  };
  Point at(double t) const;
  double value(double t) const { return at(t).value; }
  double slope(double t) const { return at(t).slope; }
  double curvature(double t) const { return at(t).curvature; }

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
};

}  // namespace hobsharp
