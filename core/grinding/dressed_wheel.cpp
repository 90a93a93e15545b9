#include "dressed_wheel.h"
#include "number_text.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "wheel_contact.h"

namespace hobsharp {
namespace {

// The conjugate profile's point and unit meridian normal at one tooth-face radius.
struct MeridianPoint {
  double r = 0, w = 0, R = 0, Z = 0, nR = 0, nZ = 0;
};

MeridianPoint meridianAt(const SharpeningSetup& s, double r, double w) {
  const WheelContact<double> c = wheelContact(s.face, s.universal, s.normalSign,
                                              s.universal.centerDistance.coefficient(0), s.face.uAtRadius(r), w);
  return {r, w, c.R(), c.Z(), c.nRadial(), c.n.z()};
}

Outcome<MeridianPoint> meridianAtRadius(const SharpeningSetup& s, double r, double wGuess) {
  auto w = contactCoordinate(s.face, s.universal, s.normalSign, s.face.uAtRadius(r), wGuess);
  if (!w) return w.error();
  return meridianAt(s, r, *w);
}

// Along the meridian tangent (nZ, -nR): zero where the normal through p passes through (R, Z).
double along(const MeridianPoint& p, double R, double Z) { return (R - p.R) * p.nZ - (Z - p.Z) * p.nR; }

}  // namespace

DressedProfile dressedProfile(const SharpeningSetup& setup, const WheelProfile& conjugate) {
  DressedProfile d;
  for (size_t k = 0; k < conjugate.r.size(); ++k) {
    const MeridianPoint p = meridianAt(setup, conjugate.r[k], conjugate.w[k]);
    const double delta = setup.wheel.value(p.R);
    d.r.push_back(p.r);
    d.R.push_back(p.R);
    d.offset.push_back(delta);
    d.dressedR.push_back(p.R - delta * p.nR);  // wheel_surface.h: p - delta n
    d.dressedZ.push_back(p.Z - delta * p.nZ);
  }
  return d;
}

Outcome<ProjectedProfile> projectOntoConjugateProfile(const SharpeningSetup& setup, const std::vector<double>& R,
                                                      const std::vector<double>& Z, double rLow, double rHigh,
                                                      const std::string& field) {
  // The conjugate profile sampled, then each point's foot bracketed and refined by the Illinois
  // variant of regula falsi in the tooth-face radius.
  constexpr int kSamples = 81;
  auto sampled = wheelProfile(setup.face, setup.universal, setup.normalSign, evenRadii(rLow, rHigh, kSamples));
  if (!sampled) return sampled.error();
  std::vector<MeridianPoint> samples;
  for (int k = 0; k < kSamples; ++k) samples.push_back(meridianAt(setup, sampled->r[k], sampled->w[k]));
  ProjectedProfile out;
  for (size_t i = 0; i < R.size(); ++i) {
    // Of the brackets, the one whose foot lies nearest the point.
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int k = 0; k + 1 < kSamples; ++k) {
      const double ga = along(samples[k], R[i], Z[i]), gb = along(samples[k + 1], R[i], Z[i]);
      if (ga * gb > 0) continue;
      const double d = std::hypot(R[i] - samples[k].R, Z[i] - samples[k].Z);
      if (d < bestDistance) bestDistance = d, best = k;
    }
    const std::string name = field + "[" + std::to_string(i) + "]";
    if (best < 0)  // the wheel file's point, counted from 1 (as wheel_input.cpp words them)
      return Error{name, "Wheel file, point " + std::to_string(i + 1) + ": (R = " + mmText(R[i]) + ", Z = " + mmText(Z[i]) +
                              ") has no foot on the wheel's conjugate profile (Eq. 6) between the face radii " +
                              mmText(rLow) + " and " + mmText(rHigh) + ": it is not a point of this wheel's profile.",
                   ErrorCode::InvalidInput};
    MeridianPoint a = samples[best], b = samples[best + 1];
    double ga = along(a, R[i], Z[i]), gb = along(b, R[i], Z[i]);
    MeridianPoint p = std::abs(ga) < std::abs(gb) ? a : b;
    int side = 0;
    for (int it = 0; it < 100 && std::abs(b.r - a.r) > 1e-13 * (1 + std::abs(a.r)); ++it) {
      if (ga == 0) { p = a; break; }
      if (gb == 0) { p = b; break; }
      const double r = (a.r * gb - b.r * ga) / (gb - ga);
      auto m = meridianAtRadius(setup, r, a.w + (b.w - a.w) * (r - a.r) / (b.r - a.r));
      if (!m) return m.error();
      p = *m;
      const double g = along(p, R[i], Z[i]);
      if (std::abs(g) < 1e-14) break;  // mm
      if ((g > 0) == (ga > 0)) {
        a = p, ga = g;
        if (side == -1) gb /= 2;
        side = -1;
      } else {
        b = p, gb = g;
        if (side == 1) ga /= 2;
        side = 1;
      }
    }
    out.r.push_back(p.r);
    out.R.push_back(p.R);
    out.offset.push_back(-((R[i] - p.R) * p.nR + (Z[i] - p.Z) * p.nZ));
  }
  return out;
}

}  // namespace hobsharp
