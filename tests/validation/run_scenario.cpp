#include "run_scenario.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include "cubic_spline.h"
#include "evaluation.h"
#include "face_vectors.h"
#include "ground_face.h"
#include "sharpening_job.h"
#include "structural_null_space.h"
#include "topography.h"

namespace hobsharp::validation {
namespace {

// The probe noise declared for a noise-free measurement, µm: a probe far better than any real one,
// so that the correction uses every direction the face shows.
constexpr double kNoiseFreeDeclared = 0.01;

// An offset (µm at radii R) as the wheel's spline (not-a-knot, as wheel_input.cpp reads it), evaluated at R.
double offsetAt(const WheelPointsInput& o, double R) {
  return CubicSpline::notAKnot(o.R, o.values).value(R);
}

// The sum of two offsets at the radii of `at`.
WheelPointsInput sumAt(const WheelPointsInput& at, const std::optional<WheelPointsInput>& a,
                       const std::optional<WheelPointsInput>& b) {
  WheelPointsInput s;
  s.R = at.R;
  for (double R : at.R) s.values.push_back((a ? offsetAt(*a, R) : 0.0) + (b ? offsetAt(*b, R) : 0.0));
  return s;
}

FaceGrid denseGrid(const FaceGrid& g) {
  return FaceGrid::even(kDenseFactor * (g.rows() - 1) + 1, kDenseFactor * (g.cols() - 1) + 1, g.r.front(), g.r.back(),
                        g.x.front(), g.x.back());
}

// The machine: the engineer's case with the wheel it really has (the recorded offset plus the
// wheel's own shape).
Outcome<SharpeningJob> machineJob(const Scenario& s, const std::optional<WheelPointsInput>& recorded) {
  CaseInput c = s.input;
  if (s.wheelError) c.wheelProfileOffset = sumAt(*s.wheelError, recorded, s.wheelError);
  else if (recorded) c.wheelProfileOffset = recorded;
  return resolveJob(c);
}

// The part of `error` in the structural null space of `machine`'s face (structural_null_space.h):
// the complement of the identifiable space in machine steps, over the motion range of `face` (the
// face measured; the identification takes the run face's). On a straight gash the split is per
// coefficient (X, Y and B), whatever the metric; on a helical one the part grinds nothing, whatever
// the metric, so the range taken moves no figure.
AxisPolynomials structuralPart(const SharpeningJob& machine, const AxisPolynomials& error, const GroundFace& face) {
  const MotionRange range = motionRange(face);
  const double reach = std::max({std::abs(range.min), std::abs(range.max), 1e-12});
  const IdentifiableSpace space = identifiableSpace(machine.setup.face, error.degree(), machine.correction, reach);
  const int q = static_cast<int>(space.coefficients.size());
  Eigen::VectorXd z(q);
  for (int j = 0; j < q; ++j)
    z(j) = error[space.coefficients[j].axis].coefficient(space.coefficients[j].degree) / space.step(j);
  const Eigen::VectorXd n = z - space.basis * (space.basis.transpose() * z);
  AxisPolynomials part = error;
  for (Axis a : kAxes)
    for (double& v : part[a].a) v = 0;
  for (int j = 0; j < q; ++j) part[space.coefficients[j].axis].a[space.coefficients[j].degree] = n(j) * space.step(j);
  return part;
}

// The face `machine` grinds when `commanded` is run and it adds `error`, on `grid`.
Outcome<Topography> faceOf(const SharpeningJob& machine, const AxisPolynomials& commanded,
                           const AxisPolynomials& error, const FaceGrid& grid) {
  auto f = simulateGroundFace(machine.setup, plusError(commanded, error), grid, Sensitivities::Skip);
  if (!f) return f.error();
  return topographyOf(*f);
}

Outcome<double> rmsOf(const SharpeningJob& machine, const AxisPolynomials& commanded, const AxisPolynomials& error,
                      const FaceGrid& grid) {
  auto f = faceOf(machine, commanded, error, grid);
  if (!f) return f.error();
  return f->rms;
}

double rmsOfDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return std::sqrt((a - b).squaredNorm() / static_cast<double>(a.size()));
}

}  // namespace

