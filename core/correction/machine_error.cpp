#include "machine_error.h"

#include <algorithm>
#include <optional>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "correction.h"
#include "face_vectors.h"
#include "identification.h"
#include "sensitivity_matrix.h"
#include "solve_report.h"

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

// A block's decomposition (identification.h) in machine steps: V in the block's own units, over
// the coefficients, divided by their steps.
StepDecomposition inSteps(const BlockDecomposition& d, const Eigen::VectorXd& step) {
  if (d.empty() || d.V.rows() != step.size()) return {};
  return {d.singularValues, step.cwiseInverse().asDiagonal() * d.V};
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
  const bool oneFace = at == 0 && id.face.size() == n;
  m.atSolution = oneFace ? inSteps(id.firstBlockAtSolution, m.space.step) : StepDecomposition{};
  m.atRun = StepDecomposition{};  // identifyMachineError sets it where E was found from the run face
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

// The first trust region of a search whose steps are measured in machine steps (StepScale::Parameters),
// in machine steps. Measured as the third start on the campaign (seeds 99, 20261125, 3, 7). As the
// scaling of every search over the faces, 10, 100 or 1,000 steps joined the same faces on seed 99
// but lost some the column-scaled starts join (seed 3's scenario 242: 0.08 -> 30 µm left).
constexpr double kMachineStepsTrustRegion = 100;

// One search for E over every free coefficient (the structural null space too), started at `e0`,
// on this face and each earlier pass's face (none with an empty history): each pass ground at its
// axes + e0 + x, the earlier ones first, this one last. An earlier pass whose face cannot be ground
// there is left out (`skipped`). The trust region measures steps as `scale` says (least_squares_options.h).
struct FreeSearch {
  Eigen::VectorXd e0;
  std::vector<int> from;  // where each face's points begin in the stacked residual
  int total = 0, earlier = 0, skipped = 0;
  Eigen::VectorXd data;
  std::optional<Outcome<Identification>> found;  // empty when this face cannot be simulated at e0
};

FreeSearch freeSearch(const MachineErrorEstimate& m, const SharpeningSetup& setup, const AxisPolynomials& run,
                        const GroundFace& runFace, const Eigen::MatrixXd& measured, const CorrectionOptions& o,
                        const PassHistory& history, const Eigen::VectorXd& e0,
                        LeastSquaresOptions::StepScale scale = LeastSquaresOptions::StepScale::FaceMoved,
                        bool decidedOnWholeError = false) {
  const std::vector<Coefficient>& cs = m.space.coefficients;
  const int q = static_cast<int>(cs.size());
  FreeSearch j;
  j.e0 = e0;
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
  j.earlier = static_cast<int>(faces.size());
  j.skipped = static_cast<int>(history.passes.size()) - j.earlier;
  if (j.earlier == 0 && !history.passes.empty()) return j;
  {
    AxisPolynomials at = plusChange(run, cs, e0);
    auto f = simulateGroundFace(setup, at, runFace.grid);
    if (!f) return j;
    base.push_back(at);
    faces.push_back(std::move(f).value());
    data.push_back(flat(measured));
  }
  for (const GroundFace& f : faces) j.from.push_back(j.total), j.total += f.size();
  j.data.resize(j.total);
  for (size_t i = 0; i < data.size(); ++i) j.data.segment(j.from[i], data[i].size()) = data[i];

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
          GroundFace f = slice(all, j.from[i], faces[i].size());
          if (!addSensitivities(f, setup, plusChange(base[i], cs, x[0]))) return false;
          fs.push_back(std::move(f));
        }
        all = stacked(fs);
        return true;
      },
      [&](const GroundFace& f, int) { return sensitivityMatrix(f, cs).normal; }};
  // Every free coefficient, each a machine step: the directions are decided by the faces.
  // decidedOnWholeError: the directions decided on what the whole error makes, e0 with the
  // search's step (identification.h, ParameterBlock::startValue); otherwise on the misfit at e0.
  const ParameterBlock all{m.space.step.asDiagonal() * Eigen::MatrixXd::Identity(q, q), Wild::TakenWhenNeeded,
                           decidedOnWholeError ? e0 : Eigen::VectorXd()};
  CorrectionOptions limits = o;
  limits.solver.maxIterations = o.solver.maxIterationsEveryCoefficient;
  limits.solver.stepScale = scale;
  if (scale == LeastSquaresOptions::StepScale::Parameters) limits.solver.initialTrustRegion = kMachineStepsTrustRegion;
  j.found = identify(model, stacked(faces), j.data, {all}, limits, {"the axes", "no axis direction"});
  return j;
}

