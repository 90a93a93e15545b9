// Truncated Taylor series arithmetic: exact Maclaurin coefficients of compositions such as
// tan(gamma_m(phi)) for Eq. 12, without fitting or finite differences.
#pragma once

#include <vector>

namespace hobsharp {

class TaylorSeries {
 public:
  // The series of a polynomial, truncated to `order` (the highest power kept).
  TaylorSeries(std::vector<double> coefficients, int order);

  int order() const { return order_; }
  const std::vector<double>& coefficients() const { return c_; }

  friend TaylorSeries operator+(const TaylorSeries& f, const TaylorSeries& g);
  friend TaylorSeries operator-(const TaylorSeries& f, const TaylorSeries& g);
  friend TaylorSeries operator*(const TaylorSeries& f, const TaylorSeries& g);
  friend TaylorSeries operator/(const TaylorSeries& f, const TaylorSeries& g);
  friend TaylorSeries operator*(double s, const TaylorSeries& f);
  TaylorSeries operator+(double s) const;

  // sin and cos of a series together, from s' = c f', c' = -s f'.
  friend void sinCos(const TaylorSeries& f, TaylorSeries* sine, TaylorSeries* cosine);

 private:
  std::vector<double> c_;
  int order_;
};

}  // namespace hobsharp
