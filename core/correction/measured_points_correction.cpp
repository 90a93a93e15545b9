// correctMeasuredPoints (correction.h): the correction of a measurement at probe points, on the
// run face simulated at those points (docs/measured-points.md).
#include <string>

#include "correction.h"
#include "earlier_passes.h"
#include "face_vectors.h"
#include "probe_points.h"

namespace hobsharp {
namespace {

Outcome<Topography> onGrid(const SharpeningSetup& setup, const AxisPolynomials& axes, const FaceGrid& grid) {
  auto f = simulateGroundFace(setup, axes, grid, Sensitivities::Skip);
  if (!f) return f.error();
  return topographyOf(*f);
}

}  // namespace

Outcome<Correction> correctMeasuredPoints(const SharpeningSetup& setup, const AxisPolynomials& nominal,
                                          const AxisPolynomials& run, const FaceGrid& grid,
                                          const ProbePoints& probes, const Eigen::VectorXd& measured,
                                          const CorrectionOptions& o, const PassHistory* history) {
  if (measured.size() != static_cast<Eigen::Index>(probes.size()))
    return refusePoints("measuredPoints", std::to_string(probes.size()) + " points but " +
                                        std::to_string(measured.size()) + " deviations.", ErrorCode::Internal);
  const int free = freeCoefficients(run.degree(), o);
  if (static_cast<int>(probes.size()) < free)
    return refusePoints("measuredPoints", std::to_string(probes.size()) + " points are too few for the " +
                                        std::to_string(free) + " free coefficients of degree " + std::to_string(run.degree()) +
                                        " (one equation per point): measure at least " + std::to_string(free) +
                                        " points, or lower the degree, or lock coefficients.");
  // The run's face at the points, or the nominal one's where the run alone cannot be simulated.
  auto runFace = simulateGroundFace(setup, run, probes, grid);
  const bool atNominal = !runFace;
  if (atNominal) runFace = simulateGroundFace(setup, nominal, probes, grid);
  if (!runFace) return runFace.error();
  auto corrected = correctMeasuredFace(setup, nominal, run, *runFace, measured, o, nullptr, nullptr,
                                       atNominal ? &nominal : nullptr);
  if (!corrected) return corrected.error();
  Correction c = std::move(corrected).value();
  c.probes = probes;
  // The sign against the last pass measured at the same points (history_sign.h); no identification
  // joins points passes.
  if (const EarlierPass* last = history ? earlierAtSamePoints(*history, probes) : nullptr)
    leadWithSign(c, historySign(*runFace, run, measured, *last, o.probeNoise, false));
  auto explained = onGrid(setup, plusError(run, c.identifiedError), grid);
  if (!explained) return explained.error();
  c.explainedOnGrid = std::move(explained).value();
  auto after = onGrid(setup, plusError(c.axes, c.identifiedError), grid);
  if (!after) return after.error();
  c.afterOnGrid = std::move(after).value();
  return c;
}

}  // namespace hobsharp
