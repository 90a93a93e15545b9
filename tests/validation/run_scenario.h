// One scenario run as an engineer would (docs/validation.md): measure the face the machine
// grinds (the module's simulation of the erroneous axes and wheel, plus noise), load it into the
// case, evaluate, run the proposed axes (and dressing) on the machine, measure again; and judge
// each pass on the probe grid and on a grid four times as dense, between the probe points.
#pragma once

#include <string>
#include <vector>

#include "scenario.h"

namespace hobsharp::validation {

// How many times denser the judging grid is than the probe grid, in each direction.
constexpr int kDenseFactor = 4;

struct PassOutcome {
  bool refused = false;      // the calculator refused the case (message says why)
  // The calculator proposed, but the machine, with its true error (and the dressing proposed),
  // does not grind the proposal's face in full: the module finds no wheel position for part of it,
  // which would stay unground (message says where). Not a refusal; the pass is missed all the same.
  bool unground = false;
  std::string message;
  double measuredRms = 0;    // the measurement's rms (with the noise), µm
  double probeRms = 0;       // the face the pass leaves, on the probe grid, noise-free, µm
  double denseRms = 0;       // the same between the probe points (the dense grid), µm
  double denseRmsRounded = 0;  // ... with correction.roundedAxes run, µm
  double predictedRms = -1;      // correction.predictedRms, µm (-1: not given)
  double predictedRmsHigh = -1;  // correction.predictedRmsHigh, µm (-1: not given)
  double foldMargin = 0;  // correction.predictedFoldMargin (capped for the JSON)
  double predictedUnseenPart = 0;  // the bound's share for the error the face cannot show, µm rms
  std::string status;        // correction.summary status
  std::string verdict;
  int rank = 0, withinNoise = 0, amplifying = 0, iterations = 0;  // how the identification went
  bool stopAdvised = false;
  bool linearisedAtNominal = false;  // the axes run alone could not be simulated
  int passesJoined = 0;              // correction.passesJoined: earlier passes identified with
  // correction.historySign (history_sign.h): the measured face change along the one the axes'
  // change makes, per that (+1 as simulated; 2: no check), and whether the sign was called reversed
  // (the campaign's faces are signed as the calculator signs them: every one is a false alarm).
  double signAlong = 2;
  double signCosine = 2;  // correction.historySign's cosine (2: no check)
  bool signReversed = false;
  int unsolvableTrials = 0;          // trial faces the wheel could not grind (rejected steps)
  // The twin machine: the one whose error is the identified one (correction.identifiedError), on a
  // pass without a wheel correction. twinMisfit: its face against the measurement, on the probe
  // grid (µm rms; how well one face tells the two machines apart); twinGap: how far apart the
  // proposed axes leave the two machines' faces, between the probe points (µm rms). -1: not
  // computed (a wheel pass, or a face that cannot be simulated). The proposal corrects the twin
  // exactly (nominal - its error), so twinGap is the face the pass leaves, to rounding.
  double twinMisfit = -1, twinGap = -1;
  // The first pass of a scenario without a wheel shape: the face, between the probe points (µm rms),
  // that the true error's part in the structural null space (structural_null_space.h: on a straight
  // gash its X, Y and B terms, on a helical one X against A) grinds alone, the axes run being
  // otherwise exact: what a correction exact in every direction a face shows to first order, and
  // blind to the rest, leaves. -1: not computed (a later pass, a wheel shape, a face not simulated).
  double nullPartRms = -1;
  double probeNoise = 0;  // the probe noise declared in the case (sigma, µm)
  // The pass left a face to judge: the calculator proposed, and the machine ground it.
  bool ground() const { return !refused && !unground; }
};

struct ScenarioOutcome {
  Scenario scenario;
  bool judged = true;        // false when the judging grid itself cannot be simulated (message)
  std::string message;
  double initialDenseRms = 0;  // the face before the first pass, between the probe points, µm
  std::vector<PassOutcome> passes;
  double seconds = 0;        // wall time of the scenario
};

// cases: where given, each pass's case as the calculator evaluated it is appended (case_file.h).
// `signReversed`: every face measured with the other sign (a measuring machine that signs deviations
// the other way round; validate --sign-reversed), to measure how often the history's sign check
// (history_sign.h) catches it.
ScenarioOutcome runScenario(const Scenario& scenario, std::vector<CaseInput>* cases = nullptr, bool signReversed = false);

}  // namespace hobsharp::validation
