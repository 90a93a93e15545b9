#include "sharpening_job.h"

#include <cmath>
#include <utility>

#include "correction_input.h"
#include "field_checks.h"
#include "grid_input.h"
#include "grid_words.h"
#include "hob_input.h"
#include "number_text.h"
#include "pass_history.h"
#include "run_axes.h"
#include "units.h"
#include "universal_settings.h"
#include "wheel_contact.h"
#include "wheel_input.h"
#include "wheel_profile.h"

namespace hobsharp {
namespace {

// How far the derived centre distance's rim may lie from the root, per mm of wheel radius (the
// boundary equation is solved to rounding; its other branches miss by tens of mm).
constexpr double kRimTolerance = 1e-6;
// How far a given centre distance's rim may pass the gash root, a share of the gash depth (a
// clearance the engineer sets on purpose; beyond it the rim grinds into the hob below the gash).
constexpr double kRimClearance = 0.1;
// The farthest derived centre distance, per mm of the wheel's and the hob's radii together.
constexpr double kFarthestCenterDistance = 4;

// The settings the case gives directly: the wheel's size, the setup's angles and centre
// distance, the machine constants and the axes' degree.
Outcome<void> checkSettings(const CaseInput& in) {
  if (auto r = positive("wheel.outerDiameter", in.wheelOuterDiameter, "mm"); !r) return r;
  if (!(std::abs(in.tilt) < 90)) return refuse("setup.tilt", "must lie between -90 and 90 deg; got " + exactText(in.tilt) + " deg.");
  if (in.settingAngle && !(std::abs(*in.settingAngle) < 90))
    return refuse("setup.settingAngle", "must lie between -90 and 90 deg; got " + exactText(*in.settingAngle) + " deg.");
  if (in.centerDistance)
    if (auto r = positive("setup.centerDistance", *in.centerDistance, "mm"); !r) return r;
  if (auto r = finite("machine.K1", in.machine.K1); !r) return r;
  if (auto r = finite("machine.K2", in.machine.K2); !r) return r;
  if (in.degree < kMinDegree || in.degree > kMaxDegree)
    return refuse("degree", "must be a whole number from " + std::to_string(kMinDegree) + " to " +
                                std::to_string(kMaxDegree) + "; got " +
                                std::to_string(in.degree) + ".");
  return success();
}

}  // namespace

Outcome<SharpeningJob> resolveJob(const CaseInput& in) {
  if (auto r = checkHob(in.hob); !r) return r.error();
  if (auto r = checkSettings(in); !r) return r.error();

  SharpeningJob job;
  job.outerRadius = in.hob.outerDiameter / 2;
  job.rootRadius = job.outerRadius - in.hob.gashDepth;
  job.wheelRadius = in.wheelOuterDiameter / 2;
  const ToothFace face = toothFace(in.hob);

  // The setting angle and the centre distance, given or derived (docs/conventions.md).
  job.settingAngleDerived = !in.settingAngle;
  const double gamma = in.settingAngle ? *in.settingAngle * kRadPerDeg : defaultSettingAngle(face);
  UniversalSettings universal = constantUniversalSettings(face, in.tilt * kRadPerDeg, gamma, 0.0);
  const double sign = outwardNormalSign(face, universal);
  job.centerDistanceDerived = !in.centerDistance;
  if (in.centerDistance) {
    universal.centerDistance = Polynomial::constant(*in.centerDistance);
  } else {
    auto E = centerDistanceFromWheelRim(face, universal, sign, job.rootRadius, job.wheelRadius);
    if (!E) return E.error();
    // Near a tilt of 90 deg the rim meets the root only from far away (2,875,195 mm at 89.999 deg on
    // the paper's hob; an independent review): farther than four times the wheel's and the hob's
    // radii together (the paper's hob: 69 mm at 15 deg, 308 mm at 80 deg) no machine's axes reach.
    const double farthest = kFarthestCenterDistance * (job.wheelRadius + job.outerRadius);
    if (*E > farthest)
      return refuse("setup.tilt", "at a tilt of " + numberText(in.tilt, 6) + " deg the wheel's rim meets the gash root only from a centre distance of " +
                                      mmText(*E) + ", more than " + numberText(kFarthestCenterDistance, 1) +
                                      " times the wheel's and the hob's radii together (" + mmText(farthest) +
                                      "), where no machine's axes reach. Check the tilt (the paper's example sets 15 deg).");
    universal.centerDistance = Polynomial::constant(*E);
  }
  job.setup = SharpeningSetup::make(face, universal, in.machine);

  // The wheel must reach the gash root and keep its axis clear of the tooth tip.
  auto ends = wheelProfile(face, universal, job.setup.normalSign, {job.rootRadius, job.outerRadius});
  if (!ends) return ends.error();
  if (ends->R[0] > job.wheelRadius + kGridTolerance)
    return refuse("wheel.outerDiameter",
                  "the wheel is too small to reach the gash root: at the root radius " + numberText(job.rootRadius) +
                      " mm the wheel needs a radius of " + numberText(ends->R[0]) + " mm, but it has " +
                      numberText(job.wheelRadius) + " mm. Use a larger wheel or a smaller setup.centerDistance.");

  // The wheel's rim at the gash root (docs/conventions.md, "The wheel's rim"). Derived, the centre
  // distance puts the rim on the root (the boundary equation), which the profile must confirm: a
  // setting angle of the wrong sign for the hand gave a solution on another branch (E = 6.27 mm on
  // the paper's hob, its profile 16.2 mm at the root for a rim of 50 mm; an independent review).
  // Given, the rim may pass the root by a clearance, not grind into the hob below the gash.
  const double rimPast = job.wheelRadius - ends->R[0];  // mm of wheel radius beyond the root's contact
  if (job.centerDistanceDerived && std::abs(rimPast) > kRimTolerance * (1 + job.wheelRadius))
    return refuse(in.settingAngle ? "setup.settingAngle" : "setup.tilt",
                  "no centre distance brings the wheel's rim (radius " + mmText(job.wheelRadius) + ") to the gash root with "
                  "this setting: the boundary equation's solution, " + mmText(universal.centerDistance.coefficient(0)) +
                  ", has the wheel's profile at " + mmText(ends->R[0]) + " at the root. Check the setting angle's sign for a " +
                  (in.hob.hand == Hand::Left ? "left" : "right") + "-hand hob (left out, it is derived: " +
                  numberText(defaultSettingAngle(face) * kDegPerRad, 5) + " deg), or give setup.centerDistance.");
  if (!job.centerDistanceDerived && rimPast > kRimClearance * in.hob.gashDepth) {
    auto atRoot = centerDistanceFromWheelRim(face, universal, sign, job.rootRadius, job.wheelRadius);
    return refuse("setup.centerDistance",
                  "the wheel's rim (radius " + mmText(job.wheelRadius) + ") reaches about " + mmText(rimPast) +
                      " past the gash root: at the root radius " + mmText(job.rootRadius) + " the wheel grinds with radius " +
                      mmText(ends->R[0]) + ", so its rim would grind into the hob below the gash (a clearance of at most " +
                      numberText(100 * kRimClearance, 2) + " % of the gash depth, " + mmText(kRimClearance * in.hob.gashDepth) +
                      ", is taken as set on purpose). " +
                      (atRoot ? "The rim touches the root at a centre distance of " + mmText(*atRoot) + "; give about that, or leave "
                                "setup.centerDistance out to have it derived, or use a smaller wheel."
                              : "Give a larger centre distance or use a smaller wheel."));
  }

  // The conjugate wheel's profile, and where it turns back below the tip: the face above lies
  // past the edge of the wheel's envelope (docs/method.md).
  auto profile = wheelProfile(face, universal, job.setup.normalSign, evenRadii(job.rootRadius, job.outerRadius, kWheelProfilePoints));
  if (!profile) return profile.error();
  job.wheelProfile = std::move(profile).value();
  if (auto turn = profileTurnRadius(face, universal, job.setup.normalSign, job.wheelProfile))
    job.setup.wheelEdge = WheelEdge{*turn, job.outerRadius};

  // The wheel as dressed or measured (wheel_input.h), or the conjugate wheel.
  auto wheel = resolveWheelSurface(in, job.setup, job.rootRadius, job.outerRadius);
  if (!wheel) return wheel.error();
  job.setup.wheel = std::move(wheel).value();
  job.wheelMeasured = in.wheelMeasuredProfile.has_value();

  auto pitch = contactCoordinate(face, universal, job.setup.normalSign, 0.0);
  if (!pitch) return pitch.error();
  const double xCentre = face.axialAt(*pitch);
  auto grid = faceGrid(in.grid, FaceExtent{job.rootRadius, job.outerRadius, in.hob.length, xCentre});
  if (!grid) return grid.error();
  job.grid = std::move(grid).value();

  job.nominalAxes = cncAxisPolynomials(universal, in.machine, in.degree);
  auto run = runAxes(in.axes, job.nominalAxes, in.degree);
  if (!run) return run.error();
  job.runAxes = std::move(run).value();
  // The motion over the hob's length: phi = x / p on a helical gash (rad), x on a straight one (mm).
  const double reach = (in.hob.length / 2 + std::abs(xCentre)) / (face.helical() ? std::abs(face.screwParameter) : 1.0);
  if (in.axes)
    if (auto r = checkNearNominal(job.runAxes, job.nominalAxes, reach, "axes"); !r) return r.error();

  // Where the measuring machine's points may lie (docs/measured-points.md).
  const PointRegion region{job.rootRadius, job.outerRadius,
                           in.hob.length / 2 + std::abs(xCentre) + kGridTolerance * (1 + in.hob.length),
                           kGridTolerance, kMaxDeviation};
  auto measured = measuredFace(in.measured, in.measuredPoints, job.grid, region);
  if (!measured) return measured.error();
  job.measured = std::move(measured).value();
  if (auto r = checkPasses(in.passes, in.degree, job.grid, region); !r) return r.error();
  for (size_t i = 0; i < in.passes.size(); ++i)
    if (auto r = checkNearNominal(in.passes[i].axes, job.nominalAxes, reach, "passes[" + std::to_string(i) + "].axes"); !r)
      return r.error();

  auto options = correctionOptions(in.correction, in.degree, "correction");
  if (!options) return options.error();
  job.correction = *options;
  job.history = passHistory(in.passes, job.nominalAxes, job.correction.wheel);
  // One equation per value, as measured points (measured_points_correction.cpp): a grid of fewer
  // values than free coefficients cannot decide them (a 2 x 2 grid at degree 6 was called
  // "Correctable" from 4 values for 35 coefficients; an independent review).
  if (job.measured.grid) {
    const int free = freeCoefficients(in.degree, job.correction);
    if (job.grid.size() < free)
      return Error{"measured", gridWords("measured") + ": " + std::to_string(job.grid.size()) + " values are too few for the " +
                                   std::to_string(free) + " free coefficients of degree " + std::to_string(in.degree) +
                                   " (one equation per value): measure a grid of at least " + std::to_string(free) +
                                   " values, or lower the degree, or lock coefficients.",
                   ErrorCode::InvalidInput};
  }
  if (job.correction.wheel && job.measured.atPoints())
    return refuse("correction.wheel", "is not available for measured points off the grid yet: give the points at the "
                                      "grid's positions (or the grid as `measured`) to correct the wheel too.");

  auto inspection = inspectionPlan(in.inspection, in.hob.normalModule, job.grid, in.hob.relief.gashes);
  if (!inspection) return inspection.error();
  job.inspection = std::move(inspection).value();
  job.gear = gearPlan(in.hob);
  return job;
}

}  // namespace hobsharp
