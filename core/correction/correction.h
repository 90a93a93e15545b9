// The correction of a measured face. The paper's step of Eq. 17: the changes of the chosen
// polynomial coefficients that cancel a measured topography in the least-squares sense, by a
// truncated SVD of the column-scaled sensitivity matrix, with the thickness error at the mean
// point as one more equation (Eq. 16). And the default: identify the machine error by nonlinear
// least squares (machine_error.h), then run nominal - error.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "correction_options.h"
#include "ground_face.h"
#include "history_sign.h"
#include "identified_axes.h"
#include "outcome.h"
#include "sensitivity_matrix.h"
#include "sharpening_setup.h"
#include "topography.h"
#include "unobservable.h"

namespace hobsharp {

// What a measured face holds of the shapes the free coefficients make, against the probe noise
// (measured_face_correction.cpp, the stop's test): along the strongest single direction of the run
// face's sensitivities, and in their span together.
struct AxisShapes {
  double largestSigmas = 0;   // the largest component along one direction, in sigma
  double togetherSigmas = 0;  // the span's sum of squares above its chi-square mean, in its standard deviations
  bool single = false;        // one direction stands out of the noise
  bool together = false;      // the span does, no direction need alone
  bool aboveNoise() const { return single || together; }
};

struct Correction {
  AxisPolynomials axes;                  // the proposal: run + change (linear), nominal - E (nonlinear)
  std::vector<Coefficient> coefficients; // the free coefficients
  Eigen::VectorXd change;                // their changes, in their units
  Topography before;                     // the measured topography
  Topography after;                      // the predicted face after the pass
  // The face the axes run grind with no machine error, at the measurement's points and read as
  // `before` is (its thickness as topography.h reads a measurement): the pass history's prediction
  // for a first pass. correctMeasuredFace fills it, except where the axes run alone cannot be
  // simulated (linearisedAtNominal).
  Topography simulated;
  Eigen::VectorXd singularValues;        // of the scaled matrix, largest first
  int rank = 0;                          // directions used in the step
  int amplifyingDropped = 0;             // directions above the truncation left out (see options)
  std::vector<UnobservableCombination> unobservable;
  // The share of the sum of squares that no coefficient change can produce, 0..1.
  double uncorrectableShare = 0;
  std::string verdict;                   // one sentence for the engineer
  // The linear step's covariance of `change` per unit probe variance (sigma = 1 µm).
  Eigen::MatrixXd changeCovariancePerNoise;

