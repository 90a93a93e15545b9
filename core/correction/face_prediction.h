// What a pass will leave on the probe grid, with a bound (docs/method.md, "Correction"; issue 20): the
// face the proposed exact axes grind, µm rms, and an upper figure that folds in
//   - the misfit the identified error leaves, its shape: the misfit's sum of squares less the noise's
//     expectation, plus three standard deviations of the noise's sum of squares (chi-square), and
//     never more than the misfit itself (all of it after a stop),
//   - the probe noise carried through the identified directions (k of them: sigma² (k + 3 sqrt(2k))),
//   - what the face cannot show: the machine's error along directions that do not move the
//     measured face to first order (the structural null space, numerically null directions) moves
//     it at second order. At the measured operating point the identification takes the part of that
//     which its directions make for axis error (and the axes then compensate an error that is not
//     there); at the new operating point it moves the face again. It is sampled: errors of the
//     identified error's size, per term of every axis (mm on X, Y, Z; rad times the grid's tip
//     radius on A, B, the tip's displacement), in the directions the face cannot show, added to the
//     identified error; the run and the proposed axes re-simulated with each; the bound takes the
//     largest of (the face moved at the new point) - (the visible part of the face moved at the
//     measured point). With the wheel alongside, also the error less twice its part along the axis
//     changes that mimic a wheel shape (`mimicking`): that part might be the wheel's.
// Beside the bound, the fold check (fold_margin.h): where, with an error the face cannot show of the
// samples' radius, a point of the face the pass grinds may come to a fold of the envelope (the wheel
// stops reaching it), the pass is uncertain and the verdict names the point.
// The last two rest on an assumption, stated in the verdict: the error the face cannot show (or cannot
// tell from the wheel's shape) is no larger than the one it shows.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "correction.h"
#include "ground_face.h"
#include "outcome.h"
#include "sharpening_setup.h"

namespace hobsharp {

struct FacePrediction {
  double rms = 0;      // µm: the predicted face, the misfit less its expected noise
  double rmsHigh = 0;  // µm: the bound
  double noisePart = 0, unseenPart = 0;  // µm rms: the bound's noise and second-order shares
  // Sampled errors with which the face the pass grinds cannot be simulated (the wheel would not
  // reach part of it). The bound cannot say for those, nor for the ones with which the face measured
  // cannot be simulated, which are not counted here.
  int ungrindable = 0;
  // How near the face the pass grinds is to a fold with an error the face cannot show, of the
  // samples' radius (fold_margin.h): the margin, and the point where it is below the check's limit
  // (face_prediction.cpp, kFoldMargin), where the wheel may stop enveloping the face.
  double foldMargin = std::numeric_limits<double>::infinity();
  std::optional<GridPoint> foldAt;
  // The unseen share includes the wheel shape the face cannot tell from the axes (`mimicking`).
  bool wheelAlike = false;
};

// `c` is the correction with its axes, identified error and predicted face (c.after) filled;
// `measuredSetup` the setup the measured face was ground with, `passSetup` the one the pass grinds
// with (the dressed wheel when there is one); `run` the axes run; `runFace` the face they ground
// without error, with its sensitivities, at the measurement's points; `unexplained` measured minus
// the identified model.
// How the bound samples the error the face cannot show.
struct UnseenSampling {
  // When given, the sensitivity matrix (points x c.coefficients, µm per unit) at the identified
  // error of the faces it was identified from, in place of the run face's at E = 0:
  //   - `passes`: every pass's face (the pass history's and this one, machine_error.h); the
  //     directions the face cannot show are those none of them shows (below kUnseenShareJoined of
  //     the strongest);
  //   - otherwise this face's, when the identification freed the structural null space
  //     (structuralFreed): at E the second-order change shows those directions, weakly; the ones
  //     it does not show are below kUnseenShare, as on the run face.
  const Eigen::MatrixXd* shownBy = nullptr;
  bool passes = false;
  // The model's faces hold more than the axes make (the wheel's shape identified alongside,
  // wheel_error.h), so a face re-simulated with the identified axis error alone is not the model's
  // face: the faces each sampled error moves are measured from re-simulated faces without it, at
  // the measurement and after the pass, not from the model's. (Taken from the model's, the wheel's
  // shape, 1 µm rms and more, read as a move of the face and made the bound 10 to 1000 times the
  // face left on the campaign's wheel passes.)
  bool fromResimulated = false;
  // With the wheel alongside: the axis changes that make the face of a wheel shape the wheel left to
  // the axes (q x m, coefficient units; machine_error.h, `mimicking`). The face cannot tell those
  // from the wheel, and they move the face at the new operating point as the axes, not as the wheel,
  // do: they are sampled with the directions the face cannot show.
  const Eigen::MatrixXd* mimicking = nullptr;
};

// What the pass leaves, as c's prediction and its bound state it, for a verdict: "the face
// measured 3 µm rms will be left at most 0.05 µm rms[ with the exact axes] [if the error the face
// cannot show is no larger than the one it shows][; quantising each axis position to the machine's
// resolution sets a floor of about 0.03 µm rms, which no pass goes below]": the bound, never the
// model's figure below it, and the pass's floor (c.resolutionFloor) where the bound lies below it.
std::string predictionText(const Correction& c);
// What c's bound (predictedRmsHigh) assumes, in the verdict's words: "if the error the face cannot
// show is no larger than the one it shows" (or "..., or cannot tell from the wheel's shape, ..."),
// with the wheel's correction also "if the wheel's shape between the probe rows is one a smooth
// curve through its 5 points makes (...)"; "" where it assumes nothing.
std::string predictionCondition(const Correction& c);

FacePrediction predictFace(const SharpeningSetup& measuredSetup, const SharpeningSetup& passSetup,
                           const AxisPolynomials& run, const GroundFace& runFace, const Correction& c,
                           const Eigen::MatrixXd& unexplained, double probeNoise, const UnseenSampling& sampling = {});

}  // namespace hobsharp
