#include "index_correction.h"

#include <cmath>
#include <numeric>

#include "face_grid.h"
#include "units.h"

namespace hobsharp {

double deviationPerIndexAngle(const SharpeningSetup& setup, double r, double x) {
  const GridPoint g = gridPoint(setup, r, x);
  const Eigen::Vector3d turn(0, -g.p.z(), g.p.y());  // x_1 x p
  return -kMicrometresPerMm * g.n.dot(turn);
}

IndexCorrection indexCorrection(const std::vector<double>& d, double perRadian, double stepRad) {
  IndexCorrection c;
  c.perRadian = perRadian;
  if (d.empty() || perRadian == 0) return c;
  const double mean = std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
  for (double dk : d) {
    const double a = -(dk - mean) / perRadian;
    const double rounded = stepRad > 0 ? std::round(a / stepRad) * stepRad : a;
    c.angle.push_back(a);
    c.rounded.push_back(rounded);
    c.after.push_back(dk + perRadian * rounded);
  }
  return c;
}

}  // namespace hobsharp
