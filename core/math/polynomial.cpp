#include "polynomial.h"

#include <cstddef>

namespace hobsharp {

PolynomialValue Polynomial::at(double w) const {
  // Horner's scheme carried for the value and the first two derivatives.
  PolynomialValue p;
  for (int k = degree(); k >= 0; --k) {
    p.d2 = p.d2 * w + 2.0 * p.d1;
    p.d1 = p.d1 * w + p.value;
    p.value = p.value * w + a[k];
  }
  return p;
}

Polynomial Polynomial::resized(int n) const {
  Polynomial p{a};
  p.a.resize(static_cast<std::size_t>(n) + 1, 0.0);
  return p;
}

}  // namespace hobsharp
