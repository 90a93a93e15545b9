// correctMeasuredFace (correction.h): either method, then the figures the engineer reads.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include <Eigen/SVD>

#include "correction.h"
#include "face_prediction.h"
#include "earlier_passes.h"
#include "face_vectors.h"
#include "identified_axes.h"
#include "machine_error.h"
#include "structural_null_space.h"
#include "number_text.h"
#include "sensitivity_matrix.h"
#include "solve_report.h"

namespace hobsharp {
namespace {

// A shape the axes make stands out of the probe noise in the face when either
//   - its component along one of the run face's directions exceeds kStopDirectionSigmas sigma: a
//     free coefficient's own shape (a column of the sensitivities, a single axis term's error), or
//     a left singular vector of the sensitivities (a combination's); pure noise does so along one
//     of 2 x 25 directions about once in 3,000 draws; or
//   - its sum of squares in their span (k directions) exceeds sigma² (k + kStopDeviations sqrt(2k)),
//     the chi-square's mean plus 5 of its standard deviations: pure noise exceeds it about once
//     in 10,000 draws at k = 25 (several shapes, none alone above the first test).
// The whole-face chi-square ceiling (noiseCeiling) alone let a shape an axis makes through: an
// independent review (2026-12-07) had a Y a0 shape of 0.6 µm rms at sigma 0.5 µm (8 sigma along its
// direction on Tab. 1's 45 points) told to stop.
constexpr double kStopDirectionSigmas = 4.5;
constexpr double kStopDeviations = 5;

AxisShapes axisShapesIn(const GroundFace& runFace, const Eigen::MatrixXd& measured, const std::vector<Coefficient>& cs,
                        double sigma) {
  AxisShapes out;
  if (cs.empty() || !(sigma > 0)) return out;
  const Eigen::MatrixXd S = sensitivityMatrix(runFace, cs).normal;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(S, Eigen::ComputeThinU);
  const Eigen::VectorXd& s = svd.singularValues();
  int k = 0;
  while (k < s.size() && s(k) > 1e-12 * s(0)) ++k;
  if (k == 0) return out;
  const Eigen::VectorXd m = flat(measured);
  const Eigen::VectorXd c = svd.matrixU().leftCols(k).transpose() * m;
  double largest = c.cwiseAbs().maxCoeff();
  for (int j = 0; j < S.cols(); ++j)
    if (const double norm = S.col(j).norm(); norm > 1e-12 * s(0)) largest = std::max(largest, std::abs(S.col(j).dot(m)) / norm);
  out.largestSigmas = largest / sigma;
  out.togetherSigmas = (c.squaredNorm() / (sigma * sigma) - k) / std::sqrt(2.0 * k);
  out.single = out.largestSigmas > kStopDirectionSigmas;
  out.together = out.togetherSigmas > kStopDeviations;
  return out;
}

// The face's normal deviations (µm) as a grid, or one column at probe points.
Eigen::MatrixXd normalOf(const GroundFace& f) { return gridOf(faceNormal(f), f.rows(), f.cols()); }

// True when the two differ by no more than rounding in their last bits: the same face.
bool sameAxes(const AxisPolynomials& a, const AxisPolynomials& b) {
  for (Axis x : kAxes)
    for (size_t k = 0; k < a[x].a.size(); ++k)
      if (std::abs(a[x].a[k] - b[x].a[k]) > 8 * std::numeric_limits<double>::epsilon() * (1 + std::abs(b[x].a[k])))
        return false;
  return true;
}

// The face the machine grinds when `commanded` is run and it adds `error`, plus the part of the
// measurement no axis makes (which stays), on the probe grid. `runFace` is a face already
// simulated for the axes `knownAxes` (the nominal ones, in a first pass: nominal - E + E), with
// `setup`'s wheel when `sameWheel`.
Outcome<Topography> predictedFace(const SharpeningSetup& setup, const GroundFace& runFace,
                                  const AxisPolynomials& commanded, const AxisPolynomials& error,
                                  const Eigen::MatrixXd& unexplained, const AxisPolynomials& knownAxes, bool sameWheel) {
  const AxisPolynomials actual = plusError(commanded, error);
  if (sameWheel && sameAxes(actual, knownAxes)) return topographyFromNormal(runFace, normalOf(runFace) + unexplained);
  auto f = simulateGroundFaceLike(runFace, setup, actual, Sensitivities::Skip);
  if (!f) return f.error();
  return topographyFromNormal(runFace, normalOf(*f) + unexplained);
}

// A sum of squares for a sentence: 3 digits, or "below 1e-6" where only rounding is left (which
// the native and the WebAssembly builds round differently).
// `historyNext`: a next pass would use this face with its own (the nonlinear method on a grid,
// without the wheel's correction; machine_error.h, pass_history.h).
std::string verdictOf(const Correction& c, const CorrectionOptions& o, int points, bool historyNext) {
  std::ostringstream v;
  v.precision(3);
  // What the pass leaves, as the prediction and its bound state it (face_prediction.h).
  const std::string leaves = predictionText(c);
  const bool withinNoise = c.leavesWithinNoise(o.probeNoise, points);
  // An identification that stalled or ran out of iterations, in a word.
  const bool unfinished = c.summary.status == SolveStatus::Stalled || c.summary.status == SolveStatus::NoConvergence;
  const char* how = c.summary.status == SolveStatus::Stalled ? "stalled" : "did not converge";
  const std::string locked = lockedText(c.axes.degree(), o);
  if (c.coefficients.empty()) {
    v << allLockedText(c.before.rms);
  } else if (c.runKept) {
    v << "No change proposed: the correction found would leave a sum of squares of " << squaresText(c.discardedSse)
      << " µm², more than the " << squaresText(c.before.sse) << " µm² measured, so the axes run stay as they are.";
  } else if (c.stop) {
    v << "Stop: the measured face (" << numberText(c.before.rms, 2) << " µm rms) is within the probe noise (sigma "
      << numberText(o.probeNoise, 3) << " µm); another pass would only move noise. Keep the axes run.";
    // A sigma far above a measuring machine's (about 1 µm, U95 about 2 µm) is likely a unit slip,
    // and the stop rests on it alone.
    constexpr double kProbeSigmaTenfold = 10;  // µm: ten times a probe's sigma
    if (o.probeNoise > kProbeSigmaTenfold)
      v << " The probe noise declared, sigma " << numberText(o.probeNoise, 3) << " µm, is more than ten times a measuring machine's "
        << "(about 1 µm, U95 about 2 µm): if it was entered in another unit, this stop rests on that.";
  } else if (c.uncertain()) {
    // A bound above the face measured, or a sampled error with which part of the face stays
    // unground (correction.h, uncertain()): the pass may leave the face worse than it is, and the
    // verdict leads with that, not with what the identified model would leave.
    v << "Uncertain: the face does not show enough of the machine's error to say that this pass improves it; "
      << leaves;
    if (c.predictedUngrindable > 0)
      v << ", and with some of the errors it cannot show the wheel would not reach part of the face (part of it "
           "would stay unground)";
    else if (c.predictedFoldAt)
      v << ", and with an error it cannot show, of that size, the wheel may stop reaching the face near r = "
        << c.predictedFoldAt->r << " mm, x = " << c.predictedFoldAt->x << " mm (part of it would stay unground)";
    v << ".";
    if (unfinished) v << " The identification " << how << ": " << c.summary.reason;
    if (historyNext)
      v << " If it is ground, keep this pass in the case: a next pass measured on the grid seeks one error that "
           "explains this face and the next together.";
  } else if (unfinished) {
    v << "Identification " << how << "; the best estimate is proposed: " << leaves << ". " << c.summary.reason;
  } else if (withinNoise && c.uncorrectableShare > o.correctableShare && c.axisShapes && c.changesNothing()) {
    // Nothing changed while the face is within twice the noise: "Correctable" would send the
    // engineer to grind the same face again. Why, as the stop's test of the axes' shapes found it.
    const AxisShapes& a = *c.axisShapes;
    const std::string free = locked.empty() ? "the axes" : "the free axes (" + locked + " locked)";
    v << "No change proposed: ";
    if (a.aboveNoise())
      v << "the shapes " << free << " make stand out of the probe noise (sigma " << o.probeNoise
        << " µm) in the face measured (" << c.before.rms << " µm rms) only together, none clearly enough on its own "
        << "for the identification to take it. The axes run stay as they are; measure the face again, on more points "
           "or with a probe of less noise, to tell which.";
    else
      v << "no shape " << free << " make stands out of the probe noise (sigma " << o.probeNoise
        << " µm) in the face measured (" << c.before.rms << " µm rms); what is left is a shape they do not produce, "
           "within twice the probe noise (rms). The axes run stay as they are: another pass with them grinds the same "
           "face.";
  } else if (c.uncorrectableShare <= o.correctableShare || withinNoise) {
    v << "Correctable: the axes can cancel the measured deviation"
      << (withinNoise && c.uncorrectableShare > o.correctableShare ? " to within twice the probe noise (rms)" : "")
      << "; " << leaves << ".";
  } else {
    v << uncorrectableText(c.uncorrectableShare, locked, ": " + leaves);
  }
  return v.str();
}

}  // namespace

void leadWithSign(Correction& c, std::optional<HistorySign> sign) {
  c.historySign = sign;
  // A stop is the whole instruction (grinding ends); otherwise a sign the history contradicts leads.
  if (!c.signReversed() || c.stop) return;
  std::ostringstream v;
  v.precision(3);
  v << "Check the sign: from the last pass measured " << (c.probes.empty() ? "on the grid" : "at these points")
    << " to this one the axes changed by what moves the face by " << c.historySign->predictedRms
    << " µm rms as this calculator signs deviations (plus = excess material), and the faces measured moved the opposite "
       "way ("
    << std::fixed << std::setprecision(2) << c.historySign->along
    << " times that). Faces signed the other way round make every correction add to the error instead of cancelling it: "
       "do not grind this proposal, which takes them as this calculator does, before checking how the measuring "
       "machine signs deviations (the manual, Conventions, Sign); if it signs them the other way round, load every "
       "face again with their sign changed, the earlier passes' too. Were the sign right, the verdict would read: "
    << c.verdict;
  c.verdict = v.str();
}

std::array<double, kAxisCount> axisChangeOver(const AxisPolynomials& proposed, const AxisPolynomials& run,
                                              const MotionRange& range) {
  std::array<double, kAxisCount> out{};
  for (Axis a : kAxes) {
    Polynomial change = proposed[a];
    for (size_t k = 0; k < change.a.size(); ++k) change.a[k] -= run[a].coefficient(static_cast<int>(k));
    out[static_cast<int>(a)] = largestOverRange(change, a, range.min, range.max);
  }
  return out;
}

Outcome<Correction> correctMeasuredFace(const SharpeningSetup& setup, const AxisPolynomials& nominal,
                                        const AxisPolynomials& run, const GroundFace& runFace,
                                        const Eigen::MatrixXd& measured, const CorrectionOptions& o,
                                        const MachineErrorEstimate* identified, const SharpeningSetup* dressed,
                                        const AxisPolynomials* linearisedAt, const PassHistory* history) {
  Correction c;
  // An earlier pass dressed the wheel: nothing to join, and the next case keeps that pass.
  const bool dressedBefore = history && history->wheelCorrected;
  if (history && history->empty()) history = nullptr;
  // The error was identified with the wheel's shape alongside (its only source, wheel_correction.cpp):
  // the model's face holds that shape, and the bound measures moves from re-simulated faces.
  const bool wheelAlongside = identified != nullptr;
  // The axes runFace was ground with: the run, or the nominal ones where the run alone cannot be
  // simulated (a pass after a large machine error; correction.h).
  const AxisPolynomials& at = linearisedAt ? *linearisedAt : run;
  c.linearisedAtNominal = linearisedAt != nullptr;
  Eigen::MatrixXd unexplained;
  std::string historyNote;  // why the earlier passes were not joined (machine_error.h)
  bool freed = false;  // the structural null space freed on this face alone (machine_error.h)
  Eigen::MatrixXd historyJacobian;  // when joined: every face's sensitivities, and the data linearised
  Eigen::VectorXd historyLinearised;
  std::string historyLeftOut;
  const MotionRange range = motionRange(runFace);
  const double reach = std::max({std::abs(range.min), std::abs(range.max), 1e-12});
  // What the face tells of the axes (identified_axes.h): the sensitivities at the identified error,
  // the free coefficients' machine steps, what was identified alongside, and the identified error.
  Eigen::MatrixXd sensitivities, alongside, basis;
  Eigen::VectorXd steps, errorCoefficients;
  // The identification's decompositions of the sensitivities at E and at the run (machine_error.h).
  StepDecomposition atSolution, atRunMade;
  if (o.method == CorrectionMethod::Linear && linearisedAt)
    return refuse("axes", "the face these axes grind without the machine's error cannot be simulated, and the linear "
                          "step needs it: use correction.method \"nonlinear\".", ErrorCode::Unsolvable);
  if (o.method == CorrectionMethod::Linear) {
    auto step = correctionStep(runFace, run, measured, o);
    if (!step) return step.error();
    c = std::move(step).value();
    c.method = CorrectionMethod::Linear;
    if (history && !history->empty())
      historyNote = "The linear step (Eq. 17) takes this face alone; the earlier passes' faces are used by the "
                    "nonlinear method.";
    c.summary.status = SolveStatus::Converged;
    c.summary.reason = "one linear step (Eq. 17).";
    c.summary.iterations = 1;
    // The step's error model: the machine added -change to what it was told.
    c.identifiedError = run;
    for (Axis a : kAxes) std::fill(c.identifiedError[a].a.begin(), c.identifiedError[a].a.end(), 0.0);
    for (size_t j = 0; j < c.coefficients.size(); ++j)
      c.identifiedError[c.coefficients[j].axis].a[c.coefficients[j].degree] = -c.change(static_cast<int>(j));
    auto explained = simulateGroundFaceLike(runFace, setup, plusError(run, c.identifiedError), Sensitivities::Skip);
    if (!explained) return explained.error();
    unexplained = measured - normalOf(*explained);
    sensitivities = sensitivityMatrix(runFace, c.coefficients).normal;
    steps.resize(static_cast<int>(c.coefficients.size()));
    for (size_t j = 0; j < c.coefficients.size(); ++j)
      steps(static_cast<int>(j)) = coefficientStep(o.resolution, c.coefficients[j], reach);
    errorCoefficients = -c.change;
    const IdentifiableSpace space = identifiableSpace(setup.face, run.degree(), o, reach);
    if (space.coefficients == c.coefficients) basis = space.basis;
  } else {
    // Identified from `at` instead of the run: at - run, by which the error found is short of the
    // machine's and the history's axes are moved as the run's are.
    AxisPolynomials shift = at;
    for (Axis a : kAxes)
      for (size_t k = 0; k < shift[a].a.size(); ++k) shift[a].a[k] -= run[a].coefficient(static_cast<int>(k));
    std::optional<PassHistory> shifted;
    if (history && linearisedAt) {
      shifted = *history;
      for (EarlierPass& p : shifted->passes) p.axes = plusError(p.axes, shift);
    }
    auto m = identified ? Outcome<MachineErrorEstimate>(*identified)
                        : identifyMachineError(setup, at, runFace, measured, o, shifted ? &*shifted : history);
    if (!m) return m.error();
    MachineErrorEstimate est = std::move(m).value();
    // The machine ran `run`, so its error is at - run more than the one found from `at`.
    if (linearisedAt) est.error = plusError(est.error, shift);
    c.method = CorrectionMethod::Nonlinear;
    c.before = topographyFromNormal(runFace, measured);
    c.coefficients = est.space.coefficients;
    c.identifiedError = est.error;
    c.summary = est.summary;
    c.singularValues = est.singularValues;
    c.directionsUsed = est.used;
    c.rank = 0;
    for (bool u : est.used) c.rank += u ? 1 : 0;
    c.amplifyingDropped = est.amplifying;
    c.withinNoise = est.withinNoise;
    c.unobservable = est.space.structural;
    // What one face does not show to first order, sought all the same (machine_error.h): said so.
    for (UnobservableCombination u : est.soughtAllTheSame) {
      u.description += est.passesJoined > 0
                           ? " on one face to first order; sought all the same over this face and the earlier passes' faces "
                             "together, which show it"
                           : " to first order; sought all the same, since this face is not explained to the probe noise "
                             "without it (away from the nominal axes it moves the face at second order)";
      c.unobservable.push_back(std::move(u));
    }
    c.passesJoined = est.passesJoined;
    historyNote = est.historyNote;
    historyJacobian = est.historyJacobian;
    historyLinearised = est.historyLinearised;
    historyLeftOut = est.historyLeftOut;
    freed = est.structuralFreed();
    unexplained = est.unexplained;
    // nominal - E; a locked coefficient stays as run.
    c.axes = run;
    for (const Coefficient& k : c.coefficients)
      c.axes[k.axis].a[k.degree] = nominal[k.axis].coefficient(k.degree) - est.error[k.axis].a[k.degree];
    c.change.resize(static_cast<int>(c.coefficients.size()));
    for (size_t j = 0; j < c.coefficients.size(); ++j)
      c.change(static_cast<int>(j)) = c.axes[c.coefficients[j].axis].a[c.coefficients[j].degree] -
                                      run[c.coefficients[j].axis].a[c.coefficients[j].degree];
    sensitivities = est.jacobian;
    alongside = est.nuisance;
    steps = est.space.step;
    basis = est.space.basis;
    atSolution = est.atSolution;
    atRunMade = est.atRun;
    errorCoefficients = est.coefficientError;
  }
  c.unexplainedRms = unexplained.size() > 0 ? std::sqrt(unexplained.squaredNorm() / static_cast<double>(unexplained.size())) : 0.0;
  const SharpeningSetup& grinding = dressed ? *dressed : setup;  // the wheel the predicted faces are ground with
  auto after = predictedFace(grinding, runFace, c.axes, c.identifiedError, unexplained, at, !dressed);
  if (!after) return after.error();
  c.after = *after;
  if (!linearisedAt) c.simulated = topographyFromNormal(runFace, normalOf(runFace));  // else the nominal axes' face
  // Within the noise: the measured sum of squares is what the probe's noise alone gives
  // (noiseCeiling). Then the verdict says to stop, and the axes run are kept: a change would only
  // move noise.
  const bool withinCeiling = c.before.sse <= noiseCeiling(runFace.size(), o.probeNoise);
  if (withinCeiling) c.axisShapes = axisShapesIn(runFace, measured, c.coefficients, o.probeNoise);
  c.stop = withinCeiling && !c.axisShapes->aboveNoise();
  // A correction that changes nothing says why in the verdict (verdictOf): what the face holds of
  // the axes' shapes.
  if (!c.stop && !c.axisShapes && c.changesNothing())
    c.axisShapes = axisShapesIn(runFace, measured, c.coefficients, o.probeNoise);
  if (c.stop) {
    c.axes = run;
    c.change.setZero();
    c.after = c.before;
  }
  // Never a proposal worse than the run: the same axes again grind the face measured. (A run that
  // holds moves the identification leaves out as amplifying, such as an earlier linear step's,
  // is where this happens.)
  if (!c.stop && c.after.sse > c.before.sse) {
    c.runKept = true;
    c.discardedSse = c.after.sse;
    c.axes = run;
    c.change.setZero();
    c.after = c.before;
  }
  c.roundedAxes = roundAsProgrammed(c.axes, o.resolution, setup.face.helical());
  const bool dressing = dressed && !c.keepsRun();  // a run kept keeps its wheel as well as its axes
  auto rounded = predictedFace(dressing ? *dressed : setup, runFace, c.roundedAxes, c.identifiedError, unexplained, at,
                               !dressing);
  if (!rounded) return rounded.error();
  c.afterRounded = *rounded;
  c.uncorrectableShare = c.before.sse > 0 ? std::min(1.0, c.after.sse / c.before.sse) : 0.0;

  std::vector<Coefficient> constants;
  for (Axis a : kAxes) constants.push_back(Coefficient{a, 0});
  const SensitivityMatrix S = sensitivityMatrix(runFace, constants);
  for (Axis a : kAxes) {
    const int i = static_cast<int>(a);
    c.identifiedErrorSize[i] = largestOverRange(c.identifiedError[a], a, range.min, range.max);
    // The degree-0 column of the axis: µm of face per mm or rad, to per µm or per µrad.
    c.facePerAxisError[i] = S.normal.col(i).cwiseAbs().maxCoeff() / displayFactor(a);
  }
  // An axis the face does not show to first order (X, Y and B on a straight gash) reads rounding
  // (Y 5.6e-17 µm per µm beside exact zeros for X and B, an independent review): below 1e-12 of the
  // largest axis's figure it is 0, not a figure.
  const double strongest = *std::max_element(c.facePerAxisError.begin(), c.facePerAxisError.end());
  for (double& v : c.facePerAxisError)
    if (v < 1e-12 * strongest) v = 0;
  c.axisChangeSize = axisChangeOver(c.axes, run, range);
  c.axisChangeOverFace = c.axisChangeSize;
  c.resolutionFloor = resolutionFloor(S.normal, o.resolution);
  // What the face reads about the machine (identified_axes.h), from the data the machine error made:
  // the measured change at the axes run, with the run face's sensitivities, so that nothing but the
  // data moves with the noise (docs/conventions.md). Joined with the pass history: what every face
  // shows, linearised at the identified error (machine_error.h); a linear step's, or one linearised
  // at the nominal axes: the misfit left plus what the identified error makes, at it. Where this
  // face needed the directions it shows only at second order (freed), they are read as at the run,
  // where they show nothing: the identifiable space's basis, not every coefficient (whether a face
  // is freed turns on its noise; read one way on some measurements and the other way on the rest,
  // a value spread twice its uncertainty on seed 20261125's scenario 550 of the calibration).
  const bool joined = c.passesJoined > 0 && historyJacobian.rows() == historyLinearised.size();
  const bool atRun = !joined && !linearisedAt && c.method == CorrectionMethod::Nonlinear;
  const Eigen::MatrixXd runSensitivities = atRun ? sensitivityMatrix(runFace, c.coefficients).normal : Eigen::MatrixXd();
  Eigen::MatrixXd readingBasis = basis;
  if (atRun && freed) {
    const IdentifiableSpace space = identifiableSpace(setup.face, run.degree(), o, reach);
    if (space.coefficients == c.coefficients) readingBasis = space.basis;
  }
  const Eigen::VectorXd linearised =
      joined ? historyLinearised
      : atRun ? Eigen::VectorXd(flat(Eigen::MatrixXd(measured - normalOf(runFace))))
      : sensitivities.cols() == errorCoefficients.size() && sensitivities.rows() == unexplained.size()
          ? Eigen::VectorXd(flat(unexplained) + sensitivities * errorCoefficients)
          : Eigen::VectorXd();
  // Read at the run, the data hold the error's second-order face too, which the linear reading takes
  // into the values: what the identified error's face holds beyond its first order (the face at E
  // less the run face less S E) is read alongside, so each value says how far it may be moved.
  Eigen::VectorXd secondOrder;
  if (atRun && runSensitivities.cols() == errorCoefficients.size() && unexplained.size() == measured.size())
    secondOrder = linearised - flat(unexplained) - runSensitivities * errorCoefficients;
  c.identified = identifiedAxes(c.coefficients, steps, joined ? historyJacobian : atRun ? runSensitivities : sensitivities, alongside, linearised, range.min, range.max,
                                o.probeNoise, o, readingBasis,
                                atRun && !freed && !atRunMade.empty() ? &atRunMade : nullptr,
                                secondOrder.size() == linearised.size() ? &secondOrder : nullptr);
  // The axes the face does not show are proposed as nominal (nominal - 0): a run off nominal on
  // them is changed back, which the face neither asks for nor shows; the unseen axes' sentence
  // (the last) says so, with the change.
  if (!c.identified.unseen.empty() && !c.identified.sentences.empty()) {
    const std::array<double, kAxisCount> fromNominal = axisChangeOver(c.axes, nominal, range);
    std::vector<Axis> changed;
    for (Axis a : c.identified.unseen) {
      const size_t i = static_cast<size_t>(a);
      const double halfStep = 0.5 * o.resolution.step[i] * (isRotary(a) ? kRadPerDeg * 1e6 : 1.0);  // µm or µrad
      if (std::abs(c.axisChangeSize[i]) > halfStep && std::abs(fromNominal[i]) < 1e-6 * halfStep) changed.push_back(a);
    }
    const std::string back = backToNominalSentence(changed, c.axisChangeSize);
    if (!back.empty()) c.identified.sentences.back() += " " + back;
  }
  // One quantity: the uncertainty is the change per µm of noise times sigma. The identified error's
  // spread is its identification's, at the identified error (from the decomposition the
  // identification made there, where it made one and nothing was identified alongside); the values
  // read are the measured change's, at the run.
  const bool decomposed = alongside.cols() == 0 && atSolution.directions.rows() == static_cast<int>(c.coefficients.size());
  const std::array<double, kAxisCount> spread =
      !atRun ? c.identified.spreadPerNoise
      : decomposed
          ? axisSpreadPerNoise(c.coefficients, steps, atSolution, range.min, range.max)
          : axisSpreadPerNoise(c.coefficients, steps, sensitivities, alongside, range.min, range.max, basis);
  for (int i = 0; i < kAxisCount; ++i) {
    c.changePerNoise[i] = spread[static_cast<size_t>(i)];
    c.uncertainty[i] = c.changePerNoise[i] * o.probeNoise;
  }
  {
    const FacePrediction p =
        predictFace(setup, dressing ? *dressed : setup, run, runFace, c, unexplained, o.probeNoise,
                    UnseenSampling{c.passesJoined > 0 ? &historyJacobian : freed ? &sensitivities : nullptr,
                                   c.passesJoined > 0, wheelAlongside, identified ? &identified->mimicking : nullptr});
    c.predictedRms = p.rms;
    c.predictedRmsHigh = p.rmsHigh;
    c.predictedNoisePart = p.noisePart;
    c.predictedUnseenPart = p.unseenPart;
    c.predictedUngrindable = p.ungrindable;
    c.predictedWheelAlike = p.wheelAlike;
    c.predictedFoldMargin = p.foldMargin;
    c.predictedFoldAt = p.foldAt;
  }
  // The wheel is corrected where this case asks for it, where the error was identified with the
  // wheel alongside (which only a wheel correction does), or where an earlier pass dressed it.
  const bool wheelCorrected = o.wheel || wheelAlongside || dressedBefore;
  c.verdict = verdictOf(c, o, runFace.size(),
                        c.method == CorrectionMethod::Nonlinear && joinsLaterPasses(!runFace.atProbes(), wheelCorrected));
  // A stop is the whole instruction: the history's sentence would only lengthen it.
  if (!c.stop && c.passesJoined > 0)
    c.verdict += " The machine's error was identified from this face and the " + std::to_string(c.passesJoined) +
                 (c.passesJoined == 1 ? " earlier pass's face" : " earlier passes' faces") +
                 " together: one error explains them all to the probe noise" + historyLeftOut + ".";
  else if (!c.stop && !historyNote.empty())
    c.verdict += " " + historyNote;
  if (c.linearisedAtNominal)
    c.verdict += " The face the axes run grind without the machine's error cannot be simulated (the wheel would not "
                 "envelop it): the correction was linearised at the nominal axes, from the face measured.";
  // Joined settles the sign only where the pass it is checked against is among the faces joined:
  // every one (a pass whose face cannot be simulated is left out of the join, machine_error.cpp).
  if (history)
    leadWithSign(c, historySign(runFace, run, measured, history->passes.back(), o.probeNoise,
                                c.passesJoined == static_cast<int>(history->passes.size())));
  return c;
}

}  // namespace hobsharp
