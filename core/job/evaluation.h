// Everything the calculator shows for one job: the derived setup and nominal axes (Eq. 9), the
// wheel profile (Eq. 6), the ground-face topography for the axes that were run (Eqs. 7, 10, 11),
// the sensitivity topographies (Eqs. 13-16) and, with a measured topography, the correction (Eq. 17).
#pragma once

#include <optional>

#include "correction.h"
#include "dressed_wheel.h"
#include "gash_faces.h"
#include "gear_effect.h"
#include "ground_face.h"
#include "index_correction.h"
#include "inspection.h"
#include "outcome.h"
#include "sensitivity_matrix.h"
#include "sharpening_job.h"
#include "topography.h"
#include "wheel_correction.h"
#include "wheel_offset_sensitivity.h"
#include "wheel_profile.h"

namespace hobsharp {

struct Evaluation {
  SharpeningJob job;
  GroundFace groundFace;
  Topography topography;
  SensitivityMatrix sensitivities;  // every coefficient, at the axes that were run
  std::optional<Correction> correction;
  // The rake-face inspection (docs/inspection.md): of the measured face when there is
  // one, else of the simulated one; the A-axis indexing correction with per-gash deviations; and
  // the inspection predicted after the correction (the face correction's predicted face, the
  // gashes after the rounded indexing correction) when either correction exists.
  Inspection inspection;
  std::optional<IndexCorrection> indexCorrection;
  std::optional<GashFaces> gashFaces;  // with inspection.gashTopographies: per gash, and the worst
  std::optional<Inspection> inspectionAfter;
  // With a wheel profile offset (job.setup.wheel): the dressed profile at job.wheelProfile's points and
  // the face's sensitivity to the offset's knot values; empty for the conjugate wheel.
  DressedProfile dressedProfile;
  WheelOffsetSensitivity offsetSensitivities;
  // The effect of the face inspected on the gear (docs/gear-effect.md): with the hob's
  // relief; else, or when it cannot be computed, the sentence that says why.
  std::optional<GearEffect> gearEffect;
  std::string gearEffectReason;
  // With the gear effect: the change of the gear's pressure angle per degree of hook at the tip
  // (rad per rad, the mean of the two flanks), from the gear-effect model on a face that carries a
  // rake error alone (rakeErrorFace, docs/inspection.md "Rake error").
  std::optional<double> pressureAnglePerRake;
  // With `correction.wheel` (docs/method.md §Wheel-profile correction): the wheel's part of the correction;
  // `correction` then holds the axes' part, its predicted face with both applied.
  std::optional<WheelCorrection> wheelCorrection;
};

// Reads the resolved job alone (sharpening_job.h), never the case's raw input.
Outcome<Evaluation> evaluate(const SharpeningJob& job);

// Fills e.inspection, e.indexCorrection and e.inspectionAfter from the rest of `e` (evaluate()
// calls it last; the benchmark times it alone).
void inspectEvaluation(Evaluation& e);

// Fills e.gearEffect (or e.gearEffectReason) from the face inspectEvaluation() inspects
// (gear_evaluation.cpp; evaluate() calls it after the inspection; the benchmark times it alone).
void gearEvaluation(Evaluation& e);

// The face the inspection and the gear effect take, and where it comes from (FaceSource,
// measured_face.h): the measured grid (also measuredPoints at the grid's positions), or for
// measuredPoints off the grid the measurement as the identified error explains it there, else the
// simulated topography.
struct InspectedFace {
  const Eigen::MatrixXd& normal;  // µm, on the grid
  FaceSource source;
};
InspectedFace inspectedFace(const Evaluation& e);
// Why the face inspectedFace() gives does not stand for the measurement, in words that follow
// "Not graded: ...": for measuredPoints off the grid, where the face the identified error explains
// on the grid leaves more than twice the probe noise of the points unexplained (rms); "" where it
// stands for it (and for every other source).
std::string unexplainedPointsText(const Evaluation& e);

}  // namespace hobsharp
