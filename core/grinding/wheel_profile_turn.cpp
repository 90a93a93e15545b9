#include "wheel_profile_turn.h"

#include "autodiff.h"
#include "number_text.h"
#include "wheel_contact.h"

namespace hobsharp {

double meridianSpeed(const ToothFace& face, const UniversalSettings& s, double normalSign, double u, double w) {
  const WheelContact<Dual<2>> c =
      wheelContact(face, s, normalSign, s.centerDistance.coefficient(0), variable<2>(u, 0), variable<2>(w, 1));
  const auto& f = c.meshing.derivatives();
  const double dwdu = -f(0) / f(1);  // along the contact line, Eq. 5
  const auto along = [dwdu](const Dual<2>& g) { return g.derivatives()(0) + g.derivatives()(1) * dwdu; };
  return along(c.R()) * c.n.z().value() - along(c.Z()) * c.nRadial().value();
}

std::optional<double> profileTurnRadius(const ToothFace& face, const UniversalSettings& s, double normalSign,
                                        const WheelProfile& profile) {
  const auto speedAt = [&](size_t k) {
    return meridianSpeed(face, s, normalSign, face.uAtRadius(profile.r[k]), profile.w[k]);
  };
  if (profile.r.empty()) return std::nullopt;
  double previous = speedAt(0);
  for (size_t k = 1; k < profile.r.size(); ++k) {
    const double speed = speedAt(k);
    if ((speed > 0) == (previous > 0) && speed != 0) {
      previous = speed;
      continue;
    }
    // Bisection in r between the profile points k - 1 and k, the contact followed by Eq. 5.
    double a = profile.r[k - 1], b = profile.r[k], wa = profile.w[k - 1], wb = profile.w[k];
    const bool startPositive = previous > 0;
    for (int it = 0; it < 60 && b - a > 1e-9; ++it) {  // 1e-9 mm: far below any grid's spacing
      const double r = 0.5 * (a + b);
      auto w = contactCoordinate(face, s, normalSign, face.uAtRadius(r), 0.5 * (wa + wb));
      if (!w) return a;  // the bracket's lower end: the band past the edge starts no higher
      if ((meridianSpeed(face, s, normalSign, face.uAtRadius(r), *w) > 0) == startPositive) a = r, wa = *w;
      else b = r, wb = *w;
    }
    return a;
  }
  return std::nullopt;
}

std::string wheelEdgeText(const WheelEdge& e) {
  return "The wheel cannot grind the top " + numberText(e.outerRadius - e.turnRadius, 2) +
         " mm of the face as designed: the conjugate wheel's profile turns back at the face radius r = " +
         mmText(e.turnRadius) + ", below the tip (r = " + mmText(e.outerRadius) +
         "), so the face above that radius lies past the edge of the wheel's envelope. The face figures above r = " +
         mmText(e.turnRadius) + " are not what the machine grinds; do not rely on them. A larger tilt or a smaller "
         "wheel moves the edge past the tip.";
}

std::string wheelEdgeVerdictText(const WheelEdge& e) {
  return "The top " + numberText(e.outerRadius - e.turnRadius, 2) + " mm of the face, above r = " + mmText(e.turnRadius) +
         ", lies past the edge of the wheel's envelope: the figures given for the face do not hold in that band, and "
         "the machine may leave part of it unground.";
}

}  // namespace hobsharp
