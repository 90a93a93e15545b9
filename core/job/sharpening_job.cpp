#include "sharpening_job.h"
#include "number_text.h"
#include "grid_words.h"
#include "probe_points.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "units.h"
#include "universal_settings.h"
#include "wheel_contact.h"
#include "wheel_input.h"
#include "wheel_profile.h"

namespace hobsharp {
namespace {

Outcome<void> positive(const std::string& field, double v, const char* unit) {
  if (!std::isfinite(v)) return refuse(field, "must be a finite number.");
  if (v <= 0) return refuse(field, "must be positive; got " + exactText(v) + " " + unit + ".");
  return success();
}

Outcome<void> finite(const std::string& field, double v) {
  if (!std::isfinite(v)) return refuse(field, "must be a finite number.");
  return success();
}

Outcome<void> checkHob(const HobInput& h) {
  for (auto [field, v, unit] : {std::tuple{"hob.normalModule", h.normalModule, "mm"},
                                std::tuple{"hob.outerDiameter", h.outerDiameter, "mm"},
                                std::tuple{"hob.pitchDiameter", h.pitchDiameter, "mm"},
                                std::tuple{"hob.gashDepth", h.gashDepth, "mm"},
                                std::tuple{"hob.length", h.length, "mm"}})
    if (auto r = positive(field, v, unit); !r) return r;
  if (auto r = finite("hob.rakeOffset", h.rakeOffset); !r) return r;
  if (!(h.normalPressureAngle > 0 && h.normalPressureAngle < 45))
    return refuse("hob.normalPressureAngle", "must lie between 0 and 45 deg; got " + exactText(h.normalPressureAngle) + " deg.");
  if (h.pitchDiameter >= h.outerDiameter)
    return refuse("hob.pitchDiameter", "must be smaller than hob.outerDiameter (" + numberText(h.outerDiameter) +
                                           " mm); got " + exactText(h.pitchDiameter) + " mm.");
  const double ra = h.outerDiameter / 2, rp = h.pitchDiameter / 2;
  if (h.gashDepth >= ra)
    return refuse("hob.gashDepth", "must be less than the hob radius (" + numberText(ra) + " mm); got " +
                                       exactText(h.gashDepth) + " mm.");
  if (ra - h.gashDepth >= rp)
    return refuse("hob.gashDepth", "the gash must reach below the pitch diameter: the root radius " +
                                       numberText(ra - h.gashDepth) + " mm is not below the pitch radius " +
                                       numberText(rp) + " mm.");
  if (std::abs(h.rakeOffset) >= rp)
    return refuse("hob.rakeOffset", "|e| must be less than the pitch radius (" + numberText(rp) + " mm); got " +
                                        exactText(h.rakeOffset) + " mm.");
  if (std::abs(h.rakeOffset) >= ra - h.gashDepth)
    return refuse("hob.rakeOffset", "|e| must be less than the gash root radius (" +
                                        numberText(ra - h.gashDepth) + " mm); got " + exactText(h.rakeOffset) + " mm.");
  if (h.gash == GashKind::Helical) {
    if (!h.gashLead && !h.gashHelixAngle)
      return refuse("hob.gashLead", "a helical gash needs hob.gashLead or hob.gashHelixAngle.");
    if (h.gashLead)
      if (auto r = positive("hob.gashLead", *h.gashLead, "mm"); !r) return r;
    if (h.gashHelixAngle && !(*h.gashHelixAngle > 0 && *h.gashHelixAngle < 90))
      return refuse("hob.gashHelixAngle", "must lie between 0 and 90 deg; got " + exactText(*h.gashHelixAngle) + " deg.");
    if (h.gashLead && h.gashHelixAngle) {
      const double fromLead = helixAngleFromLead(*h.gashLead, rp) * kDegPerRad;
      if (std::abs(fromLead - *h.gashHelixAngle) > kHelixAngleAgreement)
        return refuse("hob.gashHelixAngle", numberText(*h.gashHelixAngle) + " deg disagrees with hob.gashLead " +
                                                numberText(*h.gashLead) + " mm, which gives " + numberText(fromLead) +
                                                " deg at the pitch diameter. Give one of the two.");
    }
  }
  return success();
}

ToothFace toothFace(const HobInput& h) {
  ToothFace f;
  f.gash = h.gash;
  f.pitchRadius = h.pitchDiameter / 2;
  f.rakeOffset = h.rakeOffset;
  if (h.gash == GashKind::Helical) {
    const double lead = h.gashLead ? *h.gashLead : leadFromHelixAngle(*h.gashHelixAngle * kRadPerDeg, f.pitchRadius);
    f.screwParameter = screwParameterFromLead(lead) * (h.hand == Hand::Left ? -1.0 : 1.0);
  }
  return f;
}

Outcome<FaceGrid> checkGrid(const GridInput& g, const SharpeningJob& job, double xCentre) {
  const int radial = g.radial.value_or(kDefaultGridRadial), axial = g.axial.value_or(kDefaultGridAxial);
  for (auto [field, n] : {std::pair{"grid.radial", radial}, std::pair{"grid.axial", axial}})
    if (n < 2 || n > kMaxGridLines)
      return refuse(field, "must be a whole number from 2 to " + std::to_string(kMaxGridLines) + "; got " +
                               std::to_string(n) + ".");
  const double half = job.input.hob.length / 2;
  const double rMin = g.rMin.value_or(job.rootRadius), rMax = g.rMax.value_or(job.outerRadius);
  const double xMin = g.xMin.value_or(xCentre - half), xMax = g.xMax.value_or(xCentre + half);
  for (auto [field, v] : {std::pair{"grid.rMin", rMin}, std::pair{"grid.rMax", rMax},
                          std::pair{"grid.xMin", xMin}, std::pair{"grid.xMax", xMax}})
    if (auto r = finite(field, v); !r) return r.error();
  if (rMin < job.rootRadius - kGridTolerance)
    return refuse("grid.rMin", numberText(rMin) + " mm lies below the gash root (radius " + numberText(job.rootRadius) + " mm).");
  if (rMax > job.outerRadius + kGridTolerance)
    return refuse("grid.rMax", numberText(rMax) + " mm lies beyond the hob's outer radius (" + numberText(job.outerRadius) + " mm).");
  if (rMin >= rMax) return refuse("grid.rMax", "must be greater than grid.rMin (" + numberText(rMin) + " mm).");
  if (xMin >= xMax) return refuse("grid.xMax", "must be greater than grid.xMin (" + numberText(xMin) + " mm).");
  // The face spans the hob length: centred on the hob (x = 0) or, as the default grid is, on the
  // contact line at phi_1 = 0 (x = xCentre); either is accepted.
  const double tol = kGridTolerance * (1 + job.input.hob.length);
  const double reach = half + std::abs(xCentre) + tol;
  if (xMax - xMin > 2 * half + tol || xMin < -reach || xMax > reach)
    return refuse(xMin < -reach ? "grid.xMin" : "grid.xMax",
                  "the grid (x = " + numberText(xMin) + " to " + numberText(xMax) + " mm) reaches past the hob's ends: the face is " +
                      numberText(2 * half) + " mm long, centred at x = 0 or on the contact line at x = " + numberText(xCentre) + " mm.");
  return FaceGrid::even(radial, axial, rMin, rMax, xMin, xMax);
}

// Axis polynomials of the case's degree with finite coefficients; `name` is their field ("axes",
// "passes[0].axes").
Outcome<void> checkAxes(const AxisPolynomials& axes, int degree, const std::string& name) {
  for (Axis a : kAxes) {
    const std::string field = name + "." + axisName(a);
    const Polynomial& p = axes[a];
    if (p.degree() != degree)
      return refuse(field, "needs " + std::to_string(degree + 1) + " coefficients a0..a" + std::to_string(degree) +
                               " (degree " + std::to_string(degree) + "); got " + std::to_string(p.a.size()) + ".");
    for (size_t k = 0; k < p.a.size(); ++k)
      if (!std::isfinite(p.a[k])) return refuse(field + "[" + std::to_string(k) + "]", "must be a finite number.");
  }
  return success();
}

// A measured grid of the grid's shape, every value finite and within ±kMaxDeviation; `name` is
// its field ("measured", "passes[1].measured"). The field of a refused value is its path (for the
// page to find the input); the message names its row and value from 1, with r and x.
Outcome<void> checkMeasured(const Eigen::MatrixXd& m, const FaceGrid& grid, const std::string& name) {
  if (m.rows() != grid.rows() || m.cols() != grid.cols())
    return Error{name, gridWords(name) + ": needs " + std::to_string(grid.rows()) + " rows (the radial grid lines) of " +
                           std::to_string(grid.cols()) + " values (the axial grid lines); got " + std::to_string(m.rows()) +
                           " x " + std::to_string(m.cols()) + ".",
                 ErrorCode::InvalidInput};
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j)
      if (!std::isfinite(m(i, j)) || std::abs(m(i, j)) > kMaxDeviation)
        return Error{name + "[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                     gridRowWords(name, i) + " (r = " + numberText(grid.r[i]) + " mm), value " + std::to_string(j + 1) +
                         " (x = " + numberText(grid.x[j]) + " mm): " +
                         (std::isfinite(m(i, j)) ? "must lie within ±" + numberText(kMaxDeviation) + " µm (10 mm); got " +
                                                       exactText(m(i, j)) + " µm."
                                                 : std::string("must be a finite number.")),
                     ErrorCode::InvalidInput};
  return success();
}

// The correction's options from the case's `correction` (or a pass's); `name` is its field
// ("correction", "passes[1].correction"), and every refusal names the member within it.
Outcome<CorrectionOptions> correctionOptions(const CorrectionInput& c, int degree, const std::string& name) {
  CorrectionOptions o;
  if (c.method) {
    if (*c.method == "linear") o.method = CorrectionMethod::Linear;
    else if (*c.method == "nonlinear") o.method = CorrectionMethod::Nonlinear;
    else return refuse(name + ".method", "must be \"nonlinear\" or \"linear\"; got \"" + *c.method + "\".");
  }
  if (c.probeNoise) {
    if (!std::isfinite(*c.probeNoise)) return refuse(name + ".probeNoise", "must be a finite number.");
    if (*c.probeNoise <= 0)
      return refuse(name + ".probeNoise", "the probe's standard deviation must be positive; got " +
                                                 exactText(*c.probeNoise) + " µm.");
    if (*c.probeNoise > kMaxDeviation)
      return refuse(name + ".probeNoise", "must be at most " + numberText(kMaxDeviation) + " µm (10 mm); got " +
                                                 exactText(*c.probeNoise) + " µm.");
    o.probeNoise = *c.probeNoise;
  }
  for (Axis a : kAxes) {
    const std::optional<double>& r = c.resolution[static_cast<int>(a)];
    if (!r) continue;
    const std::string field = name + ".resolution." + axisName(a);
    if (auto ok = positive(field, *r, isRotary(a) ? "deg" : "µm"); !ok) return ok.error();
    // A step from a nanometre (a nanodegree) to a millimetre (a degree): beyond any machine, and
    // far from where the scaled coordinates of the correction lose their digits.
    const double least = isRotary(a) ? kLeastRotaryResolution : kLeastLinearResolution;
    const double most = isRotary(a) ? kMostRotaryResolution : kMostLinearResolution;
    if (*r < least || *r > most)
      return refuse(field, "must lie between " + numberText(least) + " and " + numberText(most) + (isRotary(a) ? " deg" : " µm") +
                               "; got " + exactText(*r) + (isRotary(a) ? " deg." : " µm."));
    o.resolution.step[static_cast<int>(a)] = *r;
  }
  if (c.truncation) {
    if (!(*c.truncation > 0 && *c.truncation < 1))
      return refuse(name + ".truncation", "must lie between 0 and 1; got " + exactText(*c.truncation) + ".");
    o.truncation = *c.truncation;
  }
  if (c.amplification) {
    if (!(*c.amplification >= 1 && std::isfinite(*c.amplification)))
      return refuse(name + ".amplification", "must be a finite number of at least 1; got " +
                                                    exactText(*c.amplification) + ".");
    o.amplification = *c.amplification;
  }
  for (const Coefficient& k : c.locked)
    if (k.degree < 0 || k.degree > degree)
      return refuse(name + ".locked", k.name() + " is beyond the polynomial degree " + std::to_string(degree) + ".");
  o.locked = c.locked;
  o.lockedAxes = c.lockedAxes;
  if (c.wheel.value_or(false)) {  // the wheel-profile correction (docs/method.md)
    if (o.method != CorrectionMethod::Nonlinear)
      return refuse(name + ".wheel", "needs correction.method \"nonlinear\": the wheel is identified together with the "
                                     "machine error, which the linear step does not do.");
    o.wheel = true;
  }
  return o;
}

}  // namespace

