// Everything the calculator shows for one job: the derived setup and nominal axes (Eq. 9), the
// wheel profile (Eq. 6), the ground-face topography for the axes that were run (Eqs. 7, 10, 11),
// the sensitivity topographies (Eqs. 13-16) and, with a measured topography, the correction (Eq. 17).
#pragma once

#include <optional>

#include "correction.h"
#include "dressed_wheel.h"
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

constexpr int kWheelProfilePoints = 41;

struct Evaluation {
  SharpeningJob job;
  WheelProfile wheelProfile;
  GroundFace groundFace;
  Topography topography;
  SensitivityMatrix sensitivities;  // every coefficient, at the axes that were run
  std::optional<Correction> correction;
  // The rake-face inspection (README, "Rake-face inspection"): of the measured face when there is
  // one, else of the simulated one; the A-axis indexing correction with per-gash deviations; and
  // the inspection predicted after the correction (the face correction's predicted face, the
  // gashes after the rounded indexing correction) when either correction exists.
  Inspection inspection;
  std::optional<IndexCorrection> indexCorrection;
  std::optional<Inspection> inspectionAfter;
  // With a wheel profile offset (job.setup.wheel): the dressed profile at wheelProfile's points and
  // the face's sensitivity to the offset's knot values; empty for the conjugate wheel.
  DressedProfile dressedProfile;
  WheelOffsetSensitivity offsetSensitivities;
  // With `correction.wheel` (README §Wheel-profile correction): the wheel's part of the correction;
  // `correction` then holds the axes' part, its predicted face with both applied.
  std::optional<WheelCorrection> wheelCorrection;
};

Outcome<Evaluation> evaluate(const SharpeningJob& job);

// Fills e.inspection, e.indexCorrection and e.inspectionAfter from the rest of `e` (evaluate()
// calls it last; the benchmark times it alone).
void inspectEvaluation(Evaluation& e);

}  // namespace hobsharp
