// A second method for the ground rake face, independent of the envelope condition (Eqs. 5, 6, 11):
// a swept-volume (material removal) simulation. It exists to test core/grinding/ against.
//
// What it shares with the library: only the inputs. The tooth face (r_p, e, p), the universal
// settings' constant parts (eta, gamma_m, E_t, L_t(0), phi_1(0)), the machine constants (K1, K2),
// the axis polynomials, and the dressing's offset spline delta(R) (the case's not-a-knot spline).
// Everything else is computed here from docs/conventions.md and docs/errata.md with plain Eigen:
// the face point and its normal line, the outward orientation, Eq. 3, the equation of meshing Eq. 5
// for the wheel's contact line (the wheel's definition), the inverse of the CNC chain Eq. 7.
//
// The method:
//   1. The wheel is a solid of revolution about z_t. Its meridian is the conjugate contact line of
//      Eq. 5 at the motion 0, solved here for a dense table of the line coordinate u (root to tip,
//      extended by a margin each way, as the library's analytic wheel is), dressed by
//      (R, Z) - delta(R) (n_R, n_Z). The table is split where R(u) turns; each monotone piece is a
//      graph Z_w(rho) (cubic Hermite in u), and its solid is the side of the graph the wheel's
//      normal points into ({(z - Z_w(rho)) n_Z > 0}, rho within the piece's range). The wheel is
//      the union of the pieces' solids.
//   2. For a grid point, the line G(t) = P + t n through the nominal face point along the outward
//      unit normal (docs/conventions.md §Sign), in the wheel frame at motion phi, is affine in t.
//      The wheel's reach along it at phi is the smallest t (within a window of +-window mm) at which
//      the line enters the wheel: t_c(phi).
//   3. The ground face is the union of the wheel's positions: the material left ends at
//      min over phi of t_c(phi). The motion is sampled densely over a range given by the caller,
//      then the minimum is refined by golden section and a last parabolic step, to 1e-9 rad (mm).
// The deviation is that t in mm (plus = excess material), as the library's.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "tooth_face.h"
#include "universal_settings.h"
#include "wheel_surface.h"

namespace hobsharp::oracle {

struct OracleOptions {
  int profilePoints = 3001;    // the wheel's meridian table, from the extended root to the extended tip
  double extension = 0.25;     // of the face depth, each way past root and tip (the analytic wheel)
  double window = 5.0;         // mm: the wheel's reach is sought for |t| <= window
  int motionSamples = 241;     // over the caller's motion range, ends included
  double motionTolerance = 1e-10;  // rad (helical) or mm (straight): the golden section's bracket
  // Which side of its meridian the wheel's body lies on. true: the side the face's outward normal
  // points to, as docs/conventions.md §Sign states ("n points out of the tooth material, into the
  // wheel"); false: the other side. The material is always on the side away from the wheel body,
  // and the deviation is reported along the library's n either way.
  bool bodyAlongNormal = true;
  // Cut the wheel at its rim (rho <= the wheel's radius): no wheel beyond the rim. Off, the
  // conjugate meridian is continued past the root as the library's analytic wheel is.
  bool cutAtRim = false;
  // Keep only the meridian's piece through the pitch point (the profile as dressed, up to where it
  // turns back, with an edge there). Off, every piece of the continued conjugate meridian is part of
  // the wheel (its sheets past a turn too): the analytic wheel, for diagnosis.
  bool mainPieceOnly = true;
  // With every piece (mainPieceOnly off): the wheel is the intersection of the pieces' solids (what a
  // dresser tracing the whole profile leaves: it removes whatever lies outside any branch) instead of
  // their union (the analytic surface taken as solid on every sheet).
  bool intersectPieces = false;
};

// The inputs, taken from a job (swept_volume_oracle.cpp: fromSetup).
struct OracleInput {
  ToothFace face;
  UniversalSettings universal;
  MachineConstants machine;
  double psiC = 0;           // rad (the universal tilt)
  WheelSurface wheel;        // only its offset spline(s) are used
  double rootRadius = 0, outerRadius = 0, wheelRadius = 0;  // mm
};

struct SweptPoint {
  bool found = false;
  double t = 0;              // mm: min over the motion of the wheel's reach along the normal line
  double phi = 0;            // the motion where the minimum lies
  double rho = 0, z = 0;     // the wheel point there (wheel frame, meridian)
  double u = 0;              // the meridian table's line coordinate of that wheel point
  int piece = -1;            // which monotone piece of the meridian reaches deepest
  double curvature = 0;      // d^2 t_c / d phi^2 at the minimum (finite differences)
  bool atRangeEnd = false;   // the minimum is at an end of the sampled motion range
  bool atWindowEnd = false;  // |t| near the window: the reach there is not the face's
  int localMinima = 0;       // distinct local minima of t_c over the samples
  double secondMinimum = 0;  // mm: how much less the next local minimum reaches (localMinima > 1)
  bool wall = false;         // the reach enters through the end of the meridian table, not its face
  bool lowerEntry = false;   // a fine scan of the line at the minimum found the wheel below t
};

class SweptVolumeOracle {
 public:
  static std::optional<SweptVolumeOracle> make(const OracleInput& in, const OracleOptions& options = {});

