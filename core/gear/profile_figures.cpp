#include "profile_figures.h"

#include <algorithm>
#include <cmath>

namespace hobsharp {

ProfileFigures profileFigures(const std::vector<double>& height, const std::vector<double>& deviation,
                              double pressureAngle) {
  ProfileFigures out;
  const std::size_t n = height.size();
  if (n < 2) return out;
  double hm = 0, dm = 0;
  for (std::size_t k = 0; k < n; ++k) {
    hm += height[k];
    dm += deviation[k];
  }
  hm /= n;
  dm /= n;
  double shh = 0, shd = 0;
  for (std::size_t k = 0; k < n; ++k) {
    shh += (height[k] - hm) * (height[k] - hm);
    shd += (height[k] - hm) * (deviation[k] - dm);
  }
  if (shh <= 0) return out;
  const double b = shd / shh;  // µm per mm of height
  const double range = height.back() - height.front();
  out.slope = b * range;
  out.pressureAngle = -out.slope * 1e-3 / (range / std::cos(pressureAngle));
  double lo = 0, hi = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double r = deviation[k] - dm - b * (height[k] - hm);
    lo = k == 0 ? r : std::min(lo, r);
    hi = k == 0 ? r : std::max(hi, r);
  }
  out.form = hi - lo;
  return out;
}

}  // namespace hobsharp
