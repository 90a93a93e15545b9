#include "hob_input.h"

#include <cmath>
#include <tuple>

#include "field_checks.h"
#include "number_text.h"
#include "units.h"

namespace hobsharp {

Outcome<void> checkHob(const HobInput& h) {
  for (auto [field, v, unit] : {std::tuple{"hob.normalModule", h.normalModule, "mm"},
                                std::tuple{"hob.outerDiameter", h.outerDiameter, "mm"},
                                std::tuple{"hob.pitchDiameter", h.pitchDiameter, "mm"},
                                std::tuple{"hob.gashDepth", h.gashDepth, "mm"},
                                std::tuple{"hob.length", h.length, "mm"}})
    if (auto r = positive(field, v, unit); !r) return r;
  if (auto r = finite("hob.rakeOffset", h.rakeOffset); !r) return r;
  if (!(h.normalPressureAngle > 0 && h.normalPressureAngle < 45))
    return refuse("hob.normalPressureAngle", "must lie between 0 and 45 deg; got " + exactText(h.normalPressureAngle) + " deg.");
  if (h.pitchDiameter >= h.outerDiameter)
    return refuse("hob.pitchDiameter", "must be smaller than hob.outerDiameter (" + numberText(h.outerDiameter) +
                                           " mm); got " + exactText(h.pitchDiameter) + " mm.");
  const double ra = h.outerDiameter / 2, rp = h.pitchDiameter / 2;
  if (h.gashDepth >= ra)
    return refuse("hob.gashDepth", "must be less than the hob radius (" + numberText(ra) + " mm); got " +
                                       exactText(h.gashDepth) + " mm.");
  if (ra - h.gashDepth >= rp)
    return refuse("hob.gashDepth", "the gash must reach below the pitch diameter: the root radius " +
                                       numberText(ra - h.gashDepth) + " mm is not below the pitch radius " +
                                       numberText(rp) + " mm.");
  if (std::abs(h.rakeOffset) >= rp)
    return refuse("hob.rakeOffset", "|e| must be less than the pitch radius (" + numberText(rp) + " mm); got " +
                                        exactText(h.rakeOffset) + " mm.");
  if (std::abs(h.rakeOffset) >= ra - h.gashDepth)
    return refuse("hob.rakeOffset", "|e| must be less than the gash root radius (" +
                                        numberText(ra - h.gashDepth) + " mm); got " + exactText(h.rakeOffset) + " mm.");
  // A lead or helix angle given with a straight gash is ignored (docs/case-format.md), as a case made
  // from a helical one by changing the gash keeps them; but not whatever its value (a helix angle
  // of -500 deg went through unremarked; an independent review).
  if (h.gashLead)
    if (auto r = positive("hob.gashLead", *h.gashLead, "mm"); !r) return r;
  if (h.gashHelixAngle && !(*h.gashHelixAngle > 0 && *h.gashHelixAngle < 90))
    return refuse("hob.gashHelixAngle", "must lie between 0 and 90 deg; got " + exactText(*h.gashHelixAngle) + " deg.");
  if (h.gash == GashKind::Helical) {
    if (!h.gashLead && !h.gashHelixAngle)
      return refuse("hob.gashLead", "a helical gash needs hob.gashLead or hob.gashHelixAngle.");
    if (h.gashLead && h.gashHelixAngle) {
      const double fromLead = helixAngleFromLead(*h.gashLead, rp) * kDegPerRad;
      if (std::abs(fromLead - *h.gashHelixAngle) > kHelixAngleAgreement)
        return refuse("hob.gashHelixAngle", numberText(*h.gashHelixAngle) + " deg disagrees with hob.gashLead " +
                                                numberText(*h.gashLead) + " mm, which gives " + numberText(fromLead) +
                                                " deg at the pitch diameter. Give one of the two.");
    }
  }
  return success();
}

ToothFace toothFace(const HobInput& h) {
  ToothFace f;
  f.gash = h.gash;
  f.pitchRadius = h.pitchDiameter / 2;
  f.rakeOffset = h.rakeOffset;
  if (h.gash == GashKind::Helical) {
    const double lead = h.gashLead ? *h.gashLead : leadFromHelixAngle(*h.gashHelixAngle * kRadPerDeg, f.pitchRadius);
    f.screwParameter = screwParameterFromLead(lead) * (h.hand == Hand::Left ? -1.0 : 1.0);
  }
  return f;
}

}  // namespace hobsharp
