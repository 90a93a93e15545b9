// A number as the refusals and messages write it: `digits` significant digits, no trailing zeros
// (std::ostream's default notation).
#pragma once

#include <cstdlib>
#include <sstream>
#include <string>

namespace hobsharp {

inline std::string numberText(double v, int digits = 6) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

// A value as given, in the fewest digits that read back as it (at least `digits`): what a refusal
// says it got, so that 10000.0001 beyond a limit of 10000 is not written "10000".
inline std::string exactText(double v, int digits = 6) {
  for (int d = digits; d < 17; ++d) {
    std::string t = numberText(v, d);
    if (std::strtod(t.c_str(), nullptr) == v) return t;
  }
  return numberText(v, 17);
}

// A length in mm, as the messages write it: "12.5 mm".
inline std::string mmText(double v) { return numberText(v) + " mm"; }

// A sum of squares as the verdicts write it: 3 digits, or "below 1e-6" where only rounding is left
// (which the native and WebAssembly builds round apart); µm², the unit written by the caller.
inline std::string squaresText(double sse) { return sse < 1e-6 ? std::string("below 1e-6") : numberText(sse, 3); }

// A share of 1 as a percentage: "12.3 %".
inline std::string percentText(double share) { return numberText(100 * share, 3) + " %"; }

}  // namespace hobsharp
