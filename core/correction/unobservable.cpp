#include "unobservable.h"

#include <cmath>
#include <sstream>

namespace hobsharp {
namespace {

// k >= 2 in superscript digits (UTF-8), as the page and the verdict write units: rad/rad².
std::string superscript(int k) {
  static const char* const kDigits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                        "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string s;
  if (k > 1)
    for (char d : std::to_string(k)) s += kDigits[d - '0'];
  return s;
}

}  // namespace

std::string coefficientUnit(const Coefficient& c, bool helical) {
  std::string u = isRotary(c.axis) ? "rad" : "mm";
  if (c.degree == 0) return u;
  const std::string per = helical ? "rad" : "mm";
  return u + "/" + per + superscript(c.degree);
}

UnobservableCombination describedCombination(std::vector<Coefficient> coefficients, std::vector<double> amounts,
                                             bool helical) {
  UnobservableCombination u;
  u.coefficients = std::move(coefficients);
  u.amounts = std::move(amounts);
  // Express the amounts per unit of the first coefficient.
  const double first = u.amounts.front();
  std::ostringstream s;
  s.precision(6);
  for (size_t i = 0; i < u.amounts.size(); ++i) {
    u.amounts[i] /= first;
    if (i > 0) s << (u.amounts[i] < 0 ? " - " : " + ");
    else if (u.amounts[i] < 0) s << "-";
    s << std::abs(u.amounts[i]) << " " << coefficientUnit(u.coefficients[i], helical) << " on "
      << u.coefficients[i].name();
  }
  s << (u.amounts.size() == 1 ? ": no effect on the face" : ": these changes cancel on the face");
  if (u.amounts.size() == 2 && u.coefficients[0].axis == Axis::X && u.coefficients[1].axis == Axis::A &&
      u.coefficients[0].degree == u.coefficients[1].degree)
    s << " (an axial shift of a helicoid equals a turn of it)";
  u.description = s.str();
  return u;
}

}  // namespace hobsharp
