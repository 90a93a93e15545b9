// A cubic spline through knots (x_i, y_i), and beyond the ends the straight line tangent there.
// Two kinds of ends (named constructors):
//   - natural (the default constructor): second derivative zero at both ends, so the extension
//     keeps it twice differentiable everywhere; the face's interpolation (actual_rake_face.h);
//   - not-a-knot (`notAKnot`): the third derivative continuous at the second and the
//     second-to-last knot, so any cubic through the knots is the cubic itself; with 3 knots the
//     parabola through them, with 2 the line. The wheel's profile offsets (docs/method.md §The
//     wheel's profile offset): a dressing error has no reason to be straight at the ends of the
//     profile, and the natural ends made the wheel's correction miss between the probe rows (the
//     campaign's wheel class, docs/validation.md). Past the ends its curvature drops to zero (the
//     tangent line): once differentiable there.
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
  // x strictly increasing, at least 2 knots, every value finite (the caller checks). Natural ends.
  CubicSpline(std::vector<double> x, std::vector<double> y);
  // The same knots with not-a-knot ends.
  static CubicSpline notAKnot(std::vector<double> x, std::vector<double> y);

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

  // The knots with the second derivatives per knot value, s (n x n), already solved.
  CubicSpline(std::vector<double> x, std::vector<double> y, Eigen::MatrixXd s);

  std::size_t segment(double t) const;
};

}  // namespace hobsharp
