#include "coefficient.h"

namespace hobsharp {

std::vector<Coefficient> allCoefficients(int degree) {
  std::vector<Coefficient> c;
  for (Axis a : kAxes)
    for (int k = 0; k <= degree; ++k) c.push_back(Coefficient{a, k});
  return c;
}

}  // namespace hobsharp
