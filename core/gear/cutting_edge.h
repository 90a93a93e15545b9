// A cutting edge of the hob: where the relieved thread flank meets the actual rake face
// (docs/gear-effect.md).
//
// The generating worm is taken as its basic rack wrapped about the hob axis: in the axial section,
// the flank of the tooth centred at x_c is x_f(R) = x_c -+ (S/2 - (R - r_p) tan alpha_n), S = pi m_n / 2
// (the left flank faces -x_1, the right flank +x_1). Behind the rake face by the angle psi the
// relieved profile lies k psi lower (hob_relief.h), so the relieved flank is
// X = x_f(R + k psi). The nominal face's edge has psi = 0 and lies on the basic rack; an edge on
// the actual face lies at psi = (angle of the nominal face - angle of the point) in the sense
// opposite to cutting, and its profile stands off the basic rack by -k psi sin(alpha_n) along the
// flank's normal (plus = excess material on the hob tooth).
#pragma once

#include "actual_rake_face.h"
#include "outcome.h"

namespace hobsharp {

// The hob's basic rack: normal module (mm), normal pressure angle (rad), reference (pitch) radius (mm).
struct BasicRack {
  double module = 0;
  double pressureAngle = 0;
  double pitchRadius = 0;
  double toothThickness() const;  // S = pi m_n / 2 on the reference line, mm
};

enum class Flank { Left, Right };  // facing -x_1, facing +x_1

// The nominal flank's axial position at radius R of the tooth centred at x_c, mm.
double flankAxial(const BasicRack& rack, double toothCentre, Flank flank, double R);

struct EdgePoint {
  double r = 0, x = 0;    // the nominal face point under the edge point, mm
  double behind = 0;      // psi, rad: how far behind the nominal face the edge point lies
  double deviation = 0;   // the generating profile's deviation at the edge, normal to the flank, mm
  int iterations = 0;
};

// The edge point at radius R from the hob axis: Newton's method on (r, x) for
//   |(y, z)| of the actual point = R,   its X = x_f(R + k psi).
// Refused (Unsolvable) when it does not converge.
Outcome<EdgePoint> cuttingEdgePoint(const ActualRakeFace& face, const BasicRack& rack, double reliefPerRadian,
                                    double toothCentre, Flank flank, double R);

}  // namespace hobsharp
