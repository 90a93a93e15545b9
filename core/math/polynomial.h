// A Maclaurin polynomial a0 + a1 w + ... + an w^n of the motion parameter w (Eq. 12).
#pragma once

#include <cstddef>
#include <vector>

namespace hobsharp {

struct PolynomialValue {
  double value = 0;  // f(w)
  double d1 = 0;     // f'(w)
  double d2 = 0;     // f''(w)
};

struct Polynomial {
  std::vector<double> a;  // a[k] multiplies w^k

  static Polynomial constant(double c) { return Polynomial{{c}}; }
  int degree() const { return static_cast<int>(a.size()) - 1; }
  double coefficient(int k) const { return k < static_cast<int>(a.size()) ? a[k] : 0.0; }
  // Horner's scheme carried for the value and the first two derivatives (inline: the envelope
  // solver evaluates the five axes at every step of every point).
  PolynomialValue at(double w) const {
    PolynomialValue p;
    for (int k = degree(); k >= 0; --k) {
      p.d2 = p.d2 * w + 2.0 * p.d1;
      p.d1 = p.d1 * w + p.value;
      p.value = p.value * w + a[static_cast<std::size_t>(k)];
    }
    return p;
  }
  // The same polynomial padded with zeros (or truncated) to `degree`.
  Polynomial resized(int degree) const;
};

}  // namespace hobsharp
