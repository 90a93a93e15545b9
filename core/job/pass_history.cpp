#include "pass_history.h"

#include <string>

#include "correction_input.h"
#include "measured_face.h"
#include "run_axes.h"

namespace hobsharp {

Outcome<void> checkPasses(const std::vector<PassInput>& passes, int degree, const FaceGrid& grid, const PointRegion& region) {
  for (size_t i = 0; i < passes.size(); ++i) {
    const std::string pass = "passes[" + std::to_string(i) + "].";
    if (auto r = checkAxes(passes[i].axes, degree, pass + "axes"); !r) return r;
    if (passes[i].measuredPoints) {
      if (auto r = checkPoints(*passes[i].measuredPoints, region, pass + "measuredPoints"); !r) return r;
    } else if (auto r = checkMeasured(passes[i].measured, grid, pass + "measured"); !r) {
      return r;
    }
    if (passes[i].correction)
      if (auto r = correctionOptions(*passes[i].correction, degree, pass + "correction"); !r) return r.error();
  }
  return success();
}

PassHistory passHistory(const std::vector<PassInput>& passes, const AxisPolynomials& nominal, bool wheelCorrected) {
  PassHistory h;
  h.nominal = nominal;
  for (const PassInput& p : passes)
    if (p.correction && p.correction->wheel.value_or(false)) wheelCorrected = true;
  h.wheelCorrected = wheelCorrected;
  for (const PassInput& p : passes)
    if (joinsLaterPasses(!p.measuredPoints && p.measured.size() > 0, wheelCorrected))
      h.passes.push_back({p.axes, p.measured});
  if (wheelCorrected) return h;
  for (auto p = passes.rbegin(); p != passes.rend(); ++p)
    if (p->measuredPoints && !p->measuredPoints->empty()) {
      Eigen::MatrixXd values(static_cast<Eigen::Index>(p->measuredPoints->size()), 1);
      for (size_t k = 0; k < p->measuredPoints->size(); ++k) {
        const MeasuredPoint& m = (*p->measuredPoints)[k];
        values(static_cast<Eigen::Index>(k), 0) = m.deviation;
        h.lastPoints.push_back(ProbePoint{m.r, m.x});
      }
      h.lastAtPoints = EarlierPass{p->axes, values};
      break;
    }
  return h;
}

}  // namespace hobsharp
