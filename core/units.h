// Angle units: the case file states angles in degrees, the core computes in radians.
#pragma once

namespace hobsharp {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180.0;
constexpr double kDegPerRad = 180.0 / kPi;

}  // namespace hobsharp
