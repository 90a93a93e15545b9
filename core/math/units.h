// Units: the case file states angles in degrees and deviations in µm; the core computes in
// radians and mm.
#pragma once

namespace hobsharp {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180.0;
constexpr double kDegPerRad = 180.0 / kPi;
constexpr double kMicrometresPerMm = 1000.0;

}  // namespace hobsharp
