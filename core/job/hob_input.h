// The hob as the case gives it (`hob`, docs/case-format.md), its value rules, and the rake face
// it makes (Eqs. 1-2).
#pragma once

#include <optional>

#include "hob_relief.h"
#include "outcome.h"
#include "tooth_face.h"

namespace hobsharp {

struct HobInput {
  double normalModule = 0;         // mm
  double normalPressureAngle = 0;  // deg
  double outerDiameter = 0;        // d_a, mm
  double pitchDiameter = 0;        // d_p, mm
  double gashDepth = 0;            // mm, from the outer diameter
  double length = 0;               // mm
  double rakeOffset = 0;           // e, mm
  GashKind gash = GashKind::Helical;
  Hand hand = Hand::Right;
  std::optional<double> gashLead;        // L_c, mm, positive
  std::optional<double> gashHelixAngle;  // deg, at the pitch diameter
  HobReliefInput relief;                 // hob.gashes, hob.relief, hob.sideReliefAngle (the gear effect)
};

// How far the helix angle given by hob.gashLead may differ from hob.gashHelixAngle when the case
// gives both, deg.
constexpr double kHelixAngleAgreement = 0.01;

// Every size positive, the pitch diameter inside the outer one, the gash reaching below the pitch
// diameter, |e| inside the pitch and the gash root radii, and a helical gash's lead or helix angle
// (agreeing to kHelixAngleAgreement when both are given); the refusal names the hob.* field.
Outcome<void> checkHob(const HobInput& hob);

// The rake face of a checked hob (docs/conventions.md §Hand): the lead from hob.gashLead or, else,
// from hob.gashHelixAngle at the pitch diameter, its sign by the hand.
ToothFace toothFace(const HobInput& hob);

}  // namespace hobsharp
