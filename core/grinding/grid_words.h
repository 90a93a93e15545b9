// A measured grid as the engineer names it (issue 22: never a JSON path in a message): "Measured
// grid" for `measured`, "Pass 2, measured grid" for `passes[1].measured` (the pass counted from 1,
// measuredWords), "Gash 2's topography" for `inspection.gashTopographies[1]`; a row and a
// value within it counted from 1. The field of a refusal stays the path, for the page to find it.
#pragma once

#include <cstddef>
#include <string>

#include "probe_points.h"

namespace hobsharp {

inline std::string gridWords(const std::string& name) {
  const std::string gash = "inspection.gashTopographies[";
  if (name.rfind(gash, 0) == 0) return "Gash " + std::to_string(std::stoul(name.substr(gash.size())) + 1) + "'s topography";
  return measuredWords(name) + " grid";
}
inline std::string gridRowWords(const std::string& name, std::size_t i) { return gridWords(name) + ", row " + std::to_string(i + 1); }
inline std::string gridValueWords(const std::string& name, std::size_t i, std::size_t j) {
  return gridRowWords(name, i) + ", value " + std::to_string(j + 1);
}

}  // namespace hobsharp
