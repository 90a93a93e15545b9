#include <cmath>

#include "evaluation.h"
#include "hob_relief.h"
#include "units.h"

namespace hobsharp {

void gearEvaluation(Evaluation& e) {
  const SharpeningJob& job = e.job;
  const HobInput& hob = job.input.hob;
  const double alpha = hob.normalPressureAngle * kRadPerDeg;
  const ReliefPerRadian k = reliefPerRadian(hob.relief, job.setup.face.pitchRadius, alpha);
  e.gearEffect.reset();
  e.gearEffectReason = k.missing;
  if (!k.value) return;
  // The face inspected (inspectEvaluation): the measured grid, else the simulated topography.
  const Eigen::MatrixXd& face = inspectedFace(e).normal;
  const BasicRack rack{hob.normalModule, alpha, job.setup.face.pitchRadius};
  auto g = gearEffect(job.setup.face, job.setup.normalSign, job.grid.r, job.grid.x, face, rack, *k.value);
  if (!g) {
    e.gearEffectReason = "No gear effect: " + g.error().message.substr(g.error().field.size() + 2);
    return;
  }
  e.gearEffect = std::move(g).value();
}

}  // namespace hobsharp
