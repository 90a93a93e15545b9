#include "grid_input.h"

#include <cmath>
#include <string>
#include <utility>

#include "field_checks.h"
#include "number_text.h"

namespace hobsharp {

Outcome<FaceGrid> faceGrid(const GridInput& g, const FaceExtent& face) {
  const int radial = g.radial.value_or(kDefaultGridRadial), axial = g.axial.value_or(kDefaultGridAxial);
  for (auto [field, n] : {std::pair{"grid.radial", radial}, std::pair{"grid.axial", axial}})
    if (n < 2 || n > kMaxGridLines)
      return refuse(field, "must be a whole number from 2 to " + std::to_string(kMaxGridLines) + "; got " +
                               std::to_string(n) + ".");
  const double half = face.length / 2, xCentre = face.xCentre;
  const double rMin = g.rMin.value_or(face.rootRadius), rMax = g.rMax.value_or(face.outerRadius);
  const double xMin = g.xMin.value_or(xCentre - half), xMax = g.xMax.value_or(xCentre + half);
  for (auto [field, v] : {std::pair{"grid.rMin", rMin}, std::pair{"grid.rMax", rMax},
                          std::pair{"grid.xMin", xMin}, std::pair{"grid.xMax", xMax}})
    if (auto r = finite(field, v); !r) return r.error();
  if (rMin < face.rootRadius - kGridTolerance)
    return refuse("grid.rMin", numberText(rMin) + " mm lies below the gash root (radius " + numberText(face.rootRadius) + " mm).");
  if (rMax > face.outerRadius + kGridTolerance)
    return refuse("grid.rMax", numberText(rMax) + " mm lies beyond the hob's outer radius (" + numberText(face.outerRadius) + " mm).");
  if (rMin >= rMax) return refuse("grid.rMax", "must be greater than grid.rMin (" + numberText(rMin) + " mm).");
  if (xMin >= xMax) return refuse("grid.xMax", "must be greater than grid.xMin (" + numberText(xMin) + " mm).");
  // The face spans the hob length: centred on the hob (x = 0) or, as the default grid is, on the
  // contact line at phi_1 = 0 (x = xCentre); either is accepted.
  const double tol = kGridTolerance * (1 + face.length);
  const double reach = half + std::abs(xCentre) + tol;
  if (xMax - xMin > 2 * half + tol || xMin < -reach || xMax > reach)
    return refuse(xMin < -reach ? "grid.xMin" : "grid.xMax",
                  "the grid (x = " + numberText(xMin) + " to " + numberText(xMax) + " mm) reaches past the hob's ends: the face is " +
                      numberText(2 * half) + " mm long, centred at x = 0 or on the contact line at x = " + numberText(xCentre) + " mm.");
  return FaceGrid::even(radial, axial, rMin, rMax, xMin, xMax);
}

}  // namespace hobsharp