Outcome<SharpeningJob> resolveJob(const CaseInput& in) {
  if (auto r = checkHob(in.hob); !r) return r.error();
  if (auto r = positive("wheel.outerDiameter", in.wheelOuterDiameter, "mm"); !r) return r.error();
  if (!(std::abs(in.tilt) < 90)) return refuse("setup.tilt", "must lie between -90 and 90 deg; got " + exactText(in.tilt) + " deg.");
  if (in.settingAngle && !(std::abs(*in.settingAngle) < 90))
    return refuse("setup.settingAngle", "must lie between -90 and 90 deg; got " + exactText(*in.settingAngle) + " deg.");
  if (in.centerDistance)
    if (auto r = positive("setup.centerDistance", *in.centerDistance, "mm"); !r) return r.error();
  if (auto r = finite("machine.K1", in.machine.K1); !r) return r.error();
  if (auto r = finite("machine.K2", in.machine.K2); !r) return r.error();
  if (in.degree < kMinDegree || in.degree > kMaxDegree)
    return refuse("degree", "must be a whole number from " + std::to_string(kMinDegree) + " to " +
                                std::to_string(kMaxDegree) + "; got " +
                                std::to_string(in.degree) + ".");

  SharpeningJob job;
  job.input = in;
  job.outerRadius = in.hob.outerDiameter / 2;
  job.rootRadius = job.outerRadius - in.hob.gashDepth;
  job.wheelRadius = in.wheelOuterDiameter / 2;
  const ToothFace face = toothFace(in.hob);

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

  // The wheel as dressed or measured (wheel_input.h), or the conjugate wheel.
  auto wheel = resolveWheelSurface(in, job.setup, job.rootRadius, job.outerRadius);
  if (!wheel) return wheel.error();
  job.setup.wheel = std::move(wheel).value();

  auto pitch = contactCoordinate(face, universal, job.setup.normalSign, 0.0);
  if (!pitch) return pitch.error();
  auto checkedGrid = checkGrid(in.grid, job, face.axialAt(*pitch));
  if (!checkedGrid) return checkedGrid.error();
  const FaceGrid& grid = *checkedGrid;
  job.grid = grid;

  job.nominalAxes = cncAxisPolynomials(universal, in.machine, in.degree);
  job.runAxes = job.nominalAxes;
  if (in.axes) {
    if (auto r = checkAxes(*in.axes, in.degree, "axes"); !r) return r.error();
    job.runAxes = *in.axes;
  }
  if (in.measured) {
    if (auto r = checkMeasured(*in.measured, grid, "measured"); !r) return r.error();
  }
  // Where the measuring machine's points may lie (docs/measured-points.md).
  const PointRegion region{job.rootRadius, job.outerRadius,
                           in.hob.length / 2 + std::abs(face.axialAt(*pitch)) + kGridTolerance * (1 + in.hob.length),
                           kGridTolerance, kMaxDeviation};
  if (in.measuredPoints) {
    if (in.measured) return refusePoints("measuredPoints", "give the measurement as a grid or as points, not both.");
    if (auto ok = checkPoints(*in.measuredPoints, region); !ok) return ok.error();
    if (auto m = gridFromPoints(*in.measuredPoints, grid, kGridTolerance)) {
      job.input.measured = std::move(m);
    } else {
      job.probes = probePointsOf(*in.measuredPoints);
      job.probeMeasured = deviationsOf(*in.measuredPoints);
    }
  }
  // The pass history is not computed with, but it must fit the job as `axes` and `measured` do.
  for (size_t i = 0; i < in.passes.size(); ++i) {
    const std::string pass = "passes[" + std::to_string(i) + "].";
    if (auto r = checkAxes(in.passes[i].axes, in.degree, pass + "axes"); !r) return r.error();
    if (in.passes[i].measuredPoints) {
      if (auto r = checkPoints(*in.passes[i].measuredPoints, region, pass + "measuredPoints"); !r) return r.error();
    } else if (auto r = checkMeasured(in.passes[i].measured, grid, pass + "measured"); !r) {
      return r.error();
    }
    if (in.passes[i].correction)
      if (auto r = correctionOptions(*in.passes[i].correction, in.degree, pass + "correction"); !r) return r.error();
  }
  auto options = correctionOptions(in.correction, in.degree, "correction");
  if (!options) return options.error();
  job.correction = *options;
  if (job.correction.wheel && !job.probes.empty())
    return refuse("correction.wheel", "is not available for measured points off the grid yet: give the points at the "
                                      "grid's positions (or the grid as `measured`) to correct the wheel too.");
  if (auto r = checkInspectionInput(in.inspection); !r) return r.error();  // docs/inspection.md
  for (std::size_t k = 0; k < in.inspection.gashTopographies.size(); ++k)
    if (auto r = checkMeasured(in.inspection.gashTopographies[k], grid, "inspection.gashTopographies[" + std::to_string(k) + "]"); !r)
      return r.error();
  return job;
}

}  // namespace hobsharp
