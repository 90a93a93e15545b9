#include "wheel_input.h"
#include "number_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dressed_wheel.h"
#include "units.h"
#include "wheel_profile.h"

namespace hobsharp {
namespace {

// The points of the conjugate profile the contact range is taken from (as Fig. 4 shows it).
constexpr int kContactRangePoints = 41;
// How far a given radius may lie past the contact range, mm (as a grid past the face).
constexpr double kRangeTolerance = 1e-3;

std::string at(const std::string& name, size_t i) { return name + "[" + std::to_string(i) + "]"; }

// A wheel's points as the engineer gave them, a wheel file (views/wheel-input.js), its points
// counted from 1; the field stays the case's path ("wheel.profileOffset.R[0]").
Error refuseWheel(const std::string& field, const std::string& reason) {
  return Error{field, "Wheel file: " + reason, ErrorCode::InvalidInput};
}
Error refuseWheelPoint(const std::string& field, size_t i, const std::string& reason) {
  return Error{at(field, i), "Wheel file, point " + std::to_string(i + 1) + ": " + reason, ErrorCode::InvalidInput};
}

// R strictly increasing, every value finite, at least 2 points.
Outcome<void> checkRadii(const std::vector<double>& R, const std::string& name) {
  if (R.size() < 2)
    return refuseWheel(name, "the spline needs at least 2 points; got " + std::to_string(R.size()) + ".");
  for (size_t i = 0; i < R.size(); ++i) {
    if (!std::isfinite(R[i])) return refuseWheelPoint(name, i, "R must be a finite number.");
    if (i > 0 && !(R[i] > R[i - 1]))
      return refuseWheelPoint(name, i, "R must be greater than the radius before it (" + numberText(R[i - 1]) + " mm); got " +
                                           exactText(R[i]) + " mm. Give the radii in increasing order.");
  }
  return success();
}

}  // namespace

Outcome<ContactRange> wheelContactRange(const SharpeningSetup& setup, double rootRadius, double outerRadius) {
  auto p = wheelProfile(setup.face, setup.universal, setup.normalSign,
                        evenRadii(rootRadius, outerRadius, kContactRangePoints));
  if (!p) return p.error();
  const auto [lo, hi] = std::minmax_element(p->R.begin(), p->R.end());
  return ContactRange{*lo, *hi};
}

Outcome<WheelSurface> resolveWheelSurface(const CaseInput& in, const SharpeningSetup& setup, double rootRadius,
                                          double outerRadius) {
  WheelSurface wheel;
  if (!in.wheelProfileOffset && !in.wheelMeasuredProfile) return wheel;
  auto range = wheelContactRange(setup, rootRadius, outerRadius);
  if (!range) return range.error();
  const std::string rangeText = numberText(range->min) + " to " + numberText(range->max) + " mm";

  if (in.wheelProfileOffset) {
    const WheelPointsInput& o = *in.wheelProfileOffset;
    const std::string R = "wheel.profileOffset.R", offset = "wheel.profileOffset.offset";
    if (auto r = checkRadii(o.R, R); !r) return r.error();
    std::vector<double> y;
    for (size_t i = 0; i < o.R.size(); ++i) {
      if (o.R[i] < range->min - kRangeTolerance || o.R[i] > range->max + kRangeTolerance)
        return refuseWheelPoint(R, i, "R = " + exactText(o.R[i]) + " mm lies outside the wheel's contact range: the wheel grinds "
                                      "the face from root to tip with the radii R = " + rangeText + ".");
      if (!std::isfinite(o.values[i])) return refuseWheelPoint(offset, i, "the offset must be a finite number.");
      if (std::abs(o.values[i]) > kMaxWheelOffset)
        return refuseWheelPoint(offset, i, "the offset must lie within ±" + numberText(kMaxWheelOffset) + " µm (10 mm); got " +
                                               exactText(o.values[i]) + " µm.");
      y.push_back(o.values[i] / kMicrometresPerMm);
    }
    wheel.offset = CubicSpline::notAKnot(o.R, std::move(y));
    return wheel;
  }

  // A measured wheel: projected onto the conjugate profile (dressed_wheel.h), searched over the
  // face's radii and a quarter of its depth past either end.
  const WheelPointsInput& m = *in.wheelMeasuredProfile;
  const std::string R = "wheel.measuredProfile.R", Z = "wheel.measuredProfile.Z";
  if (auto r = checkRadii(m.R, R); !r) return r.error();
  for (size_t i = 0; i < m.values.size(); ++i)
    if (!std::isfinite(m.values[i])) return refuseWheelPoint(Z, i, "Z must be a finite number.");
  // Where the equation of meshing has no solution a quarter of the depth past the tip (the wheel's
  // profile ends there: the page's own dresser path was refused on 10 of 299 random hobs, an
  // independent review), the search keeps closer to the face, down to the face itself.
  Outcome<ProjectedProfile> projected = Error{};
  double share = 0;
  for (double s : {0.25, 0.125, 0.05, 0.0}) {
    share = s;
    const double margin = s * (outerRadius - rootRadius);
    const double rLow = std::max(rootRadius - margin, 0.5 * (rootRadius + std::abs(setup.face.rakeOffset)));
    projected = projectOntoConjugateProfile(setup, m.R, m.values, rLow, outerRadius + margin, "wheel.measuredProfile");
    if (projected || projected.error().code != ErrorCode::Unsolvable) break;
  }
  if (!projected) {  // names the point in words, and the radii searched beside the face's own
    Error e = projected.error();
    e.message += " (The face runs from r = " + numberText(rootRadius) + " to " + numberText(outerRadius) + " mm; a wheel point is sought " +
                 (share == 0.25 ? std::string("a quarter of its depth past either end.)")
                  : share > 0 ? numberText(100 * share, 3) + " % of its depth past either end (the wheel's profile ends closer to the tip).)"
                              : std::string("on the face's own radii (the wheel's profile ends at the tip).)"));
    return e;
  }
  // The feet's radii in the order of the points, and covering the contact range.
  for (size_t i = 1; i < projected->R.size(); ++i)
    if (!(projected->R[i] > projected->R[i - 1]))
      return refuseWheelPoint(R, i, "projected onto the conjugate profile, this point falls at R = " + numberText(projected->R[i]) +
                                  " mm, not beyond the point before it (" + numberText(projected->R[i - 1]) +
                                  " mm): the measured profile folds back.");
  const double lo = projected->R.front(), hi = projected->R.back();
  if (lo > range->min + kRangeTolerance || hi < range->max - kRangeTolerance)
    return refuseWheel("wheel.measuredProfile", "the measured profile covers the conjugate wheel radii R = " + numberText(lo) + " to " + numberText(hi) +
                                               " mm only; the wheel grinds the face with R = " + rangeText +
                                               ". Measure the profile over the whole contact range.");
  for (size_t i = 0; i < projected->offset.size(); ++i)
    if (std::abs(projected->offset[i]) * kMicrometresPerMm > kMaxWheelOffset)
      return refuseWheelPoint(Z, i, "the point lies " + numberText(projected->offset[i]) + " mm from the conjugate profile, more than " +
                                  numberText(kMaxWheelOffset / kMicrometresPerMm) + " mm: not a profile of this wheel.");
  wheel.offset = CubicSpline::notAKnot(projected->R, projected->offset);
  return wheel;
}

}  // namespace hobsharp
