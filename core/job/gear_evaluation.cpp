#include <cmath>

#include "evaluation.h"
#include "face_checks.h"
#include "hob_relief.h"
#include "units.h"

namespace hobsharp {
namespace {

// The hook the rake sensitivity is computed at: small enough for the first order, large enough
// (some 60 µm on a module-7 face) to stand well clear of the edge solver's tolerance.
constexpr double kReferenceHook = 0.1 * kRadPerDeg;

}  // namespace

void gearEvaluation(Evaluation& e) {
  const SharpeningJob& job = e.job;
  const ReliefPerRadian& k = job.gear.relief;
  e.gearEffect.reset();
  e.pressureAnglePerRake.reset();
  e.gearEffectReason = k.missing;
  if (!k.value) return;
  // The face inspected (inspectEvaluation, inspectedFace).
  const Eigen::MatrixXd& face = inspectedFace(e).normal;
  const BasicRack& rack = job.gear.rack;
  // Measured points the face on the grid does not explain: no gear effect of a model's face.
  const std::string unexplained = unexplainedPointsText(e);
  if (!unexplained.empty()) {
    e.gearEffectReason = "No gear effect: " + unexplained + ".";
    return;
  }
  auto g = gearEffect(job.setup.face, job.setup.normalSign, job.grid.r, job.grid.x, face, rack, *k.value);
  if (!g) {
    e.gearEffectReason = "No gear effect: " + g.error().message.substr(g.error().field.size() + 2);
    return;
  }
  e.gearEffect = std::move(g).value();
  // A rake error alone: the face moved across its lines by the offset that turns the rake angle at
  // the tip by kReferenceHook (d gamma = d e / sqrt(r_a^2 - e^2), face_checks.h).
  const FaceLines lines = FaceLines::of(job.setup, job.grid);
  const double offset = kReferenceHook * lines.alongLine.back();
  auto rake = gearEffect(job.setup.face, job.setup.normalSign, job.grid.r, job.grid.x, rakeErrorFace(lines, offset), rack, *k.value);
  if (rake) e.pressureAnglePerRake = 0.5 * (rake->left.pressureAngle + rake->right.pressureAngle) / kReferenceHook;
}

}  // namespace hobsharp
