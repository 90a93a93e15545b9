// A sharpening job as the case file `hobsharp-case/1` states it (docs/case-format.md), in the
// file's units: lengths in mm, angles in degrees, coefficients in SI with the motion parameter,
// deviations in µm. Optional fields are empty when the file leaves them out.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "correction_input.h"
#include "grid_input.h"
#include "hob_input.h"
#include "inspection_input.h"
#include "measured_points.h"

namespace hobsharp {

// One grinding pass of the history: the axes the machine ran and the face measured after it, as
// a grid (µm, grid.radial x grid.axial) or as the measuring machine's points, as `passes` holds
// them (docs/case-format.md).
struct PassInput {
  AxisPolynomials axes;
  Eigen::MatrixXd measured;  // empty when the pass gives measuredPoints
  std::optional<std::vector<MeasuredPoint>> measuredPoints;
  std::optional<CorrectionInput> correction;  // the options its correction was computed with
};

// Points along the wheel's radius as the case gives them (docs/case-format.md §The wheel's
// profile): R with one value each, an offset (µm) or an axial position Z (mm).
struct WheelPointsInput {
  std::vector<double> R;       // mm
  std::vector<double> values;  // offset µm, or Z mm
};

// The job's record (`job`, docs/case-format.md): who and what the sharpening is for. Not used by
// the calculation; the printed report and the NC programs' headers name it. Empty when not given.
struct JobRecord {
  std::optional<std::string> number;     // the job or order number
  std::optional<std::string> customer;
  std::optional<std::string> hobSerial;  // the hob's serial number
  std::optional<std::string> operatorName;
  std::optional<std::string> notes;      // may hold line breaks
};
// The longest each of the job's texts may be, in characters (Unicode code points).
constexpr int kMaxJobText = 60, kMaxJobCustomer = 100, kMaxJobNotes = 1000;

// What the case file's `degree` defaults to (the grid's defaults: grid_input.h).
constexpr int kDefaultDegree = 4;

struct CaseInput {
  HobInput hob;
  double wheelOuterDiameter = 0;  // mm
  double tilt = 0;                // eta, deg
  std::optional<double> settingAngle;    // gamma_m, deg
  std::optional<double> centerDistance;  // E_t, mm
  MachineConstants machine;
  int degree = kDefaultDegree;
  GridInput grid;
  std::optional<AxisPolynomials> axes;      // what the machine ran
  std::optional<Eigen::MatrixXd> measured;  // µm, grid.radial x grid.axial
  CorrectionInput correction;
  std::vector<PassInput> passes;  // earlier passes, oldest first; the calculation does not use them
  InspectionInput inspection;     // per-gash deviations and an edited tolerance table (`inspection`)
  // The measuring machine's points, an alternative to `measured`; resolveJob() turns them into the
  // measured face (measured_face.h).
  std::optional<std::vector<MeasuredPoint>> measuredPoints;
  std::optional<WheelPointsInput> wheelProfileOffset;    // wheel.profileOffset: R mm, offset µm
  std::optional<WheelPointsInput> wheelMeasuredProfile;  // wheel.measuredProfile: R mm, Z mm
  JobRecord job;                                         // `job`: the record only
};

// The most points of a wheel's profile (wheel.profileOffset, wheel.measuredProfile): the wheel is
// fitted to every point (0.6 s for 1,000, 3.4 s for 4,000 in the page; memory runs out near
// 12,000), and a dressed wheel's profile has a few hundred.
constexpr int kMaxWheelPoints = 2000;

}  // namespace hobsharp
