#include "swept_volume_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "sharpening_job.h"

namespace hobsharp::oracle {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// docs/conventions.md §Frames.
Matrix3d Rx(double t) {
  const double c = std::cos(t), s = std::sin(t);
  Matrix3d m;
  m << 1, 0, 0, 0, c, -s, 0, s, c;
  return m;
}
Matrix3d Ry(double t) {
  const double c = std::cos(t), s = std::sin(t);
  Matrix3d m;
  m << c, 0, s, 0, 1, 0, -s, 0, c;
  return m;
}

double evalPoly(const Polynomial& p, double w) {
  double v = 0;
  for (int k = p.degree(); k >= 0; --k) v = v * w + p.a[static_cast<std::size_t>(k)];
  return v;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

OracleInput oracleInput(const SharpeningJob& job) {
  OracleInput in;
  in.face = job.setup.face;
  in.universal = job.setup.universal;
  in.machine = job.setup.machine;
  in.psiC = job.setup.universal.tilt;
  in.wheel = job.setup.wheel;
  in.rootRadius = job.rootRadius;
  in.outerRadius = job.outerRadius;
  in.wheelRadius = job.wheelRadius;
  return in;
}

SweptVolumeOracle::Line SweptVolumeOracle::line(double r, double x) const {
  const ToothFace& f = in_.face;
  const double e = f.rakeOffset, rp = f.pitchRadius;
  Line l;
  l.u = std::sqrt(r * r - e * e) - std::sqrt(rp * rp - e * e);
  const double y0 = std::sqrt(rp * rp - e * e) + l.u;
  if (f.helical()) {
    const double p = f.screwParameter;
    l.w = x / p;
    const double c = std::cos(l.w), s = std::sin(l.w);
    l.p = Vector3d(p * l.w, y0 * c - e * s, y0 * s + e * c);
    l.n = Vector3d(y0, p * s, -p * c);
  } else {
    l.w = x;
    l.p = Vector3d(x, y0, e);
    l.n = Vector3d(0, 0, -1);
  }
  l.n = normalSign_ * l.n.normalized();
  return l;
}

namespace {

// Eq. 3 at the motion 0: the hob point and normal in the wheel frame.
struct Contact {
  Vector3d r, n;
};
Contact contact(const OracleInput& in, double sign, double u, double w) {
  const ToothFace& f = in.face;
  const double e = f.rakeOffset, rp = f.pitchRadius;
  const double y0 = std::sqrt(rp * rp - e * e) + u;
  Vector3d p, n;
  if (f.helical()) {
    const double pp = f.screwParameter, c = std::cos(w), s = std::sin(w);
    p = Vector3d(pp * w, y0 * c - e * s, y0 * s + e * c);
    n = Vector3d(y0, pp * s, -pp * c);
  } else {
    p = Vector3d(w, y0, e);
    n = Vector3d(0, 0, -1);
  }
  const UniversalSettings& s = in.universal;
  const Matrix3d M = Rx(-s.tilt) * Ry(s.settingAngle.coefficient(0));
  const Matrix3d P = Rx(s.rotation.coefficient(0));
  Contact c;
  c.r = M * (P * p + Vector3d(s.axialMovement.coefficient(0), -s.centerDistance.coefficient(0), 0));
  c.n = sign * (M * (P * n)).normalized();
  return c;
}

double meshing(const Contact& c) { return -c.n.x() * c.r.y() + c.n.y() * c.r.x(); }

}  // namespace

std::optional<double> SweptVolumeOracle::contactW(double u, double guess) const {
  const bool helical = in_.face.helical();
  const double h = helical ? 1e-6 : 1e-4, limit = helical ? 0.2 : 10.0;
  double w = guess;
  for (int it = 0; it < 80; ++it) {
    const double f0 = meshing(contact(in_, normalSign_, u, w));
    const double fp = meshing(contact(in_, normalSign_, u, w + h));
    const double fm = meshing(contact(in_, normalSign_, u, w - h));
    const double d = (fp - fm) / (2 * h);
    if (!(std::abs(d) > 0)) return std::nullopt;
    double step = f0 / d;
    if (!std::isfinite(step)) return std::nullopt;
    step = std::clamp(step, -limit, limit);
    w -= step;
    if (std::abs(step) < 1e-15 * (1 + std::abs(w))) return w;
    if (it > 6 && std::abs(step) < 1e-13 * (1 + std::abs(w))) return w;
  }
  return std::nullopt;
}

std::optional<double> SweptVolumeOracle::nominalMotion(double r, double x) const {
  const Line l = line(r, x);
  auto w = contactW(l.u, 0.0);
  if (!w) return std::nullopt;
  return *w - l.w;
}

std::optional<SweptVolumeOracle::Meridian> SweptVolumeOracle::meridianAt(double u, double& wGuess) const {
  auto w = contactW(u, wGuess);
  if (!w) return std::nullopt;
  wGuess = *w;
  const Contact c = contact(in_, normalSign_, u, *w);
  Meridian m;
  m.R = std::hypot(c.r.x(), c.r.y());
  m.Z = c.r.z();
  m.nR = (c.n.x() * c.r.x() + c.n.y() * c.r.y()) / m.R;
  m.nZ = c.n.z();
  if (in_.wheel.hasOffset()) {
    const double delta = in_.wheel.value(m.R);
    m.R -= delta * m.nR;
    m.Z -= delta * m.nZ;
  }
  return m;
}

std::optional<SweptVolumeOracle> SweptVolumeOracle::make(const OracleInput& in, const OracleOptions& o) {
  SweptVolumeOracle w;
  w.in_ = in;
  w.o_ = o;
  // The outward orientation, fixed at the pitch point: against the wheel axis (conventions.md §Sign).
  w.normalSign_ = 1;
  w.normalSign_ = contact(in, 1.0, 0.0, 0.0).n.z() < 0 ? 1.0 : -1.0;
  const double e = in.face.rakeOffset, rp = in.face.pitchRadius;
  w.uRoot_ = std::sqrt(in.rootRadius * in.rootRadius - e * e) - std::sqrt(rp * rp - e * e);
  w.uTip_ = std::sqrt(in.outerRadius * in.outerRadius - e * e) - std::sqrt(rp * rp - e * e);
  const double depth = w.uTip_ - w.uRoot_;
  const double uLo = w.uRoot_ - o.extension * depth, uHi = w.uTip_ + o.extension * depth;
  const int N = o.profilePoints;
  std::vector<double> us(N);
  for (int k = 0; k < N; ++k) us[k] = uLo + (uHi - uLo) * k / (N - 1);
  // Continuation outwards from the node nearest the pitch point (u = 0).
  int k0 = 0;
  for (int k = 0; k < N; ++k)
    if (std::abs(us[k]) < std::abs(us[k0])) k0 = k;
  std::vector<std::optional<Meridian>> m(N), mp(N), mm(N);
  const double hu = 1e-5 * std::max(1.0, depth);
  auto fill = [&](int k, double& guess) {
    double g0 = guess;
    m[k] = w.meridianAt(us[k], g0);
    if (!m[k]) return false;
    guess = g0;
    double gp = g0, gm = g0;
    mp[k] = w.meridianAt(us[k] + hu, gp);
    mm[k] = w.meridianAt(us[k] - hu, gm);
    return mp[k].has_value() && mm[k].has_value();
  };
  double guess = 0;
  int lo = k0, hi = k0;
  if (!fill(k0, guess)) return std::nullopt;
  const double start = guess;
  for (int k = k0 + 1; k < N && fill(k, guess); ++k) hi = k;
  guess = start;
  for (int k = k0 - 1; k >= 0 && fill(k, guess); --k) lo = k;
  if (us[lo] > w.uRoot_ || us[hi] < w.uTip_) return std::nullopt;
  // Split where R(u) turns; each piece ascending in R.
  std::vector<double> dR(N), dZ(N);
  for (int k = lo; k <= hi; ++k) {
    dR[k] = (mp[k]->R - mm[k]->R) / (2 * hu);
    dZ[k] = (mp[k]->Z - mm[k]->Z) / (2 * hu);
  }
  int first = lo;
  for (int k = lo + 1; k <= hi; ++k) {
    const bool turn = k < hi && (dR[k] > 0) != (dR[k + 1] > 0);
    if (!turn && k < hi) continue;
    Piece p;
    for (int j = first; j <= k; ++j) {
      p.u.push_back(us[j]);
      p.R.push_back(m[j]->R);
      p.Z.push_back(m[j]->Z);
      p.dR.push_back(dR[j]);
      p.dZ.push_back(dZ[j]);
    }
    if (p.R.front() > p.R.back()) {
      std::reverse(p.u.begin(), p.u.end());
      std::reverse(p.R.begin(), p.R.end());
      std::reverse(p.Z.begin(), p.Z.end());
      std::reverse(p.dR.begin(), p.dR.end());
      std::reverse(p.dZ.begin(), p.dZ.end());
    }
    p.side = (m[(first + k) / 2]->nZ > 0 ? 1.0 : -1.0) * (o.bodyAlongNormal ? 1.0 : -1.0);
    const bool main = us[first] <= 0 && us[k] >= 0;
    if (p.R.size() >= 2 && (main || !o.mainPieceOnly)) w.pieces_.push_back(std::move(p));
    if (turn && us[k] > w.uRoot_ && us[k] < w.uTip_ && !w.turnU_) w.turnU_ = us[k];
    first = k;
  }
  return w;
}

std::optional<double> SweptVolumeOracle::turnU() const { return turnU_; }

std::optional<SweptVolumeOracle::PieceValue> SweptVolumeOracle::evaluate(const Piece& p, double rho) const {
  if (!(rho >= p.Rmin() && rho <= p.Rmax())) return std::nullopt;
  const auto it = std::upper_bound(p.R.begin(), p.R.end(), rho);
  std::size_t k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - p.R.begin()) - 1));
  k = std::min(k, p.R.size() - 2);
  const double h = p.u[k + 1] - p.u[k];
  const double R0 = p.R[k], R1 = p.R[k + 1], a0 = h * p.dR[k], a1 = h * p.dR[k + 1];
  const auto Rs = [&](double s, double& ds) {
    const double s2 = s * s, s3 = s2 * s;
    ds = (6 * s2 - 6 * s) * R0 + (3 * s2 - 4 * s + 1) * a0 + (-6 * s2 + 6 * s) * R1 + (3 * s2 - 2 * s) * a1;
    return (2 * s3 - 3 * s2 + 1) * R0 + (s3 - 2 * s2 + s) * a0 + (-2 * s3 + 3 * s2) * R1 + (s3 - s2) * a1;
  };
  double sLo = 0, sHi = 1;
  double s = R1 != R0 ? (rho - R0) / (R1 - R0) : 0.5;
  for (int i = 0; i < 60; ++i) {
    double ds;
    const double f = Rs(s, ds) - rho;
    if (f < 0) sLo = s; else sHi = s;
    double next = ds != 0 ? s - f / ds : 0.5 * (sLo + sHi);
    if (!(next > sLo && next < sHi)) next = 0.5 * (sLo + sHi);
    if (std::abs(next - s) < 1e-15) {
      s = next;
      break;
    }
    s = next;
  }
  double dRs;
  Rs(s, dRs);
  const double Z0 = p.Z[k], Z1 = p.Z[k + 1], b0 = h * p.dZ[k], b1 = h * p.dZ[k + 1];
  const double s2 = s * s, s3 = s2 * s;
  PieceValue v;
  v.Z = (2 * s3 - 3 * s2 + 1) * Z0 + (s3 - 2 * s2 + s) * b0 + (-2 * s3 + 3 * s2) * Z1 + (s3 - s2) * b1;
  const double dZs = (6 * s2 - 6 * s) * Z0 + (3 * s2 - 4 * s + 1) * b0 + (-6 * s2 + 6 * s) * Z1 + (3 * s2 - 2 * s) * b1;
  v.slope = dRs != 0 ? dZs / dRs : 0;
  v.u = p.u[k] + s * h;
  return v;
}

