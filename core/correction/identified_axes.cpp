#include "identified_axes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include <Eigen/QR>
#include <Eigen/SVD>

#include "machine_resolution.h"
#include "number_text.h"

namespace hobsharp {
namespace {

// Samples of the motion range at which the axes' curves are judged.
constexpr int kSamples = 101;
// Singular values (in machine steps) below this share of the largest are directions the face
// does not show.
constexpr double kNull = 1e-10;
// A curve with more than this share of it in a direction the face does not show is not read alone.
constexpr double kLeak = 1e-6;
// The other axes of a combination mimic the first's face without their weakest directions, below
// this share of their largest singular value: no wild amounts for a last bit of likeness.
constexpr double kAlikeCutoff = 1e-6;
// Alike to this share is the same face.
constexpr double kSameFace = 0.999;
// How far the error's second-order face may move a value read, per value the identified error's
// own second-order face reads: on random hobs (seed 20261125, 300 hobs, 10 µm rms) the mean read
// lay within 3 uncertainties plus twice that of the true error's first-order reading for 325 of
// 327 values, plus once for 322 (docs/validation.md, "Against the true error").
constexpr double kSecondOrderMargin = 2;

const char* unitOf(Axis a) { return isRotary(a) ? "µrad" : "µm"; }

// Per axis, the columns of its free coefficients.
using Blocks = std::array<std::vector<int>, kAxisCount>;

// The motion range sampled where the axes' curves are judged: w^d at each of kSamples points
// (rows) for d = 0 .. the highest degree (columns), and each power's mean over the samples.
struct MotionSamples {
  Eigen::MatrixXd power;     // kSamples x (degree + 1)
  Eigen::RowVectorXd mean;   // the columns' means
};
MotionSamples motionSamples(const std::vector<Coefficient>& cs, double min, double max) {
  int degree = 0;
  for (const Coefficient& c : cs) degree = std::max(degree, c.degree);
  MotionSamples m;
  m.power.resize(kSamples, degree + 1);
  for (int i = 0; i < kSamples; ++i) {
    const double w = min + (max - min) * i / (kSamples - 1);
    m.power(i, 0) = 1;
    for (int d = 1; d <= degree; ++d) m.power(i, d) = m.power(i, d - 1) * w;
  }
  m.mean = m.power.colwise().mean();
  return m;
}

// A least-squares fit over some columns, in machine steps: its solution and covariance per unit
// noise variance (directions below kNull of `reference` left out).
struct Fit {
  std::vector<int> columns;
  Eigen::VectorXd x;    // per column
  Eigen::MatrixXd cov;  // per unit noise variance
  double misfit = 0;    // |data - A x|², µm²
  Eigen::VectorXd shift;  // the same solution of the second-order part (factorFace's y2), or empty
};

Eigen::MatrixXd columnsOf(const Eigen::MatrixXd& A, const std::vector<int>& columns) {
  Eigen::MatrixXd B(A.rows(), static_cast<int>(columns.size()));
  for (size_t k = 0; k < columns.size(); ++k) B.col(static_cast<int>(k)) = A.col(columns[k]);
  return B;
}

// The fit of B = A's `columns` from B's SVD (with U and V).
Fit fitFrom(const Eigen::JacobiSVD<Eigen::MatrixXd>& svd, const Eigen::MatrixXd& B, const Eigen::VectorXd& y,
            std::vector<int> columns, double reference, double cutoff, const Eigen::VectorXd& y2 = Eigen::VectorXd()) {
  Fit f;
  f.columns = std::move(columns);
  const int n = static_cast<int>(f.columns.size());
  const bool second = y2.size() == y.size() && y.size() > 0;
  f.x = Eigen::VectorXd::Zero(n);
  if (second) f.shift = Eigen::VectorXd::Zero(n);
  f.cov = Eigen::MatrixXd::Zero(n, n);
  const Eigen::VectorXd& s = svd.singularValues();
  const double floor = cutoff * (reference > 0 ? reference : (s.size() ? s(0) : 0.0));
  for (int i = 0; i < s.size(); ++i) {
    if (!(s(i) > floor)) continue;
    const Eigen::VectorXd v = svd.matrixV().col(i);
    f.x += v * (svd.matrixU().col(i).dot(y) / s(i));
    if (second) f.shift += v * (svd.matrixU().col(i).dot(y2) / s(i));
    f.cov += v * v.transpose() / (s(i) * s(i));
  }
  f.misfit = (y - B * f.x).squaredNorm();
  return f;
}

Fit fitColumns(const Eigen::MatrixXd& A, const Eigen::VectorXd& y, std::vector<int> columns, double reference,
               double cutoff = kNull, const Eigen::VectorXd& y2 = Eigen::VectorXd()) {
  if (columns.empty()) {
    Fit f;
    f.columns = std::move(columns);
    f.misfit = y.squaredNorm();
    return f;
  }
  const Eigen::MatrixXd B = columnsOf(A, columns);
  return fitFrom(Eigen::JacobiSVD<Eigen::MatrixXd>(B, Eigen::ComputeThinU | Eigen::ComputeThinV), B, y,
                 std::move(columns), reference, cutoff, y2);
}

// An axis's curve in a fit: its mean over the motion range (linear in the data, so its spread
// over repeated measurements is its standard deviation: a largest value over the range would fold
// the noise of the slope into it) and that mean's standard deviation per unit noise.
struct CurveFigures {
  double value = 0, perNoise = 0;
  double shift = 0;  // the value the second-order part alone reads (0 without one)
};
CurveFigures curveOf(const Fit& f, Axis a, const std::vector<Coefficient>& cs, const Eigen::VectorXd& step,
                     const MotionSamples& m) {
  CurveFigures c;
  const int n = static_cast<int>(f.columns.size());
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < n; ++k) {
    const int j = f.columns[static_cast<size_t>(k)];
    if (cs[static_cast<size_t>(j)].axis == a) g(k) = m.mean(cs[static_cast<size_t>(j)].degree) * step(j) * displayFactor(a);
  }
  c.value = g.dot(f.x);
  c.perNoise = std::sqrt(std::max(0.0, g.dot(f.cov * g)));
  if (f.shift.size() == n) c.shift = g.dot(f.shift);
  return c;
}

// "+8.03", "−0.42": signed, with `decimals` decimals (a minus sign, not a hyphen).
std::string signedText(double v, int decimals) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(decimals);
  s << std::abs(v);
  std::string t = s.str();
  const bool zero = t.find_first_not_of("0.") == std::string::npos;
  return (zero ? "" : v < 0 ? "\u2212" : "+") + t;
}

