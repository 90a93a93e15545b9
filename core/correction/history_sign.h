// Whether the faces measured run with the calculator's sign, from the pass history (docs/method.md
// §The sign against the pass history). Between an earlier pass (the last measured on the grid, or
// the last at the same points) and this one the machine's error is the same, so the measured face moved by what the change of the axes
// moves it: S (run - earlier axes), S the run face's sensitivities (Eqs. 13-16), to first order. A
// measuring machine that signs deviations the other way moves it by minus that, and every
// correction from its faces adds to the error instead of cancelling it (docs/conventions.md §Sign).
#pragma once

#include <optional>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "earlier_passes.h"
#include "ground_face.h"

namespace hobsharp {

struct HistorySign {
  double predictedRms = 0;  // µm rms on the grid: the face change the axes' change makes, S (run - earlier)
  double along = 0;         // the measured face change along it, per the predicted: +1 as simulated, -1 reversed
  double alongSigmas = 0;   // that component against the two faces' probe noise (sigma sqrt 2)
  double cosine = 0;        // between the measured and the predicted change: +1 as simulated, -1 reversed
  // Called reversed: along <= kReversedAlong and cosine <= -kReversedCosine (the measured change is
  // minus the predicted one, not a change of another shape that happens to lean against it), both
  // the predicted change and its component stand out of the noise, and no one machine error
  // explains the faces together (`joined` false). A joined history is explained to the noise by one
  // error, as signed: that settles it. The first-order prediction alone does not: after a 150 µm
  // error a change along directions the run face barely shows moves the face at second order, and
  // once it read along -4.4 (cosine -0.42) on a history one error explains (seed 1006, scenario 56),
  // which the linear method or a locked axis would not have joined (an independent review,
  // 2026-12-07; docs/method.md).
  bool reversed = false;
};

// The check against an earlier pass measured on the same rows as this face (the history's last
// pass measured on the grid, or its last at the same points); nothing where the rows differ, or
// where the axes did not change enough to move the face out of the noise (a floor of kSignFloor µm
// of sigma where none is declared). `joined`: the identification explained this face and the
// earlier pass together (it was among the faces the identification joined).
std::optional<HistorySign> historySign(const GroundFace& runFace, const AxisPolynomials& run,
                                       const Eigen::MatrixXd& measured, const EarlierPass& earlier, double probeNoise,
                                       bool joined);

// The earlier pass a face measured at `probes` is checked against: the history's last pass at the
// same points (each within 1e-9 mm), or none.
const EarlierPass* earlierAtSamePoints(const PassHistory& history, const ProbePoints& probes);

}  // namespace hobsharp
