// The correction's options as the case gives them (`correction`, and a pass's, docs/case-format.md),
// and their value rules: checked, they are the CorrectionOptions the correction runs with.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "axis_polynomials.h"
#include "coefficient.h"
#include "correction_options.h"
#include "outcome.h"

namespace hobsharp {

struct CorrectionInput {
  std::optional<std::string> method;      // "nonlinear" (the default) or "linear"
  std::optional<double> probeNoise;       // sigma, µm
  // Per axis, as given: µm for X, Y, Z, degrees for A, B; the machine defaults where not given.
  std::array<std::optional<double>, kAxisCount> resolution;
  std::optional<double> truncation;
  std::optional<double> amplification;
  std::vector<Axis> lockedAxes;
  std::vector<Coefficient> locked;
  std::optional<bool> wheel;              // solve for a wheel-profile offset too (default false)
};

// The range of correction.resolution: µm for X, Y, Z and degrees for A, B.
constexpr double kLeastLinearResolution = 1e-3, kMostLinearResolution = 1e3;
constexpr double kLeastRotaryResolution = 1e-9, kMostRotaryResolution = 1;

// The options of `c` for axes of the given degree, the defaults where it gives none; `name` is its
// field ("correction", "passes[1].correction"), and every refusal names the member within it.
Outcome<CorrectionOptions> correctionOptions(const CorrectionInput& c, int degree, const std::string& name);

}  // namespace hobsharp