  // What the engineer reads (docs/method.md, "Correction"), filled by correctMeasuredFace for either method.
  CorrectionMethod method = CorrectionMethod::Linear;
  LeastSquaresSummary summary;           // status, reason, iterations
  AxisPolynomials identifiedError;       // E: the machine's actual axes minus the commanded ones
  AxisPolynomials roundedAxes;           // `axes` as the NC program carries them (roundAsProgrammed)
  Topography afterRounded;               // the face predicted with roundedAxes, re-simulated
  // The pass's floor, µm rms on the probe grid: the face rms that quantising each axis position
  // to its resolution causes (resolutionFloor, machine_resolution.h).
  double resolutionFloor = 0;
  // Per axis, X Y Z A B, signed value of largest magnitude over the motion range: µm (X, Y, Z)
  // or µrad (A, B).
  std::array<double, kAxisCount> identifiedErrorSize{};
  std::array<double, kAxisCount> axisChangeSize{};      // axes - run axes
  // The same change over the motion range the program runs (the grid's): the figure above where
  // the face was measured on the grid; at measured points that span less, the change the program
  // makes beyond them (axisChangeOver; filled by the job, which has the grid's face).
  std::array<double, kAxisCount> axisChangeOverFace{};
  // The standard uncertainty of the identified error and of the change, per axis, from sigma:
  // changePerNoise times sigma, exactly (docs/conventions.md §What the engineer reads about the machine).
  std::array<double, kAxisCount> uncertainty{};
  // The precision demand: µm of face per µm or µrad of a constant axis error (largest over the
  // grid), and µm or µrad of axis change per µm of probe noise: the standard deviation of the
  // axis's curve over every direction the face shows (not only those the correction takes) among
  // those sought (the identifiable space; every coefficient where the face needed them), largest
  // over the motion range.
  std::array<double, kAxisCount> facePerAxisError{};
  std::array<double, kAxisCount> changePerNoise{};
  // What the face identifies of each axis, and the combinations it shows, in words (identified_axes.h).
  IdentifiedAxes identified;
  std::vector<bool> directionsUsed;      // per singular value: identified (true) or left out
  int withinNoise = 0;                   // directions left out: within the probe noise (nonlinear)
  // The correction found would leave a worse face than the one measured (re-simulated): the run
  // axes are proposed unchanged, and `discardedSse` is what the discarded proposal predicted, µm².
  bool runKept = false;
  double discardedSse = 0;
  // What the pass will leave on the probe grid, µm rms, and its bound (face_prediction.h).
  double predictedRms = 0, predictedRmsHigh = 0;
  double predictedNoisePart = 0, predictedUnseenPart = 0;  // the bound's shares, µm rms
  // Of the errors the bound samples (in the directions the face cannot show, and the error less its
  // part that mimics the wheel's shape: face_prediction.h), those with which the proposed axes grind
  // a face the wheel does not envelop everywhere.
  int predictedUngrindable = 0;
  // The bound also samples the wheel shape the face cannot tell from the axes' motion (the wheel
  // identified alongside; face_prediction.h, `mimicking`).
  bool predictedWheelAlike = false;
  // With the wheel's correction: the points of the spline its shape is identified as (wheel_error.h).
  // The probe grid does not show the wheel between its rows, so the bound assumes it that smooth.
  int wheelKnots = 0;
  // With an error the face cannot show, of the size the bound samples, the wheel may stop
  // enveloping the face the pass grinds (a fold of the envelope, fold_margin.h): the margin, and the
  // point where it falls below the check's limit (face_prediction.h).
  double predictedFoldMargin = std::numeric_limits<double>::infinity();
  std::optional<GridPoint> predictedFoldAt;
  // The measured face is within the probe noise: another pass would only move noise.
  bool stop = false;
  // The stop's test of the shapes the axes make, where it was taken (a face within the whole-face
  // ceiling, or a correction that changes nothing).
  std::optional<AxisShapes> axisShapes;
  // The axes run are proposed unchanged (run kept, or stop): so is the wheel, with no dressing.
  bool keepsRun() const { return runKept || stop; }
  // No coefficient is changed (every change 0, or none free): also where the identification took
  // no direction (wasm/lib/pass-bound.js, changesNothing, reads the same from correction.change).
  bool changesNothing() const { return change.size() == 0 || change.cwiseAbs().maxCoeff() == 0.0; }
  // A change is proposed whose bound is above the face measured, or with which some of the errors
  // the face cannot show leave part of the face unground: the face does not show enough of the
  // machine's error to say that the pass improves it (the verdicts lead with "Uncertain:"). A bound
  // below the face measured does not clear the second: on campaign seed 7005's scenario 344 it was
  // 106 of 149 µm, 4 of the 6 samples left part of the face unground, and so did the true machine.
  bool uncertain() const {
    return !keepsRun() && (predictedRmsHigh > before.rms || predictedUngrindable > 0 || predictedFoldAt.has_value());
  }
  // An uncertain change with which part of the face may stay unground: some of the errors the bound
  // samples leave part of it unground, or the wheel may stop enveloping it near a point (the
  // verdict's "part of it would stay unground").
  bool mayStayUnground() const {
    return !coefficients.empty() && uncertain() && (predictedUngrindable > 0 || predictedFoldAt.has_value());
  }
  // The face the pass leaves (`after`, over `points` values) is within twice the probe noise: its
  // rms at most twice the probe's sigma (the verdict's "to within twice the probe noise"). Looser
  // than the chi-square ceiling the status and the stop take (noiseCeiling, 1.28 sigma on 45
  // points): a misfit between the two holds axis directions left out within the noise as often as
  // a shape no axis makes, so it is not called uncorrectable (tried with the ceiling: 3 of the
  // committed campaign's 100 noisy passes, with no wheel shape, were told to correct the wheel).
  bool leavesWithinNoise(double probeNoise, int points) const {
    return after.sse <= points * std::pow(2 * probeNoise, 2);
  }
  // The axes run alone grind no face the wheel envelops (a pass after a large machine error): the
  // correction was linearised at the nominal axes instead, from the face measured.
  bool linearisedAtNominal = false;
  // The earlier passes whose measured faces the identified error explains together with this one
  // (machine_error.h); 0 when identified from this face alone.
  int passesJoined = 0;
  // The faces measured against the pass history's last one, as the change of the axes moves the
  // face (history_sign.h); nothing without a history or where the axes moved the face too little.
  std::optional<HistorySign> historySign;
  bool signReversed() const { return historySign && historySign->reversed; }

