// The spacing of the cutting faces around the hob (README, "Rake-face inspection"), from one mean
// deviation per gash at the pitch radius (µm, gash 1, 2, .. z in turn; plus = excess material):
//   adjacent   - gash k+1's deviation minus gash k's, for every neighbouring pair (the last pair
//                is gash z and gash 1); the largest is the one of largest magnitude, signed;
//   cumulative - the largest deviation minus the smallest: the worst spread between any two faces.
#pragma once

#include <string>
#include <vector>

#include "outcome.h"

namespace hobsharp {

struct GashSpacing {
  std::vector<double> adjacent;  // µm, z values
  double adjacentLargest = 0;    // µm, signed
  double cumulative = 0;         // µm, >= 0
};

GashSpacing gashSpacing(const std::vector<double>& deviations);

// The gashes a case may give: 2 to kMaxGashes values, each finite and at most kMaxGashDeviation
// in magnitude. `field` names the list ("inspection.gashDeviations"); a value as field[k].
constexpr int kMaxGashes = 100;
constexpr double kMaxGashDeviation = 1e4;  // µm
Outcome<void> checkGashDeviations(const std::vector<double>& deviations, const std::string& field);

}  // namespace hobsharp