bool converged(const FreeSearch& j) {
  return j.found && *j.found && (*j.found)->summary.status == SolveStatus::Converged;
}

// The rms left over the faces searched, µm; infinite when the search has no result.
double misfitOf(const FreeSearch& j) {
  if (!j.found || !*j.found || j.total == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt((*j.found)->summary.finalCost / static_cast<double>(j.total));
}

// m's estimate is one sought over every free coefficient: nothing is left out, and what one face
// does not show to first order is kept as sought all the same.
void soughtOverEveryCoefficient(MachineErrorEstimate& m) {
  const int q = static_cast<int>(m.space.coefficients.size());
  m.space.basis = Eigen::MatrixXd::Identity(q, q);
  if (m.soughtAllTheSame.empty()) m.soughtAllTheSame = std::move(m.space.structural);
  m.space.structural.clear();
}

// E sought over every free coefficient so that it explains each pass's face and this one together
// (machine_error.h). Replaces m's estimate when the solve converges (every face explained to the
// probe noise); otherwise sets m.historyNote.
void joinHistory(MachineErrorEstimate& m, const SharpeningSetup& setup, const AxisPolynomials& run,
                 const GroundFace& runFace, const Eigen::MatrixXd& measured, const CorrectionOptions& o,
                 const PassHistory& history) {
  const std::vector<Coefficient>& cs = m.space.coefficients;
  const int q = static_cast<int>(cs.size());
  if (q == 0) return;
  // Started first at E0 = nominal - run: the error the run compensates (the previous pass proposed
  // nominal - E). Where that search does not explain the faces, once more from this face's own
  // estimate, which explains this face; the one that explains them is kept. Where neither does,
  // once more from E0 with the steps measured in machine steps: over two faces the directions
  // one face barely shows are weak columns of the Jacobian, and a trust region scaled by the
  // columns lets the search run along them (hundreds of thousands of steps on seed 99's
  // scenarios 344 and 380, where the error is six to eight thousand steps from E0) into a
  // minimum that explains neither face; it is kept where it explains them. Where none does, the
  // note speaks of the one of the first two that came nearest (the least rms left): a start that
  // ended above the noise says nothing of the faces while the other left less.
  const Eigen::VectorXd e0 = errorCompensated(history.nominal, run, cs);
  FreeSearch j = freeSearch(m, setup, run, runFace, measured, o, history, e0);
  if (!converged(j)) {
    FreeSearch own = freeSearch(m, setup, run, runFace, measured, o, history, m.coefficientError);
    if (converged(own) || misfitOf(own) < misfitOf(j)) j = std::move(own);
  }
  if (!converged(j)) {
    FreeSearch steps = freeSearch(m, setup, run, runFace, measured, o, history, e0,
                                  LeastSquaresOptions::StepScale::Parameters);
    if (converged(steps)) j = std::move(steps);
  }
  const std::string left = j.skipped > 0 ? " (" + passesWord(j.skipped) + " left out: " +
                                                (j.skipped == 1 ? "its face" : "their faces") +
                                                " cannot be simulated with this estimate)"
                                          : "";
  if (j.earlier == 0) {
    m.historyNote = std::string(j.skipped == 1 ? "The earlier pass's face" : "The earlier passes' faces") +
                    " cannot be simulated with the error this run compensates: identified from this face alone.";
    return;
  }
  if (!j.found) {
    m.historyNote = "This face cannot be simulated with the error the run compensates: identified from this face alone.";
    return;
  }
  Outcome<Identification>& found = *j.found;
  const std::string these = "this face and " + facesWord(j.earlier);
  if (!found || found->summary.status != SolveStatus::Converged) {
    // Only a solve that ended above the noise shows that no one error explains the faces; one that
    // ran out of iterations or stalled may have explained them already (a misfit within the noise).
    std::ostringstream misfit;
    misfit.precision(2);
    if (found) misfit << " (" << misfitOf(j) << " µm rms left)";
    const SolveStatus st = found ? found->summary.status : SolveStatus::Failed;
    // Locked coefficients are not sought: their error stays in every face, and no error over the
    // free ones may explain them together with nothing changed on the machine; or the machine
    // changed. The note names both.
    const std::string locked = lockedText(run.degree(), o);
    if (st == SolveStatus::AboveNoise && !locked.empty())
      m.historyNote = "No one error of the free coefficients (" + locked + " locked) explains " + these +
                      " to the probe noise" + misfit.str() + left +
                      ": identified from this face alone. A locked coefficient's error stays in every face: unlock " +
                      locked + " to seek one error over them all; if that does not join them, has the machine or the "
                      "setup changed?";
    else if (st == SolveStatus::AboveNoise)
      m.historyNote = "No one machine error explains " + these + " to the probe noise" + misfit.str() + left +
                      ": identified from this face alone (has the machine or the setup changed?).";
    else if (st == SolveStatus::NoConvergence)
      m.historyNote = "The search for one machine error explaining " + these + " did not converge in " +
                      std::to_string(o.solver.maxIterationsEveryCoefficient) + " iterations" + misfit.str() + left +
                      ": identified from this face alone.";
    else if (st == SolveStatus::Stalled)
      m.historyNote = "The search for one machine error explaining " + these + " stalled" + misfit.str() + left +
                      ": identified from this face alone (has the machine or the setup changed?).";
    else
      m.historyNote = "One machine error could not be sought over " + these + left + ": identified from this face alone.";
    return;
  }
  m.historyJacobian = found->jacobian[0];
  m.historyLinearised = j.data - found->explained + m.historyJacobian * (j.e0 + found->value[0]);
  m.historyLeftOut = left;
  keep(m, std::move(found).value(), j.e0, measured, j.from.back());
  m.summary.reason += " Identified from " + these + " together" + left + ".";
  m.passesJoined = j.earlier;
  // Nothing is left out by construction: the faces decide every direction.
  soughtOverEveryCoefficient(m);
  m.historyNote.clear();
}

}  // namespace

