// The calibration of what the engineer reads about the machine, on random hobs (issue 20, item 5;
// docs/validation.md, "The uncertainty of the values read"): for each hob, one random machine error
// measured again and again with fresh probe noise; each value the page reads (an axis read alone,
// a combination's equivalent, a member's value alone) is collected with the standard uncertainty
// given with it, and its spread over the measurements is set against that uncertainty. A
// calibrated uncertainty gives a ratio near 1; the target is 0.7 to 1.4.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hobsharp::validation {

struct CalibrationOptions {
  std::uint64_t seed = 20261125;
  int hobs = 300;        // random hobs (scenarios of the noisy class: 10 µm rms error)
  int firstHob = 0;      // the first: hob h is the campaign's scenario 6 h + 4 of the seed
  int measurements = 30; // probe-noise draws per hob
  double sigma = 0.5;    // probe noise, µm (declared as correction.probeNoise)
  // A value is judged when the page reads it in at least this share of the measurements (the
  // reading of an axis can change with the noise: alone in some measurements, together in others).
  double leastShareRead = 2.0 / 3.0;
  double low = 0.7, high = 1.4;  // the ratio asked: spread / uncertainty given
  // The machine error drawn, times this (1: the noisy class's 10 µm rms; 3: about 30 µm rms).
  double errorScale = 1;
  // Only the error's constant terms (an offset on each axis, as a machine that is set off has):
  // axes are then read alone more often, and those values are judged against the true error.
  bool offsetsOnly = false;
  // Each value is judged against the true error too: the same value read from the face the true
  // error makes to first order (the nominal face plus its sensitivities times the error), without
  // noise, the value the reading stands for. Its mean over the measurements should lie within this
  // many of its standard uncertainties of that (beyond it: a value wrong by more than it says).
  double truthWithin = 3;
  // A parametric bootstrap of each hob's first measurement (0: none): the face the identified error
  // grinds, measured this many times with fresh probe noise of the same sigma and identified again
  // as the page does; each axis curve's spread over those draws is set against the spread over the
  // measurements (AxisSpread::bootstrap). What a per-axis spread of one proposal, computed from its
  // own measurement alone, would give.
  int bootstrapDraws = 0;
};

// One value the page reads on one hob, over the measurements that read it.
struct CalibratedValue {
  int hob = 0;             // scenario index of the campaign's seed
  std::string what;        // e.g. "Z alone", "Y-equivalent of Y, Z, A", "A alone of Y, Z, A"
  std::string unit;        // µm or µrad
  int read = 0;            // measurements that read it
  double mean = 0;         // mean of the values read
  double spread = 0;       // their standard deviation (n - 1)
  double given = 0;        // root mean square of the standard uncertainties given with them
  // The value read from the true error's first-order face, noise-free (where it is read there).
  bool hasTruth = false;
  double truth = 0;
  // The mean of how far the error's second order may move the value, as each measurement said
  // (identified_axes.h, secondOrder); and of the measurements, how many read it within 3
  // uncertainties plus that of the truth.
  double secondOrder = 0;
  int drawsNearTruth = 0;
  double ratio() const { return given > 0 ? spread / given : 0.0; }
  // How far the mean read lies from the truth, in uncertainties given (0 without a truth).
  double miss() const { return hasTruth && given > 0 ? std::abs(mean - truth) / given : 0.0; }
  // The mean within truthWithin uncertainties plus the second-order figure of the truth.
  bool withinStated(double within) const { return hasTruth && std::abs(mean - truth) <= within * given + secondOrder; }
};

// One axis of the identified error (correction.identifiedError) on one hob, over the measurements:
// its curve's standard deviation, largest over the motion range the face spans, against the root
// mean square of the per-axis figure the result gives beside it (correction.uncertainty, the
// precision demand times the probe noise; docs/conventions.md). The figure is the spread over every
// direction the face shows, as if each were taken; the identification takes only those the data
// hold above the noise, so this says how far the figure is from what the proposal does.
struct AxisSpread {
  int hob = 0;
  std::string axis;  // X, Y, Z, A, B
  std::string unit;  // µm or µrad
  double spread = 0;  // largest over the range of the curve's standard deviation (n - 1)
  double given = 0;   // root mean square of correction.uncertainty over the measurements
  // With bootstrapDraws: the same spread over the bootstrap of the first measurement (0 where the
  // bootstrap never moves the axis, or was not run).
  double bootstrap = 0;
  double ratio() const { return given > 0 ? spread / given : 0.0; }
  // The spread over the measurements against the bootstrap's (0 without a bootstrap figure).
  double bootstrapRatio() const { return bootstrap > 0 ? spread / bootstrap : 0.0; }
  bool figureOver(double factor) const { return ratio() * factor < 1; }  // given above factor times the spread
  bool figureUnder(double share) const { return ratio() * share > 1; }   // given below share of the spread
};

struct Calibration {
  CalibrationOptions options;
  int hobsRun = 0;          // hobs whose measurements were evaluated (refused ones counted in `refused`)
  int hobsFailed = 0;       // hobs not drawn or whose face could not be simulated
  int evaluations = 0, refused = 0;  // evaluations run; of them refused by the calculator
  int unstable = 0;         // values read in some measurements but fewer than leastShareRead
  std::vector<CalibratedValue> unstableValues;  // those values (read: how many times)
  std::vector<CalibratedValue> values;  // the values judged
  std::vector<AxisSpread> axisSpreads;  // per hob, each axis whose identified error moves with the noise
  double seconds = 0;
  int within() const;       // values whose ratio lies in [low, high]
  int withTruth() const;    // values also read from the true error's first-order face
  int nearTruth() const;    // of them, those within truthWithin uncertainties of it
  int nearTruthStated() const;  // ... within truthWithin uncertainties plus the second-order figure
  int draws() const, drawsNearTruth() const;  // the same per measurement, over the values with a truth
  int axisSpreadsWithin() const;            // axis spreads whose ratio lies in [low, high]
  int figureOver(double factor) const;      // ... whose figure given is more than factor times the spread
  int figureUnder(double share) const;      // ... whose figure given is less than share of the spread
  // With bootstrapDraws: the axis spreads whose bootstrap figure is there (moved by the bootstrap),
  // of them those whose spread over the measurements lies within [low, high] times it, and those
  // whose spread is more than `factor` times it (the bootstrap a figure more certain than it is).
  int bootstrapMoved() const, bootstrapWithin() const;
  int bootstrapUnder(double factor) const;
};

Calibration runCalibration(const CalibrationOptions& options, unsigned threads);
nlohmann::json toJson(const Calibration& c);
std::string calibrationText(const Calibration& c);  // the summary as the terminal prints it

}  // namespace hobsharp::validation
