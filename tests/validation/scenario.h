// The validation campaign's scenarios (docs/validation.md): a random hob within realistic ranges,
// a random machine error on every coefficient of every axis scaled to a face rms, probe noise, and
// for one class a smooth radial wheel shape. The module is the machine: the measured face is the
// calculator's own simulation of the erroneous axes (and wheel), plus noise.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "case_input.h"
#include "outcome.h"

namespace hobsharp::validation {

// What a scenario tests, with its target (docs/validation.md, "Targets").
enum class ScenarioClass {
  Small,       // noise-free, 3 µm rms: one pass
  Medium,      // noise-free, 30 µm rms: one pass
  Large,       // noise-free, 150 µm rms: two passes
  NoiseOnly,   // a perfect face measured with sigma = 1 µm: one pass
  Noisy,       // 10 µm rms measured with sigma = 0.5 µm: one pass
  Wheel,       // a radial wheel shape up to degree 4 and 6 µm with a 10 µm rms axis error: two passes
};
constexpr int kScenarioClasses = 6;
const char* className(ScenarioClass c);   // "small", "medium", ...
const char* classTitle(ScenarioClass c);  // in words, with units

struct ScenarioSpec {
  ScenarioClass kind = ScenarioClass::Medium;
  double errorRms = 0;   // the machine error's face rms on the probe grid, µm
  double sigma = 0;      // the probe noise added, µm (also declared as correction.probeNoise)
  int passes = 1;
  bool wheel = false;    // a wheel shape in the machine, correction.wheel in the case
};
ScenarioSpec specOf(ScenarioClass c);

struct Scenario {
  std::uint64_t seed = 0;
  int index = 0;
  ScenarioSpec spec;
  CaseInput input;            // the engineer's case, without a measurement
  AxisPolynomials error;      // the machine's actual axes minus the commanded ones
  // The machine's wheel: its offset from the conjugate wheel, µm at wheel radii R (mm).
  std::optional<WheelPointsInput> wheelError;
  std::string description;    // the hob in words: module, diameters, gash, hand, degree, grid
  int rejected = 0;           // random hobs drawn and refused before this one
};

// Scenario `index` of the campaign with `seed`: its class is index mod kScenarioClasses, and it is
// the same on every run with the same seed and index.
Outcome<Scenario> makeScenario(std::uint64_t seed, int index);

}  // namespace hobsharp::validation
