// Everything the calculator shows for one job: the derived setup and nominal axes (Eq. 9), the
// wheel profile (Eq. 6), the ground-face topography for the axes that were run (Eqs. 7, 10, 11),
// the sensitivity topographies (Eqs. 13-16) and, with a measured topography, the correction (Eq. 17).
#pragma once

#include <optional>

#include "correction.h"
#include "dressed_wheel.h"
#include "ground_face.h"
#include "outcome.h"
#include "sensitivity_matrix.h"
#include "sharpening_job.h"
#include "topography.h"
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
  // With a wheel profile offset (job.setup.wheel): the dressed profile at wheelProfile's points and
  // the face's sensitivity to the offset's knot values; empty for the conjugate wheel.
  DressedProfile dressedProfile;
  WheelOffsetSensitivity offsetSensitivities;
};

Outcome<Evaluation> evaluate(const SharpeningJob& job);

}  // namespace hobsharp
