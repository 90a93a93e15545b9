// What the gear effect (docs/gear-effect.md) takes from the case: the hob's basic rack and its
// relief per radian k = K z / 2 pi, or the sentence that says what is missing for it.
#pragma once

#include "cutting_edge.h"
#include "hob_input.h"
#include "hob_relief.h"

namespace hobsharp {

struct GearPlan {
  BasicRack rack;         // normal module, normal pressure angle (rad), pitch radius (mm)
  ReliefPerRadian relief;  // mm/rad; or `missing` says why there is no gear effect
};

// The plan of a checked hob (checkHob; its relief is checked by the reader, case_json.cpp).
GearPlan gearPlan(const HobInput& hob);

}  // namespace hobsharp