ScenarioOutcome runScenario(const Scenario& s, std::vector<CaseInput>* cases, bool signReversed) {
  const auto start = std::chrono::steady_clock::now();
  ScenarioOutcome out;
  out.scenario = s;
  std::mt19937_64 noise(s.seed * 0x94D049BB133111EBull + static_cast<std::uint64_t>(s.index) + 7);
  std::normal_distribution<double> gauss(0, 1);

  std::optional<WheelPointsInput> recorded;  // the wheel offset the case records (earlier dressings)
  auto first = resolveJob(s.input);
  if (!first) {
    out.judged = false;
    out.message = first.error().message;
    return out;
  }
  AxisPolynomials run = first->nominalAxes;
  std::vector<PassInput> history;  // the passes so far, oldest first
  const FaceGrid dense = denseGrid(first->grid);
  {
    auto machine = machineJob(s, recorded);
    auto r = machine ? rmsOf(*machine, run, s.error, dense) : Outcome<double>(machine.error());
    if (!r) {
      out.judged = false;
      out.message = "the judging grid: " + r.error().message;
      return out;
    }
    out.initialDenseRms = *r;
  }
  // A pass the calculator refuses ends the scenario ...
  const auto refused = [&out](PassOutcome& p, std::string why) {
    p.refused = true;
    p.message = std::move(why);
    out.passes.push_back(p);
  };
  // ... or whose proposal the machine does not grind in full.
  const auto unground = [&out](PassOutcome& p, std::string why) {
    p.unground = true;
    p.message = std::move(why);
    out.passes.push_back(p);
  };
  for (int pass = 0; pass < s.spec.passes; ++pass) {
    PassOutcome p;
    auto machine = machineJob(s, recorded);
    if (!machine) {
      unground(p, "the machine's wheel, dressed as proposed: " + machine.error().message);
      break;
    }
    auto ground = simulateGroundFace(machine->setup, plusError(run, s.error), machine->grid, Sensitivities::Skip);
    if (!ground) {
      out.judged = false;
      out.message = "the machine's face: " + ground.error().message;
      break;
    }
    if (pass == 0 && !s.spec.wheel) {
      // What the error's part no face shows to first order leaves alone (run_scenario.h).
      auto alone = rmsOf(*machine, run, structuralPart(*machine, s.error, *ground), dense);
      if (alone) p.nullPartRms = *alone;
    }
    Eigen::MatrixXd measured = topographyOf(*ground).normal;
    for (int i = 0; i < measured.size(); ++i) measured.data()[i] += s.spec.sigma * gauss(noise);
    if (signReversed) measured = -measured;
    p.measuredRms = std::sqrt(measured.squaredNorm() / static_cast<double>(measured.size()));

    CaseInput c = s.input;
    c.axes = run;
    c.measured = measured;
    c.passes = history;  // the earlier passes, as the page's "Use as next run" keeps them
    c.correction.probeNoise = s.spec.sigma > 0 ? s.spec.sigma : kNoiseFreeDeclared;
    if (s.spec.wheel) c.correction.wheel = true;
    if (recorded) c.wheelProfileOffset = recorded;
    if (cases) cases->push_back(c);
    auto job = resolveJob(c);
    auto e = job ? evaluate(*job) : Outcome<Evaluation>(job.error());
    if (!e || !e->correction) {
      refused(p, e ? "no correction was computed" : e.error().message);
      break;
    }
    const Correction& k = *e->correction;
    p.status = statusName(k.summary.status);
    p.verdict = k.verdict;
    p.predictedRms = k.predictedRms;
    p.predictedRmsHigh = k.predictedRmsHigh;
    p.predictedUnseenPart = k.predictedUnseenPart;
    p.foldMargin = std::min(k.predictedFoldMargin, 1e30);
    p.stopAdvised = k.stop;
    p.linearisedAtNominal = k.linearisedAtNominal;
    p.passesJoined = k.passesJoined;
    if (k.historySign) p.signAlong = k.historySign->along, p.signCosine = k.historySign->cosine;
    p.signReversed = k.signReversed();
    p.unsolvableTrials = k.summary.unsolvableFaces;
    p.rank = k.rank;
    p.withinNoise = k.withinNoise;
    p.amplifying = k.amplifyingDropped;
    p.iterations = k.summary.iterations;
    std::optional<WheelPointsInput> next = recorded;
    if (e->wheelCorrection) {
      WheelPointsInput dressing{e->wheelCorrection->knots.R, e->wheelCorrection->offset};
      next = sumAt(*s.wheelError, recorded, dressing);
    }
    auto after = machineJob(s, next);
    if (!after) {
      unground(p, "the dressed wheel: " + after.error().message);
      break;
    }
    auto probe = rmsOf(*after, k.axes, s.error, after->grid);
    auto left = faceOf(*after, k.axes, s.error, dense);
    auto rounded = rmsOf(*after, k.roundedAxes, s.error, dense);
    if (!probe || !left || !rounded) {
      unground(p, std::string("the proposed axes grind a face that cannot be simulated ") +
                     (!probe ? "on the probe grid" : !left ? "between the probe points" : "with the rounded axes") + ": " +
                     (!probe ? probe.error() : !left ? left.error() : rounded.error()).message);
      break;
    }
    if (!e->wheelCorrection) {
      // The twin machine (run_scenario.h): the true wheel with the identified error.
      auto twin = faceOf(*after, run, k.identifiedError, after->grid);
      auto twinLeft = faceOf(*after, k.axes, k.identifiedError, dense);
      if (twin && twinLeft) {
        p.twinMisfit = rmsOfDifference(twin->normal, measured);
        p.twinGap = rmsOfDifference(twinLeft->normal, left->normal);
      }
    }
    p.probeNoise = *c.correction.probeNoise;
    p.probeRms = *probe;
    p.denseRms = left->rms;
    p.denseRmsRounded = *rounded;
    out.passes.push_back(p);
    PassInput done;
    done.axes = run;
    done.measured = measured;
    done.correction = CorrectionInput{};
    done.correction->probeNoise = c.correction.probeNoise;
    if (s.spec.wheel) done.correction->wheel = true;
    history.push_back(done);
    run = k.axes;
    recorded = next;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace hobsharp::validation
