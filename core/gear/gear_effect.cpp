#include "gear_effect.h"

#include <algorithm>
#include <cmath>

#include "hob_relief.h"
#include "number_text.h"

namespace hobsharp {
namespace {

// The least active profile taken, as a share of the module.
constexpr double kLeastActiveShare = 0.2;
// The most teeth either side of the middle one (a fine-pitch hob evaluates its middle 101 teeth).
constexpr double kMostTeethEitherSide = 50;

void keepLargest(ProfileFigures& kept, const ProfileFigures& f, bool first) {
  if (first || std::abs(f.slope) > std::abs(kept.slope)) {
    kept.slope = f.slope;
    kept.pressureAngle = f.pressureAngle;
  }
  kept.form = first ? f.form : std::max(kept.form, f.form);
}

}  // namespace

Outcome<GearEffect> gearEffect(const ToothFace& face, double normalSign, const std::vector<double>& r,
                               const std::vector<double>& x, const Eigen::MatrixXd& deviation, const BasicRack& rack,
                               double reliefPerRadian, int profilePoints) {
  GearEffect out;
  out.reliefPerRadian = reliefPerRadian;
  out.sideReliefAngle = sideReliefAngleAt(reliefPerRadian, rack.pitchRadius, rack.pressureAngle);
  // The active profile: one module either side of the reference line, within the measured radii.
  out.rFrom = std::max(rack.pitchRadius - rack.module, r.front());
  out.rTo = std::min(rack.pitchRadius + rack.module, r.back());
  if (out.rTo - out.rFrom < kLeastActiveShare * rack.module)
    return refuse("gearEffect", "the grid's radii (" + mmText(r.front()) + " to " + mmText(r.back()) +
                                    ") hold too little of the active profile (" + mmText(rack.pitchRadius - rack.module) +
                                    " to " + mmText(rack.pitchRadius + rack.module) + ").");
  // The teeth of the gash, one axial pitch pi m_n apart about the middle of the grid, whose edges
  // lie on the grid over the whole active profile.
  const double pitch = kPi * rack.module;
  const double halfWidth = rack.toothThickness() / 2 + (rack.pitchRadius - out.rFrom) * std::tan(rack.pressureAngle);
  const double middle = 0.5 * (x.front() + x.back());
  const int reach = static_cast<int>(
      std::min(kMostTeethEitherSide, std::floor((0.5 * (x.back() - x.front()) - halfWidth) / pitch + 1e-9)));
  if (reach < 0)
    return refuse("gearEffect", "the grid's axial span (" + mmText(x.front()) + " to " + mmText(x.back()) +
                                    ") is narrower than one tooth of the hob (" + mmText(2 * halfWidth) + ").");
  const ActualRakeFace actual(face, normalSign, r, x, deviation);
  for (int k = 0; k < profilePoints; ++k)  // the gear's root (the hob's tip) first
    out.height.push_back(rack.pitchRadius - out.rTo + (out.rTo - out.rFrom) * k / (profilePoints - 1));
  for (int t = -reach; t <= reach; ++t) {
    ToothEdges tooth;
    tooth.x = middle + t * pitch;
    for (Flank flank : {Flank::Left, Flank::Right}) {
      std::vector<double>& profile = flank == Flank::Left ? tooth.leftProfile : tooth.rightProfile;
      for (double h : out.height) {
        auto e = cuttingEdgePoint(actual, rack, reliefPerRadian, tooth.x, flank, rack.pitchRadius - h);
        if (!e) return e.error();
        // The hob tooth's excess material is the gear's deficit.
        profile.push_back(-e->deviation * 1e3);
      }
      (flank == Flank::Left ? tooth.left : tooth.right) = profileFigures(out.height, profile, rack.pressureAngle);
    }
    out.teeth.push_back(std::move(tooth));
  }
  double loL = 0, hiL = 0, loR = 0, hiR = 0;
  for (std::size_t t = 0; t < out.teeth.size(); ++t) {
    const ToothEdges& tooth = out.teeth[t];
    keepLargest(out.left, tooth.left, t == 0);
    keepLargest(out.right, tooth.right, t == 0);
    loL = t == 0 ? tooth.left.slope : std::min(loL, tooth.left.slope);
    hiL = t == 0 ? tooth.left.slope : std::max(hiL, tooth.left.slope);
    loR = t == 0 ? tooth.right.slope : std::min(loR, tooth.right.slope);
    hiR = t == 0 ? tooth.right.slope : std::max(hiR, tooth.right.slope);
  }
  out.leftScatter = hiL - loL;
  out.rightScatter = hiR - loR;
  return out;
}

}  // namespace hobsharp
