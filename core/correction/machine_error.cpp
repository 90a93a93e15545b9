#include "machine_error.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "face_vectors.h"
#include "identification.h"
#include "sensitivity_matrix.h"

namespace hobsharp {

const char* statusName(SolveStatus s) {
  switch (s) {
    case SolveStatus::Converged: return "converged";
    case SolveStatus::AboveNoise: return "aboveNoise";
    case SolveStatus::NoConvergence: return "notConverged";
    case SolveStatus::Stalled: return "stalled";
    case SolveStatus::Failed: return "failed";
  }
  return "failed";
}

Outcome<MachineErrorEstimate> identifyMachineError(const SharpeningSetup& setup, const AxisPolynomials& run,
                                                   const GroundFace& runFace, const Eigen::MatrixXd& measured,
                                                   const CorrectionOptions& o) {
  // The face's shape: the grid, or one column of probe points (ground_face.h).
  const int rows = runFace.rows(), cols = runFace.cols();
  if (measured.rows() != rows || measured.cols() != cols)
    return refuse("measured", "the topography has " + std::to_string(measured.rows()) + " x " +
                                  std::to_string(measured.cols()) + " values; the grid is " + std::to_string(rows) +
                                  " radial x " + std::to_string(cols) + " axial.");
  if (!measured.allFinite()) return refuse("measured", "holds a value that is not a finite number.");
  const MotionRange range = motionRange(runFace);
  const double reach = std::max({std::abs(range.min), std::abs(range.max), 1e-12});

  MachineErrorEstimate m;
  m.space = identifiableSpace(setup.face, run.degree(), o, reach);
  const std::vector<Coefficient>& cs = m.space.coefficients;
  const int q = static_cast<int>(cs.size());
  // One block: E over the free coefficients, per machine step of each identifiable direction.
  const ParameterBlock axes{m.space.step.asDiagonal() * m.space.basis, Wild::TakenWhenNeeded};
  // face(run + E), simulated at runFace's points: the grid, or the probe points.
  const FaceModel model{
      [&](const std::vector<Eigen::VectorXd>& x) {
        return simulateGroundFaceLike(runFace, setup, plusChange(run, cs, x[0]), Sensitivities::Skip);
      },
      [&](GroundFace& f, const std::vector<Eigen::VectorXd>& x) {
        return static_cast<bool>(addSensitivities(f, setup, plusChange(run, cs, x[0])));
      },
      [&](const GroundFace& f, int) { return sensitivityMatrix(f, cs).normal; }};
  auto found = identify(model, runFace, flat(measured), {axes}, o, {"the axes", "no identified axis direction"});
  if (!found) return found.error();
  Identification id = std::move(found).value();
  const BlockDirections& decided = id.blocks[0];
  m.singularValues = decided.singularValues;
  m.used = decided.decision.used;
  m.withinNoise = decided.decision.withinNoise;
  m.amplifying = decided.decision.amplifying;
  m.coefficientError = id.value[0];
  m.error = run;
  for (Axis a : kAxes) std::fill(m.error[a].a.begin(), m.error[a].a.end(), 0.0);
  for (int j = 0; j < q; ++j) m.error[cs[j].axis].a[cs[j].degree] = m.coefficientError(j);
  m.explained = gridOf(id.explained, rows, cols);
  m.unexplained = measured - m.explained;
  m.jacobian = std::move(id.jacobian[0]);
  m.covariancePerNoise = id.covariancePerNoise(0);
  m.face = std::move(id.face);
  m.summary = id.summary;
  return m;
}

}  // namespace hobsharp