  // With a measurement at probe points (correctMeasuredPoints, docs/measured-points.md): `before`,
  // `after` and `afterRounded` hold one column, a value per point in the points' order, and their
  // figures are over the points. On the grid the plots show: the face the identified error grinds
  // with the axes run (the measurement as the axes explain it) and the predicted face, both
  // re-simulated, without the part no axis makes (known only at the points).
  ProbePoints probes;
  Topography explainedOnGrid, afterOnGrid;
  // µm rms over the measured values: what the identified error does not explain (the part no axis
  // makes, noise and all). At probe points the grid's maps and the inspection hold the explained
  // face alone, so this is how far they may be from the measurement (inspectEvaluation).
  double unexplainedRms = 0;
  bool atProbes() const { return !probes.empty(); }
};

// Per axis, X Y Z A B, the change proposed - run of largest magnitude over the motion range
// [range.min, range.max], signed: µm (X, Y, Z) or µrad (A, B).
std::array<double, kAxisCount> axisChangeOver(const AxisPolynomials& proposed, const AxisPolynomials& run,
                                              const MotionRange& range);

// The coefficients `o` locks at `degree`, in words: "Y" where the whole axis is, "Y a2, Y a3" where
// part of it is; "" without locks.
std::string lockedText(int degree, const CorrectionOptions& o);

// The verdict where every coefficient is locked: no change, and why (`rms`, the face measured, µm).
std::string allLockedText(double rms);

// The verdict for a face the free axes do not make (uncorrectableShare above correctableShare):
// "Partly uncorrectable: 42 % of the sum of squares is a shape no axis polynomial produces …;
// it stays in the residual<residual>." and what may remove it: the locked axes (`locked`,
// lockedText), and a dressing only for a shape along the radius (the wheel correction decides).
std::string uncorrectableText(double share, const std::string& locked, const std::string& residual);

// The paper's single linear step (Eq. 17), with the linear prediction in `after`.
Outcome<Correction> correctionStep(const GroundFace& run, const AxisPolynomials& runAxes,
                                   const Eigen::MatrixXd& measured, const CorrectionOptions& options);

// The correction of a measured face (measured: the face ground when `run` was commanded), by the
// chosen method, with every figure the engineer reads: for the nonlinear method the axes are
// nominal - E (machine_error.h); `after` and `afterRounded` are re-simulated with the nonlinear
// model, plus the part of the measurement no axis makes.
// `identified`, when given, is the machine error identified elsewhere (with the wheel,
// wheel_error.h): used in place of identifying it here (nonlinear method). `dressed`, when given,
// is the setup the predicted faces are ground with: the wheel as a dressing leaves it
// (wheel_correction.h), not the wheel `runFace` was ground with. `linearisedAt`, when given, is the
// axes `runFace` was simulated for instead of `run` (the nominal ones, where the run alone cannot be
// simulated); `identified`, when given with it, is the error identified from those axes. `history`,
// when given, is the earlier passes the error is identified together with (machine_error.h); an
// empty one is none, though its wheelCorrected still says whether a pass dressed the wheel.
struct MachineErrorEstimate;
struct PassHistory;
Outcome<Correction> correctMeasuredFace(const SharpeningSetup& setup, const AxisPolynomials& nominal,
                                        const AxisPolynomials& run, const GroundFace& runFace,
                                        const Eigen::MatrixXd& measured, const CorrectionOptions& options,
                                        const MachineErrorEstimate* identified = nullptr,
                                        const SharpeningSetup* dressed = nullptr,
                                        const AxisPolynomials* linearisedAt = nullptr,
                                        const PassHistory* history = nullptr);

// The sign check's finding (history_sign.h) into `c`: where the faces moved against the change of
// the axes, the verdict leads with "Check the sign:" (not after a stop: grinding ends there).
void leadWithSign(Correction& c, std::optional<HistorySign> sign);

// The same for a measurement at a measuring machine's probe points (µm, one per point): the
// correction's rows are exactly those points (the run face simulated there, its sensitivities
// there; nothing interpolated), and the grid views are filled (measured_points_correction.cpp).
// Refused as `measuredPoints` with fewer points than free coefficients.
Outcome<Correction> correctMeasuredPoints(const SharpeningSetup& setup, const AxisPolynomials& nominal,
                                          const AxisPolynomials& run, const FaceGrid& grid,
                                          const ProbePoints& probes, const Eigen::VectorXd& measured,
                                          const CorrectionOptions& options, const PassHistory* history = nullptr);

}  // namespace hobsharp
