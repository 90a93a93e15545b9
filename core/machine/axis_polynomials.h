// The five CNC axes X, Y, Z (mm) and A, B (rad) as Maclaurin polynomials of the motion
// parameter w (Eq. 12), and their conversion from the universal settings (Eq. 9).
#pragma once

#include <array>
#include <string>

#include "polynomial.h"
#include "universal_settings.h"

namespace hobsharp {

enum class Axis { X = 0, Y = 1, Z = 2, A = 3, B = 4 };
constexpr int kAxisCount = 5;
constexpr std::array<Axis, kAxisCount> kAxes = {Axis::X, Axis::Y, Axis::Z, Axis::A, Axis::B};
constexpr int kMinDegree = 1;
constexpr int kMaxDegree = 6;

inline const char* axisName(Axis a) {
  static const char* names[] = {"X", "Y", "Z", "A", "B"};
  return names[static_cast<int>(a)];
}
inline bool isRotary(Axis a) { return a == Axis::A || a == Axis::B; }

// The machine constants of Eq. 7: K1 (O_d to O_e along z_e) and K2 (O_g to O_f along z_f), mm.
// The manual tilt psi_c equals the universal tilt eta.
struct MachineConstants {
  double K1 = 0;
  double K2 = 0;
};

struct AxisPolynomials {
  std::array<Polynomial, kAxisCount> axis;

  Polynomial& operator[](Axis a) { return axis[static_cast<int>(a)]; }
  const Polynomial& operator[](Axis a) const { return axis[static_cast<int>(a)]; }
  int degree() const { return axis[0].degree(); }
};

// Eq. 9, expanded by Eq. 12 from exact derivatives (truncated Taylor series):
//   A = phi_1, B = gamma_m, psi_c = eta,
//   X = L_t + K1 tan(gamma_m),
//   Y = E_t - (K1 sec(gamma_m) + K2) tan(eta),
//   Z = -sec(eta) sec(gamma_m) (K1 + K2 cos(gamma_m)).
AxisPolynomials cncAxisPolynomials(const UniversalSettings& s, const MachineConstants& m, int degree);

}  // namespace hobsharp
