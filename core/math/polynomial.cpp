#include "polynomial.h"

#include <cstddef>

namespace hobsharp {

Polynomial Polynomial::resized(int n) const {
  Polynomial p{a};
  p.a.resize(static_cast<std::size_t>(n) + 1, 0.0);
  return p;
}

}  // namespace hobsharp