// Decimals that show an uncertainty u to 2 significant digits (0 to 4).
int decimalsFor(double u) {
  if (!(u > 0)) return 3;
  return std::clamp(1 - static_cast<int>(std::floor(std::log10(u))), 0, 4);
}

// "+8.03 ± 0.25 µm", and where the error's second-order face may move the value by more than the
// noise does: "+8.03 ± 0.25 µm (probe noise; the error's second order may move it up to 1.6 µm)".
std::string valueText(double v, double u, Axis a, double secondOrder = 0) {
  const int d = decimalsFor(u);
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(d);
  s << std::abs(u);
  std::string t = signedText(v, d) + " \u00b1 " + s.str() + " " + unitOf(a);
  if (secondOrder > u)
    t += " (probe noise; the error's second order may move it up to " + numberText(secondOrder, 2) + " " + unitOf(a) + ")";
  return t;
}

// 2 significant digits, signed: "−0.42", "+3.1", "+140".
std::string amountText(double v) {
  if (v == 0) return "0";
  const int d = std::clamp(1 - static_cast<int>(std::floor(std::log10(std::abs(v)))), 0, 6);
  return signedText(v, d);
}

std::string listText(const std::vector<std::string>& items) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i) {
    if (i > 0) s += i + 1 == items.size() ? " and " : ", ";
    s += items[i];
  }
  return s;
}