Eigen::Vector3d SweptVolumeOracle::toWheel(const Eigen::Vector3d& G, const AxisPolynomials& axes, double phi) const {
  const double X = evalPoly(axes[Axis::X], phi), Y = evalPoly(axes[Axis::Y], phi), Z = evalPoly(axes[Axis::Z], phi);
  const double A = evalPoly(axes[Axis::A], phi), B = evalPoly(axes[Axis::B], phi);
  // docs/errata.md §Eq. 7: q = T(0,0,-Z) Rx(-psi_c) T(0,0,-K2) Ry(B) [Rx(A) G + (X, -Y, -K1)].
  const Vector3d b = Rx(A) * G + Vector3d(X, -Y, -in_.machine.K1);
  Vector3d q = Rx(-in_.psiC) * (Ry(B) * b - Vector3d(0, 0, in_.machine.K2));
  q.z() -= Z;
  return q;
}

std::optional<SweptVolumeOracle::Crossing> SweptVolumeOracle::crossing(const Piece& p, const Vector3d& q0,
                                                                        const Vector3d& d) const {
  const double W = o_.window;
  const double Rcut = o_.cutAtRim ? std::min(p.Rmax(), in_.wheelRadius) : p.Rmax();
  if (Rcut <= p.Rmin()) return std::nullopt;
  // rho(t)^2 = a t^2 + b t + c.
  const double a = d.x() * d.x() + d.y() * d.y(), b = 2 * (q0.x() * d.x() + q0.y() * d.y()),
               c = q0.x() * q0.x() + q0.y() * q0.y();
  std::vector<std::pair<double, double>> intervals;
  if (a < 1e-300) {
    const double rho = std::sqrt(c);
    if (rho >= p.Rmin() && rho <= Rcut) intervals.push_back({-W, W});
  } else {
    const double discMax = b * b - 4 * a * (c - Rcut * Rcut);
    if (discMax < 0) return std::nullopt;
    const double t1 = (-b - std::sqrt(discMax)) / (2 * a), t2 = (-b + std::sqrt(discMax)) / (2 * a);
    const double discMin = b * b - 4 * a * (c - p.Rmin() * p.Rmin());
    std::vector<std::pair<double, double>> raw;
    if (discMin <= 0) {
      raw.push_back({t1, t2});
    } else {
      const double t3 = (-b - std::sqrt(discMin)) / (2 * a), t4 = (-b + std::sqrt(discMin)) / (2 * a);
      raw.push_back({t1, std::min(t2, t3)});
      raw.push_back({std::max(t1, t4), t2});
    }
    for (auto [lo, hi] : raw) {
      lo = std::max(lo, -W), hi = std::min(hi, W);
      if (hi > lo) intervals.push_back({lo, hi});
    }
  }
  const auto h = [&](double t) -> double {
    const Vector3d q = q0 + t * d;
    const double rho = std::hypot(q.x(), q.y());
    const double rc = std::clamp(rho, p.Rmin(), Rcut);
    auto v = evaluate(p, rc);
    if (!v) return -kInf;
    return (q.z() - v->Z) * p.side;
  };
  for (auto [lo, hi] : intervals) {
    if (h(lo) > 0) return Crossing{lo, lo > -W};
    constexpr int K = 16;
    double prev = lo;
    for (int i = 1; i <= K; ++i) {
      const double t = lo + (hi - lo) * i / K;
      if (h(t) > 0) {
        double a0 = prev, b0 = t;  // h(a0) <= 0 < h(b0): bisection with secant steps
        double fa = h(a0), fb = h(b0);
        for (int j = 0; j < 200 && b0 - a0 > 1e-14; ++j) {
          double m = (std::isfinite(fa) && fb != fa) ? a0 - fa * (b0 - a0) / (fb - fa) : 0.5 * (a0 + b0);
          if (!(m > a0 + 0.01 * (b0 - a0) && m < b0 - 0.01 * (b0 - a0))) m = 0.5 * (a0 + b0);
          const double fm = h(m);
          if (fm > 0) b0 = m, fb = fm; else a0 = m, fa = fm;
          if (std::abs(fm) < 1e-15) {
            a0 = b0 = m;
            break;
          }
        }
        return Crossing{0.5 * (a0 + b0), false};
      }
      prev = t;
    }
  }
  return std::nullopt;
}

