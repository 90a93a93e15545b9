// The spacing of the cutting faces around the hob (docs/inspection.md), from one mean
// deviation per gash at the pitch radius (µm, gash 1, 2, .. z in turn; plus = excess material):
//   adjacent   - the single pitch deviation of the cutting faces (f_tN, DIN 3968 item 8): gash
//                k+1's deviation minus gash k's, for every neighbouring pair (the last pair is gash
//                z and gash 1); the largest is the one of largest magnitude, signed;
//   pitch jump - f_uN (item 9): the difference between two consecutive single pitch deviations,
//                pitch k's minus pitch k-1's (pitch 1's minus pitch z's); the one of largest
//                magnitude, signed (docs/inspection.md, "Spacing");
//   cumulative - the largest deviation minus the smallest: the worst spread between any two faces,
//                shown as information (no table row grades it).
#pragma once

#include <string>
#include <vector>

#include "outcome.h"

namespace hobsharp {

struct GashSpacing {
  std::vector<double> adjacent;   // µm, z values
  double adjacentLargest = 0;     // µm, signed
  std::vector<double> pitchJump;  // µm, z values: pitch k's single pitch deviation minus pitch k-1's
  double pitchJumpLargest = 0;    // µm, signed
  double cumulative = 0;         // µm, >= 0
};

GashSpacing gashSpacing(const std::vector<double>& deviations);

// The gashes a case may give: 2 to kMaxGashes values, each finite and at most kMaxGashDeviation
// in magnitude. `field` names the list ("inspection.gashDeviations"); a value as field[k].
constexpr int kMaxGashes = 100;
constexpr double kMaxGashDeviation = 1e4;  // µm
Outcome<void> checkGashDeviations(const std::vector<double>& deviations, const std::string& field);

}  // namespace hobsharp