// The face's Jacobian in machine steps and the data, with the nuisance's directions taken out (the
// wheel identified alongside: what it can make tells nothing about the axes), reduced to the
// triangular factor of [A y] (Q^T [A y] = R): every fit of some of A's columns to y or to another
// column is the same on R, which has q + 1 rows, not a row per probe point (a 150 x 150 grid has
// 22,500). A coefficient outside the identifiable space `basis` (a straight gash's X, Y and B)
// moves nothing the first-order face shows: its column is set to 0 (its computed one is rounding
// and second order).
void factorFace(const Eigen::MatrixXd& S, const Eigen::VectorXd& step, const Eigen::MatrixXd& nuisance,
                const Eigen::VectorXd& data, const Eigen::MatrixXd& basis, Eigen::MatrixXd& A, Eigen::VectorXd& y,
                const Eigen::VectorXd* data2 = nullptr, Eigen::VectorXd* y2 = nullptr) {
  const int q = static_cast<int>(S.cols());
  A = S * step.asDiagonal();
  if (basis.rows() == q)
    for (int j = 0; j < q; ++j)
      if (basis.row(j).norm() < kLeak) A.col(j).setZero();
  y = data;
  const bool second = data2 && y2 && data2->size() == data.size();
  Eigen::VectorXd z = second ? *data2 : Eigen::VectorXd();
  if (nuisance.cols() > 0 && nuisance.rows() == S.rows()) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> ns(nuisance, Eigen::ComputeThinU);
    for (int i = 0; i < ns.singularValues().size(); ++i) {
      if (!(ns.singularValues()(i) > kNull * ns.singularValues()(0))) break;
      const Eigen::VectorXd u = ns.matrixU().col(i);
      A -= u * (u.transpose() * A);
      y -= u * u.dot(y);
      if (second) z -= u * u.dot(z);
    }
  }
  // A second data column rides along (its own row below y's, where y and A are 0): every fit of it
  // is the same linear map of it as of y.
  const int k = second ? 2 : 1;
  Eigen::MatrixXd Ay(A.rows(), q + k);
  if (second) Ay << A, y, z;
  else Ay << A, y;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Ay);
  const int rows = static_cast<int>(std::min<Eigen::Index>(Ay.rows(), q + k));
  const Eigen::MatrixXd R = qr.matrixQR().topRows(rows).triangularView<Eigen::Upper>();
  A = R.leftCols(q);
  y = R.col(q);
  if (second) *y2 = R.col(q + 1);
}

// The directions the face shows: the singular values above kNull of the largest.
int shownRank(const Eigen::VectorXd& s) {
  int rank = 0;
  while (rank < s.size() && s(rank) > kNull * s(0)) ++rank;
  return rank;
}

// Per axis, the standard deviation of its curve per µm of noise, largest over the samples, where
// the coordinates in machine steps have the covariance W W^T per unit noise variance. At a sample
// axis a's curve is g_a^T z (z the coefficients in machine steps, g_a their machine steps in µm or
// µrad times the sample's powers p_a): its variance g_a^T W W^T g_a = p_a^T (Wc_a Wc_a^T) p_a,
// Wc_a = diag(c_a) times W's rows at a, the matrix formed once; every sample at once (P_a's rows).
std::array<double, kAxisCount> spreadOverRange(const Eigen::MatrixXd& W, const std::vector<Coefficient>& cs,
                                               const Eigen::VectorXd& step, const MotionSamples& samples) {
  std::array<double, kAxisCount> spread{};
  if (W.cols() == 0) return spread;
  Blocks block;
  for (size_t j = 0; j < cs.size(); ++j) block[static_cast<int>(cs[j].axis)].push_back(static_cast<int>(j));
  for (int i = 0; i < kAxisCount; ++i) {
    const std::vector<int>& b = block[static_cast<size_t>(i)];
    const int n = static_cast<int>(b.size());
    if (n == 0) continue;
    Eigen::MatrixXd Wc(n, W.cols()), P(kSamples, n);
    for (int k = 0; k < n; ++k) {
      const Coefficient& c = cs[static_cast<size_t>(b[static_cast<size_t>(k)])];
      Wc.row(k) = W.row(b[static_cast<size_t>(k)]) * (step(b[static_cast<size_t>(k)]) * displayFactor(c.axis));
      P.col(k) = samples.power.col(c.degree);
    }
    const Eigen::MatrixXd G = Wc.lazyProduct(Wc.transpose());
    spread[static_cast<size_t>(i)] = std::sqrt(std::max(0.0, P.lazyProduct(G).cwiseProduct(P).rowwise().sum().maxCoeff()));
  }
  return spread;
}

}  // namespace

std::array<double, kAxisCount> axisSpreadPerNoise(const std::vector<Coefficient>& cs, const Eigen::VectorXd& step,
                                                  const StepDecomposition& made, double min, double max) {
  const int q = static_cast<int>(cs.size());
  const Eigen::VectorXd& s = made.singularValues;
  const Eigen::MatrixXd& V = made.directions;
  // (A face with fewer points than directions has fewer singular values than V has columns: its
  // first s.size() columns are the ones they belong to.)
  if (q == 0 || V.rows() != q || s.size() > V.cols() || !(s.size() && s(0) > 0)) return {};
  const int rank = shownRank(s);
  return spreadOverRange(V.leftCols(rank) * s.head(rank).cwiseInverse().asDiagonal(), cs, step,
                         motionSamples(cs, min, max));
}