std::optional<SweptVolumeOracle::Crossing> SweptVolumeOracle::reachAt(const Line& l, const AxisPolynomials& axes,
                                                                      double phi, int* piece) const {
  const double dir = o_.bodyAlongNormal ? 1.0 : -1.0;  // the search runs from the material into the wheel
  const Vector3d q0 = toWheel(l.p, axes, phi);
  const Vector3d d = toWheel(l.p + dir * l.n, axes, phi) - q0;
  if (o_.intersectPieces && pieces_.size() > 1) {
    // The first point of the window inside every piece that covers it: a scan, then bisection.
    const auto in = [&](double t) {
      const Vector3d q = q0 + t * d;
      return inside(std::hypot(q.x(), q.y()), q.z());
    };
    constexpr int kScan = 4000;
    double prev = -o_.window;
    if (in(prev)) return Crossing{prev, false};
    for (int i = 1; i <= kScan; ++i) {
      const double t = -o_.window + 2 * o_.window * i / kScan;
      if (in(t)) {
        double a = prev, b = t;
        while (b - a > 1e-13) {
          const double m = 0.5 * (a + b);
          if (in(m)) b = m; else a = m;
        }
        if (piece) *piece = -1;
        return Crossing{b, false};
      }
      prev = t;
    }
    return std::nullopt;
  }
  std::optional<Crossing> best;
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    auto c = crossing(pieces_[k], q0, d);
    if (c && (!best || c->t < best->t)) {
      best = c;
      if (piece) *piece = static_cast<int>(k);
    }
  }
  return best;
}