Eigen::VectorXd errorCompensated(const AxisPolynomials& nominal, const AxisPolynomials& run,
                                 const std::vector<Coefficient>& cs) {
  Eigen::VectorXd e0(static_cast<int>(cs.size()));
  for (size_t k = 0; k < cs.size(); ++k)
    e0(static_cast<int>(k)) = nominal[cs[k].axis].coefficient(cs[k].degree) - run[cs[k].axis].coefficient(cs[k].degree);
  return e0;
}

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
  const ParameterBlock axes{m.space.step.asDiagonal() * m.space.basis, Wild::TakenWhenNeeded, Eigen::VectorXd()};
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
  const StepDecomposition atRun = inSteps(found->firstBlockAtStart, m.space.step);
  keep(m, std::move(found).value(), Eigen::VectorXd::Zero(q), measured, 0);
  m.atRun = atRun;
  // Not explained to the noise, with directions left out that the geometry hides at first order
  // (X, Y and B on a straight gash): away from E = 0 they move the face at second order, and the
  // face may need them (issue 20: no direction left out while the misfit is above the noise). Kept
  // when every free coefficient explains the face to the noise.
  if (m.summary.status != SolveStatus::Converged && m.summary.finalCost > noiseCeiling(runFace.size(), o.probeNoise) &&
      !m.space.structural.empty() && !runFace.atProbes()) {
    // Its directions decided first on what the whole error makes: a search that takes only what
    // the misfit left at the estimate needs moves in those few directions, and the rest are
    // "unseen" to the bound and the words. Where that search does not explain the face (it leaves
    // out wild directions the misfit needs: scenario 182 of the campaign's default seed), once more
    // decided on the misfit left (docs/method.md, "Freed when the face needs them").
    FreeSearch j = freeSearch(m, setup, run, runFace, measured, o, PassHistory{}, m.coefficientError,
                              LeastSquaresOptions::StepScale::FaceMoved, true);
    if (!converged(j)) j = freeSearch(m, setup, run, runFace, measured, o, PassHistory{}, m.coefficientError);
    if (converged(j)) {
      keep(m, std::move(*j.found).value(), j.e0, measured, 0);
      m.summary.reason += " Sought over every coefficient, the directions the face shows only at second order too.";
      soughtOverEveryCoefficient(m);
    }
  }
  if (history && !history->empty() && !runFace.atProbes()) joinHistory(m, setup, run, runFace, measured, o, *history);
  return m;
}

}  // namespace hobsharp
