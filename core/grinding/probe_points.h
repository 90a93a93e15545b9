// The points a measuring machine probed on the rake face, anywhere on it, in the machine's own
// order (docs/measured-points.md): radius r from the hob axis and axial position x, in mm.
// The alternative to a FaceGrid for simulating the ground face (ground_face.h): the correction's
// rows are then exactly these points, with nothing interpolated.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "outcome.h"

namespace hobsharp {

struct ProbePoint {
  double r = 0, x = 0;  // mm
};

using ProbePoints = std::vector<ProbePoint>;

// A measurement as the engineer names it: "Measured" for the case's own, "Pass 2, measured" for
// `passes[1]`'s (the pass counted from 1); "Measured points", "Pass 2, measured points" for its
// points; one point counted from 1: "Measured point 81" for the point k = 80.
inline std::string measuredWords(const std::string& field) {
  if (field.rfind("passes[", 0) == 0) {
    const std::size_t end = field.find(']');
    if (end != std::string::npos && end > 7) return "Pass " + std::to_string(std::stoul(field.substr(7, end - 7)) + 1) + ", measured";
  }
  return "Measured";
}
inline std::string pointsWords(const std::string& field) { return measuredWords(field) + " points"; }
inline std::string pointWords(const std::string& field, std::size_t k) {
  std::string w = pointsWords(field);
  return w.substr(0, w.size() - 1) + " " + std::to_string(k + 1);
}

// A refused point: the field is its path in the case ("measuredPoints[80]", for the page to find
// the input), the message names it in words ("Measured point 81: ...").
inline Error refusePoint(const std::string& field, std::size_t k, const std::string& reason,
                         ErrorCode code = ErrorCode::InvalidInput) {
  return Error{field + "[" + std::to_string(k) + "]", pointWords(field, k) + ": " + reason, code};
}
// A refused list of points: "Measured points: ...".
inline Error refusePoints(const std::string& field, const std::string& reason, ErrorCode code = ErrorCode::InvalidInput) {
  return Error{field, pointsWords(field) + ": " + reason, code};
}

}  // namespace hobsharp
