#include "evaluation.h"

#include <algorithm>

namespace hobsharp {

void inspectEvaluation(Evaluation& e) {
  const SharpeningJob& job = e.job;
  const InspectionInput& in = job.input.inspection;
  const ToleranceTable& table = toleranceTableOf(in);
  const bool helical = job.setup.face.helical();
  const double module = job.input.hob.normalModule;
  const Eigen::MatrixXd& face = job.input.measured ? *job.input.measured : e.topography.normal;
  std::optional<GashSpacing> spacing;
  if (!in.gashDeviations.empty()) {
    spacing = gashSpacing(in.gashDeviations);
    const double perRadian = deviationPerIndexAngle(job.setup, job.setup.face.pitchRadius, 0.0);
    e.indexCorrection = indexCorrection(in.gashDeviations, perRadian, job.correction.resolution.inAxisUnit(Axis::A));
  }
  e.inspection = inspect(checkFace(face, job.grid.r, job.grid.x, helical), spacing, table, module);
  if (!e.correction && !e.indexCorrection) return;
  const Eigen::MatrixXd& after = e.correction ? e.correction->after.normal : face;
  std::optional<GashSpacing> spacingAfter;
  if (e.indexCorrection) spacingAfter = gashSpacing(e.indexCorrection->after);
  e.inspectionAfter = inspect(checkFace(after, job.grid.r, job.grid.x, helical), spacingAfter, table, module);
}

Outcome<Evaluation> evaluate(const SharpeningJob& job) {
  Evaluation e;
  e.job = job;
  const SharpeningSetup& s = job.setup;
  auto profile = wheelProfile(s.face, s.universal, s.normalSign,
                              evenRadii(job.rootRadius, job.outerRadius, kWheelProfilePoints));
  if (!profile) return profile.error();
  e.wheelProfile = std::move(profile).value();
  auto face = simulateGroundFace(s, job.runAxes, job.grid);
  if (!face) return face.error();
  e.groundFace = std::move(face).value();
  e.topography = topographyOf(e.groundFace);
  e.sensitivities = sensitivityMatrix(e.groundFace, allCoefficients(job.runAxes.degree()));
  if (s.wheel.hasOffset()) {
    e.dressedProfile = dressedProfile(s, e.wheelProfile);
    e.offsetSensitivities = wheelOffsetSensitivity(e.groundFace, s.wheel);
  }
  if (job.input.measured && job.correction.wheel) {  // README §Wheel-profile correction
    const double rLow = std::max(job.grid.r.front(), job.rootRadius), rHigh = std::min(job.grid.r.back(), job.outerRadius);
    auto c = correctAxesAndWheel(s, job.nominalAxes, job.runAxes, e.groundFace, *job.input.measured, job.correction,
                                 e.wheelProfile, rLow, rHigh);
    if (!c) return c.error();
    e.correction = std::move(c->correction);
    e.wheelCorrection = std::move(c->wheel);
  } else if (job.input.measured) {
    auto c = correctMeasuredFace(s, job.nominalAxes, job.runAxes, e.groundFace, *job.input.measured, job.correction);
    if (!c) return c.error();
    e.correction = std::move(c).value();
  }
  inspectEvaluation(e);
  return e;
}

}  // namespace hobsharp
