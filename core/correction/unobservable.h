// A combination of coefficients whose effects on the face cancel, and its description in words.
#pragma once

#include <string>
#include <vector>

#include "coefficient.h"

namespace hobsharp {

// Coefficients whose effects on the face cancel: the combination sum(amount_i * coefficient_i),
// in each coefficient's unit, changes nothing the grid can see.
struct UnobservableCombination {
  std::vector<Coefficient> coefficients;
  std::vector<double> amounts;
  std::string description;
};

// The combination with its amounts per unit of the first coefficient, and the sentence
// ("1 mm on X a0 + 0.00717 rad on A a0: these changes cancel on the face (...)").
UnobservableCombination describedCombination(std::vector<Coefficient> coefficients, std::vector<double> amounts,
                                             bool helical);

// The unit of a coefficient as the page writes it: mm, rad/rad², mm/mm⁴.
std::string coefficientUnit(const Coefficient& c, bool helical);

}  // namespace hobsharp
