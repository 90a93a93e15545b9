// Hand-built rake faces for the inspection's tests (docs/inspection.md, "Radial alignment"), with
// nothing of FaceLines in them: the actual face is Eq. 2's face with another rake offset, turned
// about the hob axis; its normal deviations on the grid come from intersecting each nominal grid
// point's normal with it; the standard's reading from plane geometry in each transverse plane (the
// reference line is the nominal line turned through the actual face's tip point, and the indicator
// reads the actual line's distance across it).
#pragma once

#include <cmath>

#include <Eigen/Dense>

#include "face_grid.h"
#include "rotations.h"
#include "sharpening_setup.h"

namespace hobsharp::test {

inline Eigen::Vector3d turned(const Eigen::Vector3d& p, double angle) { return rotateX(p, std::cos(angle), std::sin(angle)); }

struct HandBuiltFace {
  ToothFace face;  // the actual face before the turn
  double theta = 0;

  Eigen::Vector3d point(double u, double w) const {
    return turned(face.point(u, w), theta);
  }
};

// The normal deviation (µm) of the hand-built face at a nominal grid point: p + t n on it.
inline double normalDeviation(const HandBuiltFace& a, const GridPoint& g) {
  Eigen::Vector3d z(g.u, g.w, 0);  // u, w of the actual face, t
  for (int it = 0; it < 50; ++it) {
    auto residual = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(a.point(v(0), v(1)) - g.p - v(2) * g.n); };
    const Eigen::Vector3d f = residual(z);
    if (f.norm() < 1e-12) break;
    Eigen::Matrix3d J;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d h = Eigen::Vector3d::Zero();
      h(k) = 1e-7 * (k == 1 && a.face.helical() ? 1e-2 : 1);
      J.col(k) = (residual(z + h) - residual(z - h)) / (2 * h(k));
    }
    z -= J.colPivHouseholderQr().solve(f);
  }
  return z(2) * 1e3;
}

// The standard's reading (µm) at radius r in the transverse plane at axial position x.
inline double standardReading(const SharpeningSetup& nominal, const HandBuiltFace& a, double rTip, double r, double x) {
  const ToothFace& f = nominal.face;
  auto polar = [](const Eigen::Vector3d& p) { return std::atan2(p.z(), p.y()); };
  auto line = [](double u0, double u1, auto point) { return std::pair{point(u0), point(u1)}; };
  // The actual line in the plane, by two of its points (Eq. 2 at fixed w is a straight line).
  const double w = a.face.wAtAxial(x);
  const auto [a0, a1] = line(-10, 10, [&](double u) { return a.point(u, w); });
  // Its point at the tip radius: on the line a0 + t (a1 - a0), |.|^2 = rTip^2 in the plane.
  const Eigen::Vector2d p0(a0.y(), a0.z()), dv(a1.y() - a0.y(), a1.z() - a0.z());
  const double qa = dv.squaredNorm(), qb = 2 * p0.dot(dv), qc = p0.squaredNorm() - rTip * rTip;
  const double t = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  const Eigen::Vector2d tip = p0 + t * dv;
  // The reference: the nominal line turned through the actual tip point.
  const GridPoint gTip = gridPoint(nominal, rTip, x), g = gridPoint(nominal, r, x);
  const double phi = std::atan2(tip.y(), tip.x()) - polar(gTip.p);
  const Eigen::Vector3d q3 = turned(g.p, phi), n3 = turned(g.n, phi);
  const Eigen::Vector3d along3 = turned(f.point(g.u + 1.0, g.w) - g.p, phi);
  Eigen::Vector2d across(-along3.z(), along3.y());
  across.normalize();
  if (across.dot(Eigen::Vector2d(n3.y(), n3.z())) < 0) across = -across;  // plus = outward, excess material
  // From q across the reference line to the actual line: q + s across = p0 + t dv.
  Eigen::Matrix2d m;
  m << across, -dv;
  const Eigen::Vector2d st = m.colPivHouseholderQr().solve(p0 - Eigen::Vector2d(q3.y(), q3.z()));
  return st(0) * 1e3;
}

// A face moved out of the tooth (excess material) by u mm, parallel, and turned by theta rad about
// the hob axis: its normal deviations on the grid (µm) and the standard's reading of largest
// magnitude over the grid (µm, signed).
struct HandBuiltInspection {
  Eigen::MatrixXd normal;
  double reading = 0;
};

inline HandBuiltInspection handBuiltInspection(const SharpeningSetup& setup, const FaceGrid& grid, double u, double theta) {
  HandBuiltFace a{setup.face, theta};
  // Eq. 2's offset e moves the line along (-sin beta, cos beta) in (y, z) (beta = 0 on a straight
  // gash): e grows by u or -u, whichever moves the face out of the tooth (along its outward normal).
  const GridPoint pitch = gridPoint(setup, setup.face.pitchRadius, 0);
  const double beta = setup.face.helical() ? pitch.w : 0;
  const double towardNormal = pitch.n.z() * std::cos(beta) - pitch.n.y() * std::sin(beta) > 0 ? 1 : -1;
  a.face.rakeOffset += towardNormal * u;
  HandBuiltInspection out;
  out.normal.resize(grid.rows(), grid.cols());
  for (int i = 0; i < grid.rows(); ++i) {
    for (int j = 0; j < grid.cols(); ++j) {
      out.normal(i, j) = normalDeviation(a, gridPoint(setup, grid.r[i], grid.x[j]));
      const double reading = standardReading(setup, a, grid.r.back(), grid.r[i], grid.x[j]);
      if (std::abs(reading) > std::abs(out.reading)) out.reading = reading;
    }
  }
  return out;
}

}  // namespace hobsharp::test
