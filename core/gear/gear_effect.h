// The effect of the actual rake face on the gear (docs/gear-effect.md): for every
// tooth of the gash that lies whole on the face, each flank's cutting edge (cutting_edge.h) at
// evenly spaced radii over the active profile, and the generating profile it gives the gear with
// its figures (profile_figures.h); then the largest over the teeth and their scatter along the hob.
// A fine-pitch hob with more than 101 teeth on the grid is evaluated on its middle 101.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "actual_rake_face.h"
#include "cutting_edge.h"
#include "outcome.h"
#include "profile_figures.h"

namespace hobsharp {

// Points along the active profile.
constexpr int kGearProfilePoints = 21;

struct ToothEdges {
  double x = 0;                        // the tooth's centre along the hob axis, mm
  ProfileFigures left, right;          // per flank
  std::vector<double> leftProfile, rightProfile;  // the gear's profile deviation at `height`, µm
};

struct GearEffect {
  double reliefPerRadian = 0;  // k = K z / 2 pi, mm/rad
  double sideReliefAngle = 0;  // at the pitch radius, rad
  double rFrom = 0, rTo = 0;   // the hob radii of the active profile evaluated, mm
  std::vector<double> height;  // on the gear from its reference line, mm, root (-) to tip (+)
  std::vector<ToothEdges> teeth;  // along the hob
  // Over the teeth: the slope (and its pressure-angle error) of largest magnitude, signed; the
  // largest form; the slope's scatter (largest minus smallest), µm.
  ProfileFigures left, right;
  double leftScatter = 0, rightScatter = 0;
};

// `deviation` in µm on the grid r x x (docs/conventions.md §Grid), `reliefPerRadian` mm/rad.
// Refused, naming `gearEffect`, when no tooth fits on the grid or an edge cannot be found.
Outcome<GearEffect> gearEffect(const ToothFace& face, double normalSign, const std::vector<double>& r,
                               const std::vector<double>& x, const Eigen::MatrixXd& deviation, const BasicRack& rack,
                               double reliefPerRadian, int profilePoints = kGearProfilePoints);

}  // namespace hobsharp
