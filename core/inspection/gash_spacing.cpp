#include "gash_spacing.h"
#include "number_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hobsharp {

GashSpacing gashSpacing(const std::vector<double>& d) {
  GashSpacing s;
  const std::size_t z = d.size();
  if (z < 2) return s;
  for (std::size_t k = 0; k < z; ++k) {
    const double step = d[(k + 1) % z] - d[k];
    s.adjacent.push_back(step);
    if (std::abs(step) > std::abs(s.adjacentLargest)) s.adjacentLargest = step;
  }
  for (std::size_t k = 0; k < z; ++k) {
    const double jump = s.adjacent[k] - s.adjacent[(k + z - 1) % z];
    s.pitchJump.push_back(jump);
    if (std::abs(jump) > std::abs(s.pitchJumpLargest)) s.pitchJumpLargest = jump;
  }
  const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
  s.cumulative = *hi - *lo;
  return s;
}

Outcome<void> checkGashDeviations(const std::vector<double>& d, const std::string& field) {
  if (d.size() < 2 || d.size() > static_cast<std::size_t>(kMaxGashes))
    return refuse(field, "needs one deviation per gash, 2 to " + std::to_string(kMaxGashes) + " values; got " +
                             std::to_string(d.size()) + ".");
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (!std::isfinite(d[k]) || std::abs(d[k]) > kMaxGashDeviation) {
      return refuse(field + "[" + std::to_string(k) + "]",
                    "must be a deviation in µm of magnitude at most 10000; got " + exactText(d[k]) + ".");
    }
  }
  return success();
}

}  // namespace hobsharp
