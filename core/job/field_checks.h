// The two value rules every part of a case uses: a number that must be finite, and one that must
// be positive (with its unit in the message).
#pragma once

#include <cmath>
#include <string>

#include "number_text.h"
#include "outcome.h"

namespace hobsharp {

inline Outcome<void> finite(const std::string& field, double v) {
  if (!std::isfinite(v)) return refuse(field, "must be a finite number.");
  return success();
}

inline Outcome<void> positive(const std::string& field, double v, const char* unit) {
  if (!std::isfinite(v)) return refuse(field, "must be a finite number.");
  if (v <= 0) return refuse(field, "must be positive; got " + exactText(v) + " " + unit + ".");
  return success();
}

}  // namespace hobsharp