std::optional<double> SweptVolumeOracle::reach(const Line& l, const AxisPolynomials& axes, double phi, int* piece,
                                               double) const {
  auto c = reachAt(l, axes, phi, piece);
  if (!c) return std::nullopt;
  return (o_.bodyAlongNormal ? 1.0 : -1.0) * c->t;
}

bool SweptVolumeOracle::inside(double rho, double z) const {
  if (o_.cutAtRim && rho > in_.wheelRadius) return false;
  if (o_.intersectPieces && pieces_.size() > 1) {
    bool covered = false;
    for (const Piece& p : pieces_) {
      auto v = evaluate(p, rho);
      if (!v) continue;
      covered = true;
      if (!((z - v->Z) * p.side > 0)) return false;
    }
    return covered;
  }
  for (const Piece& p : pieces_) {
    auto v = evaluate(p, rho);
    if (v && (z - v->Z) * p.side > 0) return true;
  }
  return false;
}

SweptPoint SweptVolumeOracle::sweep(double r, double x, const AxisPolynomials& axes, double phiMin,
                                    double phiMax) const {
  SweptPoint out;
  const Line l = line(r, x);
  const int M = std::max(3, o_.motionSamples);
  std::vector<double> phis(M), ts(M);
  for (int k = 0; k < M; ++k) {
    phis[k] = phiMin + (phiMax - phiMin) * k / (M - 1);
    auto c = reachAt(l, axes, phis[k], nullptr);
    ts[k] = c ? c->t : kInf;
  }
  int best = 0;
  for (int k = 1; k < M; ++k)
    if (ts[k] < ts[best]) best = k;
  if (!std::isfinite(ts[best])) return out;
  // Local minima of the samples (plateaus counted once).
  std::vector<double> minima;
  for (int k = 0; k < M; ++k) {
    const double left = k > 0 ? ts[k - 1] : kInf, right = k + 1 < M ? ts[k + 1] : kInf;
    if (std::isfinite(ts[k]) && ts[k] < left && ts[k] <= right) minima.push_back(ts[k]);
  }
  std::sort(minima.begin(), minima.end());
  out.localMinima = static_cast<int>(minima.size());
  if (minima.size() > 1) out.secondMinimum = minima[1] - minima[0];
  out.atRangeEnd = best == 0 || best == M - 1;
  // Golden section on [phi_{k-1}, phi_{k+1}].
  const auto f = [&](double phi) {
    auto c = reachAt(l, axes, phi, nullptr);
    return c ? c->t : kInf;
  };
  double a = phis[std::max(0, best - 1)], b = phis[std::min(M - 1, best + 1)];
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c1 = b - g * (b - a), c2 = a + g * (b - a);
  double f1 = f(c1), f2 = f(c2);
  while (b - a > o_.motionTolerance) {
    if (f1 <= f2) {
      b = c2, c2 = c1, f2 = f1;
      c1 = b - g * (b - a), f1 = f(c1);
    } else {
      a = c1, c1 = c2, f1 = f2;
      c2 = a + g * (b - a), f2 = f(c2);
    }
  }
  double phi = f1 <= f2 ? c1 : c2;
  double t = std::min(f1, f2);
  if (ts[best] < t) phi = phis[best], t = ts[best];  // an end of the range
  const double dir = o_.bodyAlongNormal ? 1.0 : -1.0;
  out.found = true;
  out.t = dir * t;
  out.phi = phi;
  int piece = -1;
  auto c = reachAt(l, axes, phi, &piece);
  out.piece = piece;
  out.wall = c && c->wall;
  const Vector3d q = toWheel(l.p + t * dir * l.n, axes, phi);
  out.rho = std::hypot(q.x(), q.y());
  out.z = q.z();
  if (piece >= 0) {
    auto v = evaluate(pieces_[static_cast<std::size_t>(piece)], out.rho);
    if (v) out.u = v->u;
  }
  const double hphi = in_.face.helical() ? 1e-4 : 1e-2;
  out.curvature = dir * (f(phi + hphi) - 2 * t + f(phi - hphi)) / (hphi * hphi);
  out.atWindowEnd = std::abs(t) > 0.99 * o_.window;
  // A fine scan of the line on the material's side of t at the minimum: the wheel must not be there.
  const Vector3d q0 = toWheel(l.p, axes, phi), d = toWheel(l.p + dir * l.n, axes, phi) - q0;
  constexpr int kScan = 2000;
  for (int i = 0; i < kScan; ++i) {
    const double s = -o_.window + (t - 1e-7 + o_.window) * i / (kScan - 1);
    const Vector3d p = q0 + s * d;
    if (inside(std::hypot(p.x(), p.y()), p.z())) {
      out.lowerEntry = true;
      break;
    }
  }
  return out;
}

}  // namespace hobsharp::oracle