  // Nominal face point and outward unit normal at (r, x) (docs/conventions.md §Grid, §Sign).
  struct Line {
    Eigen::Vector3d p, n;
    double u = 0, w = 0;
  };
  Line line(double r, double x) const;
  double normalSign() const { return normalSign_; }

  // w*(u): the contact coordinate of the conjugate wheel's line at u (Eq. 5 at motion 0).
  std::optional<double> contactW(double u, double guess) const;
  // The nominal motion that grinds (r, x): w*(u) - w.
  std::optional<double> nominalMotion(double r, double x) const;

  // A hob point in the wheel frame S_t with the axes at motion phi (the inverse of Eq. 7).
  Eigen::Vector3d toWheel(const Eigen::Vector3d& G, const AxisPolynomials& axes, double phi) const;

  // The wheel's reach along the line at motion phi: the smallest t in the window where the line is
  // inside the wheel; nothing when it does not enter it there. `piece` gets the piece entered.
  std::optional<double> reach(const Line& l, const AxisPolynomials& axes, double phi, int* piece = nullptr,
                              double tGuess = 0.0) const;

  // The swept-volume face point at (r, x), the motion sampled over [phiMin, phiMax].
  SweptPoint sweep(double r, double x, const AxisPolynomials& axes, double phiMin, double phiMax) const;

  // Whether (rho, z) of the wheel frame's meridian plane lies inside the wheel (for checks).
  bool inside(double rho, double z) const;

  // The conjugate meridian's turn (dR/du changes sign) inside [root, tip]: its u, or nothing.
  std::optional<double> turnU() const;
  double uRoot() const { return uRoot_; }
  double uTip() const { return uTip_; }
  int pieces() const { return static_cast<int>(pieces_.size()); }

 private:
  struct Meridian {
    double R = 0, Z = 0, nR = 0, nZ = 0;
  };
  std::optional<Meridian> meridianAt(double u, double& wGuess) const;  // dressed
  struct Piece {
    std::vector<double> u, R, Z, dR, dZ;  // ascending in R; dR, dZ: d/du
    double side = 1;                       // sign of n_Z: inside when (z - Z_w) side > 0
    double Rmin() const { return R.front(); }
    double Rmax() const { return R.back(); }
  };
  struct PieceValue {
    double Z = 0, slope = 0, u = 0;  // Z_w(rho), dZ_w/drho, u
  };
  std::optional<PieceValue> evaluate(const Piece& p, double rho) const;
  struct Crossing {
    double t = 0;
    bool wall = false;
  };
  std::optional<Crossing> crossing(const Piece& p, const Eigen::Vector3d& q0, const Eigen::Vector3d& d) const;
  std::optional<Crossing> reachAt(const Line& l, const AxisPolynomials& axes, double phi, int* piece) const;

  OracleInput in_;
  OracleOptions o_;
  double normalSign_ = 1;
  double uRoot_ = 0, uTip_ = 0;
  std::vector<Piece> pieces_;
  std::optional<double> turnU_;
};

}  // namespace hobsharp::oracle

namespace hobsharp {
struct SharpeningJob;
namespace oracle {
// The oracle's inputs from a resolved job (its setup's face, settings, machine, wheel offset).
OracleInput oracleInput(const SharpeningJob& job);
}  // namespace oracle
}  // namespace hobsharp
