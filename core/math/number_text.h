// A number as the refusals and messages write it: `digits` significant digits, no trailing zeros
// (std::ostream's default notation).
#pragma once

#include <sstream>
#include <string>

namespace hobsharp {

inline std::string numberText(double v, int digits = 6) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

// A length in mm, as the messages write it: "12.5 mm".
inline std::string mmText(double v) { return numberText(v) + " mm"; }

}  // namespace hobsharp
