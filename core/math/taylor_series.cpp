#include "taylor_series.h"

#include <cmath>
#include <cstddef>

namespace hobsharp {

TaylorSeries::TaylorSeries(std::vector<double> coefficients, int order)
    : c_(std::move(coefficients)), order_(order) {
  c_.resize(static_cast<std::size_t>(order) + 1, 0.0);
}

TaylorSeries operator+(const TaylorSeries& f, const TaylorSeries& g) {
  TaylorSeries h = f;
  for (int k = 0; k <= h.order_; ++k) h.c_[k] += g.c_[k];
  return h;
}

TaylorSeries operator-(const TaylorSeries& f, const TaylorSeries& g) { return f + (-1.0) * g; }

TaylorSeries operator*(double s, const TaylorSeries& f) {
  TaylorSeries h = f;
  for (double& c : h.c_) c *= s;
  return h;
}

TaylorSeries TaylorSeries::operator+(double s) const {
  TaylorSeries h = *this;
  h.c_[0] += s;
  return h;
}

TaylorSeries operator*(const TaylorSeries& f, const TaylorSeries& g) {
  TaylorSeries h({}, f.order_);
  for (int k = 0; k <= f.order_; ++k)
    for (int j = 0; j <= k; ++j) h.c_[k] += f.c_[j] * g.c_[k - j];
  return h;
}

TaylorSeries operator/(const TaylorSeries& f, const TaylorSeries& g) {
  // h g = f, solved term by term.
  TaylorSeries h({}, f.order_);
  for (int k = 0; k <= f.order_; ++k) {
    double s = f.c_[k];
    for (int j = 0; j < k; ++j) s -= h.c_[j] * g.c_[k - j];
    h.c_[k] = s / g.c_[0];
  }
  return h;
}

void sinCos(const TaylorSeries& f, TaylorSeries* sine, TaylorSeries* cosine) {
  const int n = f.order_;
  TaylorSeries s({}, n), c({}, n);
  s.c_[0] = std::sin(f.c_[0]);
  c.c_[0] = std::cos(f.c_[0]);
  for (int k = 1; k <= n; ++k) {
    double ds = 0, dc = 0;
    for (int j = 1; j <= k; ++j) {
      ds += j * f.c_[j] * c.c_[k - j];
      dc -= j * f.c_[j] * s.c_[k - j];
    }
    s.c_[k] = ds / k;
    c.c_[k] = dc / k;
  }
  *sine = s;
  *cosine = c;
}

}  // namespace hobsharp
