#include "evaluation.h"

namespace hobsharp {

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
  if (job.input.measured) {
    auto c = correctMeasuredFace(s, job.nominalAxes, job.runAxes, e.groundFace, *job.input.measured, job.correction);
    if (!c) return c.error();
    e.correction = std::move(c).value();
  }
  return e;
}

}  // namespace hobsharp
