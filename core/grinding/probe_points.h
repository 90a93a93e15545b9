// The points a measuring machine probed on the rake face, anywhere on it, in the machine's own
// order (docs/measured-points.md): radius r from the hob axis and axial position x, in mm.
// The alternative to a FaceGrid for simulating the ground face (ground_face.h): the correction's
// rows are then exactly these points, with nothing interpolated.
#pragma once

#include <vector>

namespace hobsharp {

struct ProbePoint {
  double r = 0, x = 0;  // mm
};

using ProbePoints = std::vector<ProbePoint>;

}  // namespace hobsharp
