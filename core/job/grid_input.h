// The grid as the case gives it (`grid`, docs/case-format.md; docs/conventions.md §Grid): its
// counts and extent, each defaulted when not given, and their value rules.
#pragma once

#include <optional>

#include "face_grid.h"
#include "outcome.h"

namespace hobsharp {

struct GridInput {
  std::optional<int> radial, axial;
  std::optional<double> rMin, rMax, xMin, xMax;  // mm
};

constexpr int kDefaultGridRadial = 5;
constexpr int kDefaultGridAxial = 9;
// The largest grid the calculator takes, per direction.
constexpr int kMaxGridLines = 201;
// How far a grid may reach past the face (root, tip, hob ends), mm.
constexpr double kGridTolerance = 1e-3;

// The face the grid may cover: from the gash root to the outer radius, and the hob's length
// centred at x = 0 or on the contact line at phi_1 = 0 (x = xCentre), mm.
struct FaceExtent {
  double rootRadius = 0, outerRadius = 0, length = 0, xCentre = 0;
};

// The grid, with the default counts and the whole face (centred on the contact line) where the
// case gives none; refused, naming the grid.* field, when it does not fit the face.
Outcome<FaceGrid> faceGrid(const GridInput& grid, const FaceExtent& face);

}  // namespace hobsharp
