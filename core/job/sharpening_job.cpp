#include "sharpening_job.h"

#include <cmath>
#include <utility>

#include "correction_input.h"
#include "field_checks.h"
#include "grid_input.h"
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

  // Where the measuring machine's points may lie (docs/measured-points.md).
  const PointRegion region{job.rootRadius, job.outerRadius,
                           in.hob.length / 2 + std::abs(xCentre) + kGridTolerance * (1 + in.hob.length),
                           kGridTolerance, kMaxDeviation};
  auto measured = measuredFace(in.measured, in.measuredPoints, job.grid, region);
  if (!measured) return measured.error();
  job.measured = std::move(measured).value();
  if (auto r = checkPasses(in.passes, in.degree, job.grid, region); !r) return r.error();

  auto options = correctionOptions(in.correction, in.degree, "correction");
  if (!options) return options.error();
  job.correction = *options;
  job.history = passHistory(in.passes, job.nominalAxes, job.correction.wheel);
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
