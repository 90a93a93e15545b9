#include "correction.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/SVD>

namespace hobsharp {
namespace {

UnobservableCombination combination(const std::vector<Coefficient>& coefficients,
                                    const Eigen::VectorXd& scaledDirection,
                                    const Eigen::VectorXd& columnScale, bool helical, double listedShare) {
  UnobservableCombination u;
  const double largest = scaledDirection.cwiseAbs().maxCoeff();
  for (int j = 0; j < scaledDirection.size(); ++j) {
    if (std::abs(scaledDirection(j)) < listedShare * largest) continue;
    u.coefficients.push_back(coefficients[j]);
    u.amounts.push_back(scaledDirection(j) * columnScale(j));
  }
  return describedCombination(std::move(u.coefficients), std::move(u.amounts), helical);
}

}  // namespace

std::string lockedText(int degree, const CorrectionOptions& o) {
  std::string locked;
  for (Axis a : kAxes) {
    std::string some;  // the axis's locked coefficients, or the axis where all of them are
    bool all = true;
    for (int k = 0; k <= degree; ++k) {
      const Coefficient ck{a, k};
      if (isLocked(ck, o)) some += std::string(some.empty() ? "" : ", ") + ck.name();
      else all = false;
    }
    if (!some.empty()) locked += std::string(locked.empty() ? "" : ", ") + (all ? std::string(axisName(a)) : some);
  }
  return locked;
}

std::string allLockedText(double rms) {
  std::ostringstream v;
  v.precision(3);
  v << "No change proposed: every axis is locked (correction options), so the axes run stay as they are; unlock an "
       "axis to correct the face (" << rms << " µm rms measured).";
  return v.str();
}

std::string uncorrectableText(double share, const std::string& locked, const std::string& residual) {
  std::ostringstream v;
  v.precision(3);
  v << "Partly uncorrectable: " << 100 * share << " % of the sum of squares is a shape "
    << (locked.empty() ? "no axis polynomial produces (such as a second-degree shape along the radius)"
                       : "the axes left free do not produce (" + locked + " locked)")
    << "; it stays in the residual" << residual << ".";
  if (!locked.empty()) v << " Unlocking " << locked << " may correct part of it.";
  // Not every shape no axis makes is the wheel's (one that changes along the gash is not): the
  // wheel correction decides the split (wheel_correction.h).
  v << " A shape along the radius is the wheel profile's: the wheel correction (correction options) says how much of "
       "it a dressing removes; a shape that changes along the gash is neither the axes' nor the wheel's (check the "
       "measurement).";
  return v.str();
}

Outcome<Correction> correctionStep(const GroundFace& run, const AxisPolynomials& runAxes,
                                   const Eigen::MatrixXd& measured, const CorrectionOptions& o) {
  // The face's shape: the grid, or one column of probe points (ground_face.h).
  struct Shape {
    int r, c;
    int rows() const { return r; }
    int cols() const { return c; }
    int size() const { return r * c; }
  } const grid{run.rows(), run.cols()};
  if (measured.rows() != grid.rows() || measured.cols() != grid.cols())
    return refuse("measured", "the topography has " + std::to_string(measured.rows()) + " x " +
                                 std::to_string(measured.cols()) + " values; the grid is " +
                                 std::to_string(grid.rows()) + " radial x " +
                                 std::to_string(grid.cols()) + " axial.");
  if (!measured.allFinite()) return refuse("measured", "holds a value that is not a finite number.");

  Correction c;
  c.before = topographyFromNormal(run, measured);
  for (const Coefficient& k : allCoefficients(runAxes.degree()))
    if (!isLocked(k, o)) c.coefficients.push_back(k);
  const SensitivityMatrix S = sensitivityMatrix(run, c.coefficients);
  const int p = grid.size(), q = static_cast<int>(c.coefficients.size());
  const bool helical = run.gash == GashKind::Helical;

  // Eq. 16: p grid equations and the thickness at the mean point. The thickness row is the
  // derivative of the datum as c.before reads it from the measurement (topography.h: interpolated
  // at the grid's centre, or the probe nearest the mean point): each column's normal sensitivities
  // read the same way. On a grid with a node at the centre that is S.thickness (the mean point's
  // own sensitivity); elsewhere the two differ (Tab. 1's error at 12 probe points: a thickness
  // change of -15.74 µm by the datum's row, -15.89 µm by the mean point's; test_correction.cpp).
  Eigen::MatrixXd A(p + 1, q);
  A.topRows(p) = S.normal;
  for (int j = 0; j < q; ++j) {
    const Eigen::VectorXd column = S.normal.col(j);
    A(p, j) = thicknessFromNormal(run, Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
                                           column.data(), grid.rows(), grid.cols()));
  }
  Eigen::VectorXd d(p + 1);
  for (int i = 0; i < grid.rows(); ++i)
    for (int j = 0; j < grid.cols(); ++j) d(i * grid.cols() + j) = measured(i, j);
  d(p) = c.before.thickness;