std::array<double, kAxisCount> axisSpreadPerNoise(const std::vector<Coefficient>& cs, const Eigen::VectorXd& step,
                                                  const Eigen::MatrixXd& S, const Eigen::MatrixXd& nuisance,
                                                  double min, double max, const Eigen::MatrixXd& basis) {
  const int q = static_cast<int>(cs.size());
  if (q == 0 || S.rows() == 0 || S.cols() != q) return {};
  Eigen::MatrixXd A;
  Eigen::VectorXd y;
  factorFace(S, step, nuisance, Eigen::VectorXd::Zero(S.rows()), basis, A, y);
  // Over the directions sought: the identifiable space's (every coefficient without a basis).
  const Eigen::MatrixXd sought = basis.rows() == q ? basis : Eigen::MatrixXd::Identity(q, q);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A * sought, Eigen::ComputeFullV);
  return axisSpreadPerNoise(cs, step, StepDecomposition{svd.singularValues(), sought * svd.matrixV()}, min, max);
}

const char* readingName(AxisReading r) {
  switch (r) {
    case AxisReading::Alone: return "alone";
    case AxisReading::Together: return "together";
    case AxisReading::Unseen: return "unseen";
    case AxisReading::Locked: return "locked";
  }
  return "locked";
}

IdentifiedAxes identifiedAxes(const std::vector<Coefficient>& cs, const Eigen::VectorXd& step, const Eigen::MatrixXd& S,
                              const Eigen::MatrixXd& nuisance, const Eigen::VectorXd& data, double min, double max,
                              double sigma, const CorrectionOptions& o, const Eigen::MatrixXd& basis,
                              const StepDecomposition* made, const Eigen::VectorXd* secondOrder) {
  IdentifiedAxes out;
  const int q = static_cast<int>(cs.size());
  Blocks block;
  for (int j = 0; j < q; ++j) block[static_cast<int>(cs[static_cast<size_t>(j)].axis)].push_back(j);
  for (Axis a : kAxes)
    if (!block[static_cast<int>(a)].empty()) out.axes[static_cast<int>(a)].reading = AxisReading::Unseen;
  if (q == 0 || S.rows() == 0 || S.cols() != q || data.size() != S.rows()) return out;

  Eigen::MatrixXd A;
  Eigen::VectorXd y;
  Eigen::VectorXd y2;
  const bool second = secondOrder && secondOrder->size() == data.size();
  factorFace(S, step, nuisance, data, basis, A, y, second ? secondOrder : nullptr, second ? &y2 : nullptr);
  // A's decomposition: made already over the directions sought, or here (A's columns outside the
  // space are 0, so the same shown directions to rounding).
  const bool given = made && made->directions.rows() == q && made->singularValues.size() <= made->directions.cols() &&
                     nuisance.cols() == 0;
  Eigen::VectorXd s;
  Eigen::MatrixXd directions;  // q x q: the shown directions first, then the rest
  if (given) {
    s = made->singularValues;
  } else {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
    s = svd.singularValues();
    directions = svd.matrixV();
  }
  const double s0 = s.size() ? s(0) : 0.0;
  if (!(s0 > 0)) {
    for (Axis a : kAxes)
      if (!block[static_cast<int>(a)].empty()) out.unseen.push_back(a);
  }
  const int rank = shownRank(s);
  if (given && rank == 0) directions = Eigen::MatrixXd::Identity(q, q);
  if (given && rank > 0) {
    // The shown directions, then an orthonormal basis of what they leave (the directions outside
    // the space and those it shows below kNull).
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(made->directions.leftCols(rank));
    directions = qr.householderQ();
    directions.leftCols(rank) = made->directions.leftCols(rank);
  }
  // Every direction the face shows: the covariance per unit noise variance is W W^T; N spans the
  // combinations it does not show.
  const Eigen::MatrixXd W = directions.leftCols(rank) * s.head(rank).cwiseInverse().asDiagonal();
  const Eigen::MatrixXd N = directions.rightCols(q - rank);

  // Each axis alone: the information its own coefficients give (the others known). Its SVD is
  // also the least-squares fit of its columns alone (below: a group's member fitted alone when no
  // axis is read alone), so that fit is kept from it (U besides V changes neither S nor V).
  std::map<std::vector<int>, Fit> fits;
  std::array<Eigen::MatrixXd, kAxisCount> ownW, ownN;
  std::array<bool, kAxisCount> seen{};
  for (Axis a : kAxes) {
    const int i = static_cast<int>(a);
    const int n = static_cast<int>(block[i].size());
    if (n == 0 || !(s0 > 0)) continue;
    const Eigen::MatrixXd Aa = columnsOf(A, block[i]);
    // (With fewer rows than columns the fit's thin V is not the full V's columns to the bit.)
    const bool tall = Aa.rows() >= n;
    const Eigen::JacobiSVD<Eigen::MatrixXd> own(Aa, tall ? Eigen::ComputeThinU | Eigen::ComputeFullV : Eigen::ComputeFullV);
    if (tall) fits.emplace(block[i], fitFrom(own, Aa, y, block[i], s0, kNull, y2));
    int r = 0;
    while (r < own.singularValues().size() && own.singularValues()(r) > kNull * s0) ++r;
    seen[i] = r > 0;
    ownW[i] = own.matrixV().leftCols(r) * own.singularValues().head(r).cwiseInverse().asDiagonal();
    ownN[i] = own.matrixV().rightCols(n - r);
  }

  // Over the motion range: each axis's spread and multiple correlation, and each pair's correlation.
  std::array<bool, kAxisCount> leaks{};
  std::array<double, kAxisCount> correlation{};
  Eigen::MatrixXd pair = Eigen::MatrixXd::Zero(kAxisCount, kAxisCount);
  const MotionSamples samples = motionSamples(cs, min, max);
  std::array<double, kAxisCount> spread = spreadOverRange(W, cs, step, samples);
  for (int i = 0; i < kAxisCount; ++i)
    if (!seen[static_cast<size_t>(i)]) spread[static_cast<size_t>(i)] = 0;
  // The curves at a sample as functionals of the coefficients in machine steps, G (q x 5: column a
  // gives axis a's error there in µm or µrad), have one entry a row: axis a's column is c_a o p_a
  // over its own coefficients (c the machine steps in µm or µrad, p the sample's powers w^d). So
  // every figure at a sample is a quadratic form in the powers, its matrix formed once here:
  //   the covariance C = G^T W W^T G:  C(a, b) = p_a^T (Wc_a Wc_b^T) p_b, Wc_a = diag(c_a) W's rows at a;
  //   |N^T g_a|² = p_a^T (Nc_a Nc_a^T) p_a, likewise; |ownN_a^T g_a|², |ownW_a^T g_a|² with diag(c_a).
  std::array<Eigen::VectorXd, kAxisCount> scale, power;  // per axis, over its coefficients: c, p
  std::array<Eigen::MatrixXd, kAxisCount> Wc, unseenGram, ownUnseenGram, ownGram;
  for (int i = 0; i < kAxisCount; ++i) {
    const int n = static_cast<int>(block[i].size());
    Eigen::MatrixXd Nc(n, N.cols());
    Wc[i].resize(n, W.cols());
    scale[i].resize(n);
    power[i].resize(n);
    for (int k = 0; k < n; ++k) {
      const int j = block[i][static_cast<size_t>(k)];
      scale[i](k) = step(j) * displayFactor(cs[static_cast<size_t>(j)].axis);
      // (A matrix of no columns has no rows to take: Eigen's row() of it offsets a null pointer.)
      if (W.cols() > 0) Wc[i].row(k) = W.row(j) * scale[i](k);
      if (N.cols() > 0) Nc.row(k) = N.row(j) * scale[i](k);
    }
    unseenGram[i] = Nc * Nc.transpose();
    const auto scaled = [&](const Eigen::MatrixXd& V) -> Eigen::MatrixXd {
      if (V.rows() != n || V.cols() == 0) return Eigen::MatrixXd::Zero(n, n);
      const Eigen::MatrixXd cV = scale[i].asDiagonal() * V;
      return cV * cV.transpose();
    };
    ownUnseenGram[i] = scaled(ownN[i]);
    ownGram[i] = scaled(ownW[i]);
  }
  std::array<std::array<Eigen::MatrixXd, kAxisCount>, kAxisCount> gram;  // Wc_a Wc_b^T, a <= b
  for (int i = 0; i < kAxisCount; ++i)
    for (int k = i; k < kAxisCount; ++k) gram[i][k] = Wc[i] * Wc[k].transpose();
  // a^T M b over small vectors, without temporaries.
  const auto form = [](const Eigen::MatrixXd& M, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    double sum = 0;
    for (Eigen::Index r = 0; r < M.rows(); ++r) {
      double row = 0;
      for (Eigen::Index c = 0; c < M.cols(); ++c) row += M(r, c) * b(c);
      sum += a(r) * row;
    }
    return sum;
  };
  Eigen::MatrixXd C(kAxisCount, kAxisCount);
  for (int sample = 0; sample < kSamples; ++sample) {
    for (int i = 0; i < kAxisCount; ++i)
      for (int k = 0; k < power[i].size(); ++k)
        power[i](k) = samples.power(sample, cs[static_cast<size_t>(block[i][static_cast<size_t>(k)])].degree);
    // the curves' covariance at the sample, per unit noise variance
    for (int i = 0; i < kAxisCount; ++i)
      for (int k = i; k < kAxisCount; ++k) C(i, k) = C(k, i) = form(gram[i][k], power[i], power[k]);
    for (int i = 0; i < kAxisCount; ++i) {
      if (!seen[static_cast<size_t>(i)]) continue;
      const double g = scale[i].cwiseProduct(power[i]).norm();  // |G's column i|
      if (!(g > 0)) continue;
      const double leak2 = kLeak * g * kLeak * g;
      if (form(unseenGram[i], power[i], power[i]) > leak2) leaks[i] = true;
      if (ownN[i].cols() > 0 && form(ownUnseenGram[i], power[i], power[i]) > leak2) leaks[i] = true;
      const double conditional = form(ownGram[i], power[i], power[i]);
      if (C(i, i) > 0) correlation[i] = std::max(correlation[i], std::sqrt(std::max(0.0, 1 - conditional / C(i, i))));
      for (int k = i + 1; k < kAxisCount; ++k)
        if (C(i, i) > 0 && C(k, k) > 0)
          pair(i, k) = pair(k, i) = std::max(pair(i, k), std::abs(C(i, k)) / std::sqrt(C(i, i) * C(k, k)));
    }
  }
  // Axes that share a combination the face does not show belong together.
  Eigen::MatrixXi unseenTogether = Eigen::MatrixXi::Zero(kAxisCount, kAxisCount);
  for (int c = 0; c < N.cols(); ++c) {
    std::vector<int> in;
    for (int i = 0; i < kAxisCount; ++i) {
      double part = 0;
      for (int j : block[i]) part += N(j, c) * N(j, c);
      if (seen[static_cast<size_t>(i)] && std::sqrt(part) > kLeak) in.push_back(i);
    }
    for (int i : in)
      for (int k : in) unseenTogether(i, k) = 1;
  }

  for (Axis a : kAxes) {
    const int i = static_cast<int>(a);
    AxisIdentification& x = out.axes[i];
    out.spreadPerNoise[i] = spread[i];
    if (block[i].empty()) continue;
    x.spreadPerNoise = spread[i];
    x.correlation = leaks[i] ? 1.0 : correlation[i];
    if (!seen[i]) {
      x.reading = AxisReading::Unseen;
      if (std::find(out.unseen.begin(), out.unseen.end(), a) == out.unseen.end()) out.unseen.push_back(a);
      continue;
    }
    const double machineStep = o.resolution.inAxisUnit(a) * displayFactor(a);
    const bool sharp = spread[i] * sigma <= o.reading.maxUncertaintySteps * machineStep;
    x.reading = !leaks[i] && x.correlation < o.reading.maxCorrelation && sharp ? AxisReading::Alone
                                                                                : AxisReading::Together;
  }

  // The axes read together, grouped: connected by correlation or by a combination the face does
  // not show.
  std::array<int, kAxisCount> group{};
  std::iota(group.begin(), group.end(), 0);
  const auto root = [&](int i) {
    while (group[static_cast<size_t>(i)] != i) i = group[static_cast<size_t>(i)];
    return i;
  };
  const auto together = [&](int i) { return out.axes[static_cast<size_t>(i)].reading == AxisReading::Together; };
  for (int i = 0; i < kAxisCount; ++i)
    for (int k = i + 1; k < kAxisCount; ++k)
      if (together(i) && together(k) && (pair(i, k) >= o.reading.partnerCorrelation || unseenTogether(i, k)))
        group[static_cast<size_t>(root(k))] = root(i);
  std::vector<std::vector<int>> groups;
  for (int i = 0; i < kAxisCount; ++i) {
    if (!together(i)) continue;
    auto it = std::find_if(groups.begin(), groups.end(), [&](const std::vector<int>& g) { return root(g[0]) == root(i); });
    if (it == groups.end()) groups.push_back({i});
    else it->push_back(i);
  }

  // The axes read alone, and each group read as the member that alone grinds the face shown best.
  std::vector<int> aloneColumns;
  for (int i = 0; i < kAxisCount; ++i)
    if (out.axes[static_cast<size_t>(i)].reading == AxisReading::Alone)
      aloneColumns.insert(aloneColumns.end(), block[i].begin(), block[i].end());
  // A group is read as the member that alone grinds the face shown best (the least misfit, the
  // axes read alone fitted with it). The members grind alike, so the noise may choose between them:
  // the sentence names every member that alone grinds it as well to within the noise, each with the
  // value it would take (a linear fit each, so each value's spread is the noise's).
  // The fits below repeat their columns (with one group, each member's fit is made for the choice
  // of the representative, for the joint fit and again for the member's value): each set of
  // columns is fitted once, here, and its fit kept for this call.
  const auto fitOf = [&](const std::vector<int>& columns) -> const Fit& {
    auto it = fits.find(columns);
    if (it == fits.end()) it = fits.emplace(columns, fitColumns(A, y, columns, s0, kNull, y2)).first;
    return it->second;
  };
  std::vector<int> representative;
  for (const std::vector<int>& g : groups) {
    int best = g[0];
    double bestMisfit = 0;
    for (int m : g) {
      std::vector<int> members = aloneColumns;
      members.insert(members.end(), block[m].begin(), block[m].end());
      const double misfit = fitOf(members).misfit;
      if (m == g[0] || misfit < bestMisfit) best = m, bestMisfit = misfit;
    }
    representative.push_back(best);
  }
  std::vector<int> columns = aloneColumns;
  for (int r : representative) columns.insert(columns.end(), block[r].begin(), block[r].end());
  const Fit& joint = fitOf(columns);
  for (Axis a : kAxes) {
    AxisIdentification& x = out.axes[static_cast<int>(a)];
    if (x.reading != AxisReading::Alone) continue;
    const CurveFigures c = curveOf(joint, a, cs, step, samples);
    x.value = c.value;
    x.perNoise = c.perNoise;
    x.secondOrder = kSecondOrderMargin * std::abs(c.shift);
  }

  // Each group in words.
  for (size_t gi = 0; gi < groups.size(); ++gi) {
    const int r = representative[gi];
    const Axis ra = kAxes[static_cast<size_t>(r)];
    AxisCombination combination;
    combination.axes.push_back(ra);
    std::vector<int> others;
    for (int m : groups[gi])
      if (m != r) combination.axes.push_back(kAxes[static_cast<size_t>(m)]), others.push_back(m);
    const CurveFigures c = curveOf(joint, ra, cs, step, samples);
    combination.value = c.value;
    combination.perNoise = c.perNoise;
    combination.secondOrder = kSecondOrderMargin * std::abs(c.shift);
    // Each member alone: the fit with the axes read alone, the other groups as they are read and
    // that member.
    std::vector<double> misfit;
    for (Axis member : combination.axes) {
      const int m = static_cast<int>(member);
      std::vector<int> members = aloneColumns;
      for (size_t h = 0; h < representative.size(); ++h)
        if (h != gi) members.insert(members.end(), block[representative[h]].begin(), block[representative[h]].end());
      members.insert(members.end(), block[m].begin(), block[m].end());
      const Fit& f = fitOf(members);
      const CurveFigures mc = curveOf(f, member, cs, step, samples);
      combination.aloneValue.push_back(mc.value);
      combination.alonePerNoise.push_back(mc.perNoise);
      combination.aloneSecondOrder.push_back(kSecondOrderMargin * std::abs(mc.shift));
      misfit.push_back(f.misfit);
    }
    const double leastMisfit = *std::min_element(misfit.begin(), misfit.end());
    for (double m : misfit)
      combination.aloneListed.push_back(m - leastMisfit <= o.significance * o.significance * sigma * sigma);
    const auto a0 = std::find_if(block[r].begin(), block[r].end(),
                                 [&](int j) { return cs[static_cast<size_t>(j)].degree == 0; });
    // The face of +1 µm or µrad on the first axis, and the others' curves that grind it best.
    if (!others.empty() && a0 != block[r].end()) {
      const Eigen::VectorXd face = A.col(*a0) / (step(*a0) * displayFactor(ra));
      std::vector<int> otherColumns;
      for (int m : others) otherColumns.insert(otherColumns.end(), block[m].begin(), block[m].end());
      const Fit mimic = fitColumns(A, face, otherColumns, 0, kAlikeCutoff);
      combination.alike = face.norm() > 0 ? std::max(0.0, 1 - std::sqrt(mimic.misfit) / face.norm()) : 0;
      for (int m : others) combination.amounts.push_back(curveOf(mimic, kAxes[static_cast<size_t>(m)], cs, step, samples).value);
    }
    std::vector<std::string> names, otherNames;
    for (Axis a : combination.axes) names.push_back(axisName(a));
    for (size_t k = 1; k < names.size(); ++k) otherNames.push_back(names[k]);
    const std::string equivalent = valueText(combination.value, combination.perNoise * sigma, ra, combination.secondOrder) + " of " +
                                   axisName(ra) + "-equivalent, the " + axisName(ra) + " error that alone grinds it";
    std::ostringstream t;
    if (!others.empty()) {
      t << listText(names) << " together: ";
      if (combination.alike >= o.reading.alikeShare && !combination.amounts.empty()) {
        std::vector<std::string> parts;
        for (size_t k = 0; k < others.size(); ++k)
          parts.push_back(amountText(combination.amounts[k]) + " " + unitOf(kAxes[static_cast<size_t>(others[k])]) +
                          " on " + otherNames[k]);
        t << "+1 " << unitOf(ra) << " on " << axisName(ra);
        if (combination.alike >= kSameFace)
          t << " grinds the same face as " << listText(parts);
        else
          t << " grinds nearly the face of " << listText(parts) << " (alike to " << static_cast<int>(std::floor(100 * combination.alike))
            << " %)";
        t << ", so the face does not tell them apart";
      } else {
        t << "the face does not tell their errors apart";
      }
      t << ". It shows their combination: " << equivalent;
      std::vector<std::string> alike;
      for (size_t k = 1; k < combination.axes.size(); ++k)
        if (combination.aloneListed[k])
          alike.push_back(std::string(axisName(combination.axes[k])) + " alone with " +
                          valueText(combination.aloneValue[k], combination.alonePerNoise[k] * sigma, combination.axes[k],
                                    combination.aloneSecondOrder[k]));
      if (!alike.empty()) t << "; " << listText(alike) << " would grind it as well, to within the probe noise";
      t << ".";
    } else if (out.axes[static_cast<size_t>(r)].correlation >= o.reading.maxCorrelation) {
      t << axisName(ra) << ": the face does not tell its error from a mix of the other axes' errors. It shows "
        << equivalent << ".";
    } else {
      const double machineStep = o.resolution.inAxisUnit(ra) * displayFactor(ra);
      t << axisName(ra) << ": the face shows its error only vaguely (within \u00b1"
        << numberText(out.axes[static_cast<size_t>(r)].spreadPerNoise * sigma, 2) << " " << unitOf(ra)
        << " over every direction it shows, more than " << numberText(o.reading.maxUncertaintySteps, 3)
        << " machine steps of " << numberText(machineStep, 3) << " " << unitOf(ra) << "). It shows " << equivalent << ".";
    }
    combination.sentence = t.str();
    out.sentences.push_back(combination.sentence);
    out.combinations.push_back(std::move(combination));
  }
  if (!out.unseen.empty()) {
    std::vector<std::string> names;
    for (Axis a : out.unseen) names.push_back(axisName(a));
    const bool one = names.size() == 1;
    out.sentences.push_back(listText(names) + ": the face does not show " + (one ? "its error" : "their errors") +
                            " at all (a move of " + (one ? "that axis" : "one of them") +
                            " alone leaves it as it is), so " + (one ? "it is" : "they are") +
                            " not identified: the identified error there is 0.");
  }
  return out;
}

std::string backToNominalSentence(const std::vector<Axis>& changed, const std::array<double, kAxisCount>& change) {
  if (changed.empty()) return "";
  std::vector<std::string> parts;
  for (Axis a : changed) parts.push_back(std::string(axisName(a)) + " " + amountText(change[static_cast<size_t>(a)]) + " " + unitOf(a));
  const bool one = changed.size() == 1;
  return "The change proposed there (" + listText(parts) + ") only takes the run back to the nominal " +
         (one ? "axis" : "axes") + ": the face neither asks for it nor shows it, so where the run was set off nominal there on purpose, keep the run's " +
         (one ? "value" : "values") + ".";
}

}  // namespace hobsharp
