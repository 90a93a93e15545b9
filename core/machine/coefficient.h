// One coefficient a_k of one CNC axis polynomial (Eq. 12): what the sensitivity matrix has a
// column for, what a correction changes, and what the case file can lock.
#pragma once

#include <string>
#include <vector>

#include "axis_polynomials.h"

namespace hobsharp {

// The coefficient a_k of `axis` (Eq. 12), in mm or rad per (rad or mm)^k.
struct Coefficient {
  Axis axis = Axis::X;
  int degree = 0;
  std::string name() const { return std::string(axisName(axis)) + " a" + std::to_string(degree); }
  bool operator==(const Coefficient& o) const { return axis == o.axis && degree == o.degree; }
};

// Every coefficient of degree 0..degree, axis by axis: X a0..an, Y a0..an, ... B a0..an.
std::vector<Coefficient> allCoefficients(int degree);

}  // namespace hobsharp