  // Scale by the motion range (a_k w^k = b_k (w / range)^k, so a_k = b_k / range^k), then set
  // aside the negligible columns, then scale every other column to unit norm.
  Eigen::VectorXd scale(q);
  for (int j = 0; j < q; ++j) scale(j) = std::pow(S.motionRange, -c.coefficients[j].degree);
  Eigen::MatrixXd As = A * scale.asDiagonal();
  const double largest = q > 0 ? As.colwise().norm().maxCoeff() : 0.0;
  std::vector<int> active;
  for (int j = 0; j < q; ++j) {
    const double n = As.col(j).norm();
    if (n <= o.negligible * largest) {
      Eigen::VectorXd e = Eigen::VectorXd::Unit(q, j);
      c.unobservable.push_back(combination(c.coefficients, e, scale, helical, o.listedShare));
    } else {
      scale(j) /= n;
      active.push_back(j);
    }
  }
  As = A * scale.asDiagonal();
  Eigen::MatrixXd B(p + 1, static_cast<int>(active.size()));
  for (size_t k = 0; k < active.size(); ++k) B.col(k) = As.col(active[k]);

  c.change = Eigen::VectorXd::Zero(q);
  c.changeCovariancePerNoise = Eigen::MatrixXd::Zero(q, q);
  if (!active.empty()) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(B, Eigen::ComputeThinU | Eigen::ComputeThinV);
    c.singularValues = svd.singularValues();
    const double cut = o.truncation * c.singularValues(0);
    // See CorrectionOptions::amplification.
    const double limit = o.amplification * d.norm();
    Eigen::VectorXd y = Eigen::VectorXd::Zero(B.cols());
    Eigen::MatrixXd covY = Eigen::MatrixXd::Zero(B.cols(), B.cols());
    for (int i = 0; i < c.singularValues.size(); ++i) {
      if (c.singularValues(i) > cut) {
        const double alpha = svd.matrixU().col(i).dot(-d) / c.singularValues(i);
        if (std::abs(alpha) <= limit) {
          y += svd.matrixV().col(i) * alpha;
          covY += svd.matrixV().col(i) * svd.matrixV().col(i).transpose() /
                  (c.singularValues(i) * c.singularValues(i));
          ++c.rank;
        } else {
          ++c.amplifyingDropped;
        }
      } else {
        Eigen::VectorXd v = Eigen::VectorXd::Zero(q);
        for (size_t k = 0; k < active.size(); ++k) v(active[k]) = svd.matrixV()(k, i);
        c.unobservable.push_back(combination(c.coefficients, v, scale, helical, o.listedShare));
      }
    }
    for (size_t k = 0; k < active.size(); ++k) c.change(active[k]) = y(k) * scale(active[k]);
    c.changeCovariancePerNoise = Eigen::MatrixXd::Zero(q, q);
    for (size_t k = 0; k < active.size(); ++k)
      for (size_t l = 0; l < active.size(); ++l)
        c.changeCovariancePerNoise(active[k], active[l]) = covY(k, l) * scale(active[k]) * scale(active[l]);
  }

  // Listed by degree, then axis, so that X a0 against A a0 comes first.
  std::stable_sort(c.unobservable.begin(), c.unobservable.end(),
                   [](const UnobservableCombination& a, const UnobservableCombination& b) {
                     const Coefficient &x = a.coefficients.front(), &y = b.coefficients.front();
                     return x.degree != y.degree ? x.degree < y.degree : x.axis < y.axis;
                   });
  c.axes = runAxes;
  for (int j = 0; j < q; ++j) c.axes[c.coefficients[j].axis].a[c.coefficients[j].degree] += c.change(j);
  const Eigen::VectorXd after = d + A * c.change;
  Eigen::MatrixXd residual(grid.rows(), grid.cols());
  for (int i = 0; i < grid.rows(); ++i)
    for (int j = 0; j < grid.cols(); ++j) residual(i, j) = after(i * grid.cols() + j);
  c.after = topographyFromNormal(run, residual);
  c.after.thickness = after(p);
  c.uncorrectableShare = c.before.sse > 0 ? c.after.sse / c.before.sse : 0.0;
  std::ostringstream v;
  v.precision(3);
  if (c.coefficients.empty()) {
    v << allLockedText(c.before.rms);
  } else if (c.uncorrectableShare <= o.correctableShare) {
    v << "Correctable: the axes can cancel the measured deviation (predicted sum of squares "
      << c.after.sse << " µm², from " << c.before.sse << " µm²).";
  } else {
    v << uncorrectableText(c.uncorrectableShare, lockedText(runAxes.degree(), o), "");
  }
  c.verdict = v.str();
  return c;
}

}  // namespace hobsharp
