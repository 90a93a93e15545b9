// The calibration of what the engineer reads about the machine, on random hobs (issue 20, item 5;
// docs/validation.md, "The uncertainty of the values read"): for each hob, one random machine error
// measured again and again with fresh probe noise; each value the page reads (an axis read alone,
// a combination's equivalent, a member's value alone) is collected with the standard uncertainty
// given with it, and its spread over the measurements is set against that uncertainty. A
// calibrated uncertainty gives a ratio near 1; the target is 0.7 to 1.4.
#pragma once

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
  double ratio() const { return given > 0 ? spread / given : 0.0; }
};

struct Calibration {
  CalibrationOptions options;
  int hobsRun = 0;          // hobs whose measurements were evaluated (refused ones counted in `refused`)
  int hobsFailed = 0;       // hobs not drawn or whose face could not be simulated
  int evaluations = 0, refused = 0;  // evaluations run; of them refused by the calculator
  int unstable = 0;         // values read in some measurements but fewer than leastShareRead
  std::vector<CalibratedValue> unstableValues;  // those values (read: how many times)
  std::vector<CalibratedValue> values;  // the values judged
  double seconds = 0;
  int within() const;       // values whose ratio lies in [low, high]
};

Calibration runCalibration(const CalibrationOptions& options, unsigned threads);
nlohmann::json toJson(const Calibration& c);
std::string calibrationText(const Calibration& c);  // the summary as the terminal prints it

}  // namespace hobsharp::validation
