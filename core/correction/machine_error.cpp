#include "machine_error.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "face_vectors.h"
#include "identification.h"
#include "sensitivity_matrix.h"

namespace hobsharp {
namespace {

// Several passes' faces one after the other, for one residual over all of them: the points and
// envelope points of each in turn (the grid and the mean point are the first's; rows() and cols()
// do not apply to the whole). `slice` takes one face back out.
GroundFace stacked(const std::vector<GroundFace>& faces) {
  GroundFace all = faces.front();
  for (size_t i = 1; i < faces.size(); ++i) {
    all.points.insert(all.points.end(), faces[i].points.begin(), faces[i].points.end());
    all.envelope.insert(all.envelope.end(), faces[i].envelope.begin(), faces[i].envelope.end());
  }
  return all;
}

// (The mean point stays the first face's: nothing reads a slice's thickness.)
GroundFace slice(const GroundFace& all, int from, int n) {
  GroundFace f = all;
  f.points.assign(all.points.begin() + from, all.points.begin() + from + n);
  f.envelope.assign(all.envelope.begin() + from, all.envelope.begin() + from + n);
  return f;
}

// m's estimate from an identification whose last n points, from `at`, are the face measured now
// (all of them with one face): E = e0 + the identified value, the face, what it explains and the
// Jacobian there, the covariance, the directions decided and the summary.
void keep(MachineErrorEstimate& m, Identification&& id, const Eigen::VectorXd& e0, const Eigen::MatrixXd& measured,
          int at) {
  const std::vector<Coefficient>& cs = m.space.coefficients;
  const int n = static_cast<int>(measured.size());
  m.coefficientError = e0 + id.value[0];
  for (Axis a : kAxes) std::fill(m.error[a].a.begin(), m.error[a].a.end(), 0.0);
  for (size_t j = 0; j < cs.size(); ++j) m.error[cs[j].axis].a[cs[j].degree] = m.coefficientError(static_cast<int>(j));
  m.explained = gridOf(id.explained.segment(at, n), static_cast<int>(measured.rows()), static_cast<int>(measured.cols()));
  m.unexplained = measured - m.explained;
  m.jacobian = id.jacobian[0].middleRows(at, n);
  m.covariancePerNoise = id.covariancePerNoise(0);
  const BlockDirections& decided = id.blocks[0];
  m.singularValues = decided.singularValues;
  m.used = decided.decision.used;
  m.withinNoise = decided.decision.withinNoise;
  m.amplifying = decided.decision.amplifying;
  m.summary = id.summary;
  m.face = at == 0 && id.face.size() == n ? std::move(id.face) : slice(id.face, at, n);
}

std::string passesWord(int n) { return std::to_string(n) + (n == 1 ? " earlier pass" : " earlier passes"); }
// "the 1 earlier pass's face", "the 2 earlier passes' faces"
std::string facesWord(int n) { return "the " + passesWord(n) + (n == 1 ? "'s face" : "' faces"); }

// E sought over every free coefficient so that it explains each pass's face and this one together
// (machine_error.h). Replaces m's estimate when the solve converges (every face explained to the
// probe noise); otherwise sets m.historyNote.
void joinHistory(MachineErrorEstimate& m, const SharpeningSetup& setup, const AxisPolynomials& run,
                 const GroundFace& runFace, const Eigen::MatrixXd& measured, const CorrectionOptions& o,
                 const PassHistory& history) {
  const std::vector<Coefficient>& cs = m.space.coefficients;
  const int q = static_cast<int>(cs.size());
  if (q == 0) return;
  // E0 = nominal - run: the error the run compensates (the previous pass proposed nominal - E).
  Eigen::VectorXd e0(q);
  for (int j = 0; j < q; ++j)
    e0(j) = history.nominal[cs[j].axis].coefficient(cs[j].degree) - run[cs[j].axis].coefficient(cs[j].degree);
  // Each pass ground at its axes + E0 + x; the earlier ones first, this one last. An earlier pass
  // whose face cannot be ground there is left out.
  std::vector<AxisPolynomials> base;
  std::vector<GroundFace> faces;
  std::vector<Eigen::VectorXd> data;
  for (const EarlierPass& p : history.passes) {
    if (p.measured.rows() != runFace.rows() || p.measured.cols() != runFace.cols()) continue;
    AxisPolynomials at = plusChange(p.axes, cs, e0);
    auto f = simulateGroundFace(setup, at, runFace.grid);
    if (!f) continue;
    base.push_back(at);
    faces.push_back(std::move(f).value());
    data.push_back(flat(p.measured));
  }
  const int earlier = static_cast<int>(faces.size());
  const int skipped = static_cast<int>(history.passes.size()) - earlier;
  const std::string left = skipped > 0 ? " (" + passesWord(skipped) + " left out: " +
                                              (skipped == 1 ? "its face" : "their faces") +
                                              " cannot be simulated with this estimate)"
                                        : "";
  if (earlier == 0) {
    m.historyNote = std::string(skipped == 1 ? "The earlier pass's face" : "The earlier passes' faces") +
                    " cannot be simulated with the error this run compensates: identified from this face alone.";
    return;
  }
  {
    AxisPolynomials at = plusChange(run, cs, e0);
    auto f = simulateGroundFace(setup, at, runFace.grid);
    if (!f) {
      m.historyNote = "This face cannot be simulated with the error the run compensates: identified from this face alone.";
      return;
    }
    base.push_back(at);
    faces.push_back(std::move(f).value());
    data.push_back(flat(measured));
  }
  std::vector<int> from;
  int total = 0;
  for (const GroundFace& f : faces) from.push_back(total), total += f.size();
  Eigen::VectorXd d(total);
  for (size_t i = 0; i < data.size(); ++i) d.segment(from[i], data[i].size()) = data[i];

  const FaceModel model{
      [&](const std::vector<Eigen::VectorXd>& x) -> Outcome<GroundFace> {
        std::vector<GroundFace> fs;
        for (size_t i = 0; i < base.size(); ++i) {
          auto f = simulateGroundFaceLike(faces[i], setup, plusChange(base[i], cs, x[0]), Sensitivities::Skip);
          if (!f) return f.error();
          fs.push_back(std::move(f).value());
        }
        return stacked(fs);
      },
      [&](GroundFace& all, const std::vector<Eigen::VectorXd>& x) {
        std::vector<GroundFace> fs;
        for (size_t i = 0; i < base.size(); ++i) {
          GroundFace f = slice(all, from[i], faces[i].size());
          if (!addSensitivities(f, setup, plusChange(base[i], cs, x[0]))) return false;
          fs.push_back(std::move(f));
        }
        all = stacked(fs);
        return true;
      },
      [&](const GroundFace& f, int) { return sensitivityMatrix(f, cs).normal; }};
  // Every free coefficient, each a machine step: the directions are decided by the faces.
  const ParameterBlock all{m.space.step.asDiagonal() * Eigen::MatrixXd::Identity(q, q), Wild::TakenWhenNeeded};
  CorrectionOptions withHistory = o;
  withHistory.solver.maxIterations = o.solver.maxIterationsWithHistory;
  auto found = identify(model, stacked(faces), d, {all}, withHistory, {"the axes", "no axis direction"});
  const std::string these = "this face and " + facesWord(earlier);
  if (!found || found->summary.status != SolveStatus::Converged) {
    // Only a solve that ended above the noise shows that no one error explains the faces; one that
    // ran out of iterations or stalled may have explained them already (a misfit within the noise).
    std::ostringstream misfit;
    misfit.precision(2);
    if (found) misfit << " (" << std::sqrt(found->summary.finalCost / static_cast<double>(total)) << " µm rms left)";
    const SolveStatus st = found ? found->summary.status : SolveStatus::Failed;
    if (st == SolveStatus::AboveNoise)
      m.historyNote = "No one machine error explains " + these + " to the probe noise" + misfit.str() + left +
                      ": identified from this face alone (has the machine or the setup changed?).";
    else if (st == SolveStatus::NoConvergence)
      m.historyNote = "The search for one machine error explaining " + these + " did not converge in " +
                      std::to_string(withHistory.solver.maxIterations) + " iterations" + misfit.str() + left +
                      ": identified from this face alone.";
    else if (st == SolveStatus::Stalled)
      m.historyNote = "The search for one machine error explaining " + these + " stalled" + misfit.str() + left +
                      ": identified from this face alone.";
    else
      m.historyNote = "One machine error could not be sought over " + these + left + ": identified from this face alone.";
    return;
  }
  m.historyJacobian = found->jacobian[0];
  m.historyLinearised = d - found->explained + m.historyJacobian * (e0 + found->value[0]);
  m.historyLeftOut = left;
  keep(m, std::move(found).value(), e0, measured, from.back());
  m.summary.reason += " Identified from " + these + " together" + left + ".";
  m.passesJoined = earlier;
  // Nothing is left out by construction: the faces decide every direction.
  m.space.basis = Eigen::MatrixXd::Identity(q, q);
  m.space.structural.clear();
  m.historyNote.clear();
}

}  // namespace

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
                                                   const CorrectionOptions& o, const PassHistory* history) {
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
  m.error = run;
  keep(m, std::move(found).value(), Eigen::VectorXd::Zero(q), measured, 0);
  if (history && !history->empty() && !runFace.atProbes()) joinHistory(m, setup, run, runFace, measured, o, *history);
  return m;
}

}  // namespace hobsharp
