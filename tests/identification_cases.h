// The hobs, machine errors, probe noise and dense grids of the identification tests
// (test_identification.cpp): each test makes its own error and judges the re-simulated face.
#pragma once

#include <cmath>
#include <random>

#include <Eigen/SVD>

#include "correction.h"
#include "structural_null_space.h"
#include "test_support.h"

namespace hobsharp::test {

// A left-hand hob with a rake offset: the paper's, mirrored, e = +2 mm.
inline CaseInput leftHandRakeCase() {
  CaseInput c = paperCase();
  c.hob.hand = Hand::Left;
  c.hob.rakeOffset = 2.0;
  return test::withDerivedSetup(c);
}

// A module-2 fine-pitch hob: d_a 32 mm, gash lead 1943 mm, 6 x 9 grid.
inline CaseInput module2Case() {
  CaseInput c = paperCase();
  c.hob.normalModule = 2;
  c.hob.outerDiameter = 32;
  c.hob.pitchDiameter = 27;
  c.hob.gashDepth = 6;
  c.hob.length = 30;
  c.hob.gashLead = 1943;
  c.grid = GridInput{};
  c.grid.radial = 6;
  c.grid.axial = 9;
  return test::withDerivedSetup(c);
}

// The paper's hob with degree-6 axes on an 11 x 21 grid.
inline CaseInput degree6Case() {
  CaseInput c = paperCase();
  c.degree = 6;
  c.grid.radial = 11;
  c.grid.axial = 21;
  return c;
}

// A straight gash: module 4, rake offset +2 mm, degree 5, 7 x 11 grid.
inline CaseInput straightModule4Case() {
  CaseInput c = paperCase();
  c.hob.normalModule = 4;
  c.hob.outerDiameter = 70;
  c.hob.pitchDiameter = 60;
  c.hob.gashDepth = 12;
  c.hob.length = 80;
  c.hob.rakeOffset = 2;
  c.hob.gash = GashKind::Straight;
  c.hob.gashLead.reset();
  c.degree = 5;
  c.grid = GridInput{};
  c.grid.radial = 7;
  c.grid.axial = 11;
  return test::withDerivedSetup(c);
}

// What the machine runs when it is told `commanded` and adds `error`.
inline AxisPolynomials withMachineError(AxisPolynomials commanded, const AxisPolynomials& error) {
  for (Axis a : kAxes)
    for (size_t k = 0; k < commanded[a].a.size(); ++k) commanded[a].a[k] += error[a].a[k];
  return commanded;
}

inline AxisPolynomials times(AxisPolynomials a, double s) {
  for (Axis x : kAxes)
    for (double& v : a[x].a) v *= s;
  return a;
}

// A machine error the axes can make and the grid can see: a random combination of the
// identifiable directions the grid shows (singular value above 1e-6 of the largest, in machine
// steps), scaled so that the face it makes has the sum of squares `sse` (µm²) on the probe grid.
inline AxisPolynomials inSpanError(const SharpeningJob& job, double sse, unsigned seed) {
  const GroundFace f = groundFaceOf(job, job.nominalAxes);
  const MotionRange r = motionRange(f);
  const IdentifiableSpace s = identifiableSpace(job.setup.face, job.nominalAxes.degree(), job.correction,
                                                std::max(std::abs(r.min), std::abs(r.max)));
  const Eigen::MatrixXd Jz = sensitivityMatrix(f, s.coefficients).normal * s.step.asDiagonal() * s.basis;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jz, Eigen::ComputeThinV);
  std::mt19937 gen(seed);
  std::normal_distribution<double> normal(0, 1);
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(s.basis.cols());
  // (A grid with fewer points than directions has fewer singular values than directions.)
  for (int i = 0; i < svd.singularValues().size(); ++i)
    if (svd.singularValues()(i) > 1e-6 * svd.singularValues()(0)) theta += normal(gen) * svd.matrixV().col(i);
  const Eigen::VectorXd a = s.step.asDiagonal() * (s.basis * theta);
  AxisPolynomials e = times(job.nominalAxes, 0.0);
  for (size_t j = 0; j < s.coefficients.size(); ++j) e[s.coefficients[j].axis].a[s.coefficients[j].degree] = a(j);
  double scale = 1;
  for (int it = 0; it < 6; ++it) {
    auto face = simulateGroundFace(job.setup, withMachineError(job.nominalAxes, times(e, scale)), job.grid);
    EXPECT_TRUE(face.ok()) << "the generated error leaves no face at scale " << scale;
    if (!face) break;
    scale *= std::sqrt(sse / topographyOf(*face).sse);
  }
  return times(e, scale);
}

// Gaussian probe noise of standard deviation sigma (µm).
inline Eigen::MatrixXd probeNoise(int rows, int cols, double sigma, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> normal(0, sigma);
  Eigen::MatrixXd m(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) m(i, j) = normal(gen);
  return m;
}

// The grid 4 times as dense in each direction, over the same face: 3 lines between the probe lines.
inline FaceGrid denseGrid(const FaceGrid& g) {
  return FaceGrid::even(4 * (g.rows() - 1) + 1, 4 * (g.cols() - 1) + 1, g.r.front(), g.r.back(), g.x.front(),
                        g.x.back());
}

inline Topography denseFace(const SharpeningJob& job, const AxisPolynomials& axes) {
  auto f = simulateGroundFace(job.setup, axes, denseGrid(job.grid), Sensitivities::Skip);
  EXPECT_TRUE(f.ok()) << (f.ok() ? "" : f.error().message);
  return topographyOf(f.value());
}

inline double rms(const Eigen::MatrixXd& m) { return std::sqrt(m.squaredNorm() / static_cast<double>(m.size())); }

// A second-degree shape along the radius, `amplitude` µm at root and tip, 0 at the mean radius.
inline double radialShape(const FaceGrid& g, double r, double amplitude) {
  const double z = (r - g.rMean()) / (0.5 * (g.r.back() - g.r.front()));
  return amplitude * z * z;
}

}  // namespace hobsharp::test
