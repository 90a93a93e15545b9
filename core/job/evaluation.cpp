#include "evaluation.h"

#include <algorithm>
#include <sstream>

#include "wheel_profile_turn.h"

namespace hobsharp {

std::string unexplainedPointsText(const Evaluation& e) {
  // Only measuredPoints off the grid are inspected on a model's face (inspectedFace).
  if (!e.correction || !e.correction->atProbes() || e.job.measured.grid) return "";
  const Correction& c = *e.correction;
  const double probeNoise = e.job.correction.probeNoise;
  if (!(c.unexplainedRms > 2 * probeNoise)) return "";
  std::ostringstream t;
  t.precision(2);
  t << "the face is known only at the measured points, and the face the identified machine error grinds on the "
       "grid, which would be graded in their place, leaves "
    << c.unexplainedRms << " \u00b5m rms of the points unexplained (more than twice the probe noise, sigma "
    << probeNoise << " \u00b5m): its readings would be a model's, not the indicator's. Measure the face on the grid "
       "(Polynomials and measuring grid) to grade it";
  return t.str();
}

InspectedFace inspectedFace(const Evaluation& e) {
  const MeasuredFace& measured = e.job.measured;
  // measuredPoints at the grid's positions are the job's measured grid (measured_face.cpp).
  if (measured.grid) return {*measured.grid, measured.source};
  // measuredPoints off the grid: the measurement as the identified error explains it, on the grid
  // (docs/measured-points.md).
  if (e.correction && e.correction->atProbes()) return {e.correction->explainedOnGrid.normal, measured.source};
  return {e.topography.normal, FaceSource::Simulated};
}

void inspectEvaluation(Evaluation& e) {
  const SharpeningJob& job = e.job;
  const InspectionPlan& plan = job.inspection;
  const ToleranceTable& table = plan.table();
  const bool helical = job.setup.face.helical();
  const double module = plan.normalModule;
  const bool points = e.correction && e.correction->atProbes();
  const Eigen::MatrixXd& face = inspectedFace(e).normal;
  const FaceLines lines = FaceLines::of(job.setup, job.grid);
  const MeasurementUncertainty& u = plan.uncertainty;
  // One topography per gash: their deviations at the pitch radius, and the worst gash's face checks.
  FaceChecks faceChecks = checkFace(face, lines, helical);
  // At probe points off the grid the face inspected is the one the identified error explains: it
  // stands for the measurement only where that explains the points to within twice the probe noise
  // (the verdict's own test, Correction::leavesWithinNoise). Beyond, its readings are a model's,
  // not the indicator's, and the face's checks are not graded (docs/measured-points.md).
  const std::string faceNotGraded = unexplainedPointsText(e);
  std::vector<double> deviations = plan.gashDeviations;
  if (!plan.gashTopographies.empty()) {
    e.gashFaces = inspectGashFaces(plan.gashTopographies, lines, helical, job.setup.face.pitchRadius);
    deviations = e.gashFaces->deviations;
    faceChecks = e.gashFaces->worst;
  }
  std::optional<GashSpacing> spacing;
  if (!deviations.empty()) {
    spacing = gashSpacing(deviations);
    const double perRadian = deviationPerIndexAngle(job.setup, job.setup.face.pitchRadius, 0.0);
    e.indexCorrection = indexCorrection(deviations, perRadian, job.correction.resolution.inAxisUnit(Axis::A));
  }
  e.inspection = inspect(faceChecks, spacing, table, module, u, faceNotGraded);
  if (!e.correction && !e.indexCorrection) return;
  // After: the corrected face's checks (on the grid, for points off it), or (only the gashes
  // re-indexed) the faces as they are. With one topography per gash, each gash less what the pass
  // removes on the grid (the same axes grind every gash): the worst of them, as before.
  FaceChecks after = faceChecks;
  if (e.gashFaces && e.correction) {
    const Eigen::MatrixXd removed = points ? Eigen::MatrixXd(e.correction->explainedOnGrid.normal - e.correction->afterOnGrid.normal)
                                           : Eigen::MatrixXd(e.correction->before.normal - e.correction->after.normal);
    std::vector<Eigen::MatrixXd> gashesAfter;
    for (const Eigen::MatrixXd& g : plan.gashTopographies) gashesAfter.push_back(g - removed);
    after = inspectGashFaces(gashesAfter, lines, helical, job.setup.face.pitchRadius).worst;
  } else if (e.correction) {
    after = checkFace(points ? e.correction->afterOnGrid.normal : e.correction->after.normal, lines, helical);
  }
  std::optional<GashSpacing> spacingAfter;
  if (e.indexCorrection) spacingAfter = gashSpacing(e.indexCorrection->after);
  e.inspectionAfter = inspect(after, spacingAfter, table, module, u, faceNotGraded);
}

namespace {

Outcome<Evaluation> evaluateJob(const SharpeningJob& job) {
  Evaluation e;
  e.job = job;
  const SharpeningSetup& s = job.setup;
  auto face = simulateGroundFace(s, job.runAxes, job.grid);
  // The machine ground a face with these axes and its error, but the axes alone grind none the wheel
  // envelops (a pass after a large machine error): with a measurement, the nominal axes' face stands
  // in (the simulated topography is theirs) and the correction is linearised there (correction.h).
  const MeasuredFace& measured = job.measured;
  const AxisPolynomials* linearisedAt = nullptr;
  if (!face && measured.given() && job.correction.method == CorrectionMethod::Nonlinear) {
    face = simulateGroundFace(s, job.nominalAxes, job.grid);
    linearisedAt = &job.nominalAxes;
  }
  if (!face) return face.error();
  e.groundFace = std::move(face).value();
  e.topography = topographyOf(e.groundFace);
  e.sensitivities = sensitivityMatrix(e.groundFace, allCoefficients(job.runAxes.degree()));
  if (s.wheel.hasOffset()) {
    e.dressedProfile = dressedProfile(s, job.wheelProfile);
    e.offsetSensitivities = wheelOffsetSensitivity(e.groundFace, s.wheel);
  }
  if (measured.grid && job.correction.wheel) {  // docs/method.md §Wheel-profile correction
    const double rLow = std::max(job.grid.r.front(), job.rootRadius), rHigh = std::min(job.grid.r.back(), job.outerRadius);
    auto c = correctAxesAndWheel(s, job.nominalAxes, job.runAxes, e.groundFace, *measured.grid, job.correction,
                                 job.wheelProfile, rLow, rHigh, linearisedAt);
    if (!c) return c.error();
    e.correction = std::move(c->correction);
    e.wheelCorrection = std::move(c->wheel);
  } else if (measured.grid) {
    auto c = correctMeasuredFace(s, job.nominalAxes, job.runAxes, e.groundFace, *measured.grid, job.correction,
                                 nullptr, nullptr, linearisedAt, &job.history);
    if (!c) return c.error();
    e.correction = std::move(c).value();
  }
  if (measured.atPoints()) {  // docs/measured-points.md
    auto c = correctMeasuredPoints(s, job.nominalAxes, job.runAxes, job.grid, measured.probes, measured.deviations,
                                   job.correction, &job.history);
    if (!c) return c.error();
    e.correction = std::move(c).value();
    // The program runs over the grid's motion range, which the points may not span: the change
    // over it where it is larger than over the points by more than half a machine step (less is
    // no move the machine makes; and points beyond the grid keep their own figure).
    Correction& p = *e.correction;
    const auto overGrid = axisChangeOver(p.axes, job.runAxes, motionRange(e.groundFace));
    for (Axis a : kAxes) {
      const int i = static_cast<int>(a);
      const double halfStep = 0.5 * job.correction.resolution.inAxisUnit(a) * displayFactor(a);
      p.axisChangeOverFace[i] = std::abs(overGrid[i]) > std::abs(p.axisChangeSize[i]) + halfStep ? overGrid[i] : p.axisChangeSize[i];
    }
  }
  // A change proposed on a face that reaches past the edge of the wheel's envelope: the verdict
  // names the band (wheel_profile_turn.h).
  if (e.correction && !e.correction->keepsRun() && s.wheelEdge) {
    double top = job.grid.r.empty() ? 0.0 : job.grid.r.back();
    if (measured.atPoints()) {
      top = 0;
      for (const ProbePoint& q : measured.probes) top = std::max(top, q.r);
    }
    if (top > s.wheelEdge->turnRadius) e.correction->verdict += " " + wheelEdgeVerdictText(*s.wheelEdge);
  }
  inspectEvaluation(e);
  gearEvaluation(e);
  return e;
}

}  // namespace

Outcome<Evaluation> evaluate(const SharpeningJob& job) {
  auto e = evaluateJob(job);
  // A wheel too wild to grind with is the case's measured profile when it gives one (envelope.h).
  if (!e && e.error().field == kWildWheelField && job.wheelMeasured) {
    Error w = e.error();
    w.field = "wheel.measuredProfile";
    return w;
  }
  return e;
}

}  // namespace hobsharp
