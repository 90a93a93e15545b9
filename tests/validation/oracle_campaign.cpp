// The swept-volume oracle (swept_volume_oracle.h) against the library's ground face on the
// validation campaign's random scenarios (scenario.h: the campaign's own hobs, machine errors and
// wheel shapes). One CSV line per grid point on stdout, a summary on stderr.
//
//   hobsharp_oracle_campaign [--seed S] [--first I] [--count N] [--dense | --dense-only]
//       [--samples M] [--margin F] [--stroke-margin F] [--body-against-normal] [--cut-at-rim]
//       [--all-pieces | --intersect-pieces]
//
// Each point's motion is swept over its own nominal motion +- F (--margin, 0.3) times the span of
// the grid's nominal motions, M samples (241); where the minimum lies at an end of that window it is
// swept again over the whole stroke (the grid's nominal motions +- --stroke-margin, 0.3, of their
// span; 2001 samples). --body-against-normal puts the wheel's body on the side the face normal points
// away from (the side that grinds the nominal face; see test_swept_volume_oracle.cpp); without it the
// body is on the side docs/conventions.md gives. --cut-at-rim ends the wheel at R = d_w / 2 (a
// cylindrical periphery); --all-pieces / --intersect-pieces keep the conjugate meridian's branches
// past a turn, as a union or an intersection of solids (swept_volume_oracle.h).
//
// Conditions per scenario: "nominal" (the run axes, the conjugate wheel) and "error" (the
// scenario's machine error added, and its wheel shape when it has one). With --dense, the grid 4
// times as dense (as docs/validation.md's "between the probe rows") as well as the probe grid.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "face_vectors.h"
#include "ground_face.h"
#include "scenario.h"
#include "sharpening_job.h"
#include "swept_volume_oracle.h"

using namespace hobsharp;
using namespace hobsharp::validation;

namespace {

FaceGrid denseGrid(const FaceGrid& g) {
  return FaceGrid::even(4 * (g.rows() - 1) + 1, 4 * (g.cols() - 1) + 1, g.r.front(), g.r.back(), g.x.front(),
                        g.x.back());
}

struct Stats {
  int points = 0, over = 0, overLarge = 0, fails = 0, retried = 0;
  double maxAbs = 0, sumSq = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seed = 20261125;
  int first = 0, count = 6, samples = 241;
  bool dense = false, bodyAlong = true, rim = false, allPieces = false, denseOnly = false, intersect = false;
  double margin = 0.3, strokeMargin = 0.3;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--first" && i + 1 < argc) first = std::atoi(argv[++i]);
    else if (a == "--count" && i + 1 < argc) count = std::atoi(argv[++i]);
    else if (a == "--samples" && i + 1 < argc) samples = std::atoi(argv[++i]);
    else if (a == "--margin" && i + 1 < argc) margin = std::atof(argv[++i]);
    else if (a == "--stroke-margin" && i + 1 < argc) strokeMargin = std::atof(argv[++i]);
    else if (a == "--dense") dense = true;
    else if (a == "--body-against-normal") bodyAlong = false;
    else if (a == "--cut-at-rim") rim = true;
    else if (a == "--all-pieces") allPieces = true;
    else if (a == "--intersect-pieces") allPieces = intersect = true;
    else if (a == "--dense-only") dense = denseOnly = true;
    else {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  std::printf(
      "seed,index,class,hand,gash,cond,grid,i,j,r,x,tLib,tOracle,diffUm,phiLib,phiOracle,rho,uWheel,uRoot,uTip,"
      "wheelRadius,turnRadius,curvature,localMinima,secondMinUm,atRangeEnd,atWindowEnd,wall,lowerEntry,"
      "crossAtLibUm,piece,pieces,oracleTurnU,retried\n");
  Stats total;
  const auto t0 = std::chrono::steady_clock::now();
  for (int index = first; index < first + count; ++index) {
    auto s = makeScenario(seed, index);
    if (!s) {
      std::fprintf(stderr, "scenario %d: %s\n", index, s.error().message.c_str());
      continue;
    }
    auto job = resolveJob(s->input);
    if (!job) continue;
    CaseInput machineCase = s->input;
    if (s->wheelError) machineCase.wheelProfileOffset = *s->wheelError;
    auto machine = resolveJob(machineCase);
    if (!machine) {
      std::fprintf(stderr, "scenario %d: machine job refused\n", index);
      continue;
    }
    for (int cond = 0; cond < 2; ++cond) {
      const SharpeningJob& j = cond == 0 ? *job : *machine;
      const AxisPolynomials axes = cond == 0 ? job->runAxes : plusError(job->runAxes, s->error);
      oracle::OracleOptions o;
      o.motionSamples = samples;
      o.bodyAlongNormal = bodyAlong;
      o.cutAtRim = rim;
      o.mainPieceOnly = !allPieces;
      o.intersectPieces = intersect;
      auto oracle = oracle::SweptVolumeOracle::make(oracle::oracleInput(j), o);
      oracle::OracleOptions wide = o;
      wide.motionSamples = 2001;
      auto strokeOracle = oracle::SweptVolumeOracle::make(oracle::oracleInput(j), wide);
      if (!oracle || !strokeOracle) {
        std::fprintf(stderr, "scenario %d: the oracle's wheel cannot be built\n", index);
        continue;
      }
      std::vector<FaceGrid> grids;
      if (!denseOnly) grids.push_back(j.grid);
      if (dense) grids.push_back(denseGrid(j.grid));
      for (std::size_t gi = 0; gi < grids.size(); ++gi) {
        const FaceGrid& grid = grids[gi];
        auto lib = simulateGroundFace(j.setup, axes, grid, Sensitivities::Skip);
        if (!lib) {
          std::fprintf(stderr, "scenario %d cond %d: library refused: %s\n", index, cond, lib.error().message.c_str());
          continue;
        }
        // The oracle's own nominal motions over the grid: their span sets each point's window.
        double lo = 1e300, hi = -1e300;
        for (double r : grid.r)
          for (double x : grid.x) {
            auto m = oracle->nominalMotion(r, x);
            if (m) lo = std::min(lo, *m), hi = std::max(hi, *m);
          }
        const double span = std::max(hi - lo, j.setup.face.helical() ? 0.02 : 2.0);
        for (int i = 0; i < grid.rows(); ++i)
          for (int k = 0; k < grid.cols(); ++k) {
            const EnvelopePoint& e = lib->envelope[static_cast<std::size_t>(i * grid.cols() + k)];
            auto m = oracle->nominalMotion(grid.r[i], grid.x[k]);
            if (!m) {
              ++total.fails;
              continue;
            }
            const double d = margin * span;
            oracle::SweptPoint p = oracle->sweep(grid.r[i], grid.x[k], axes, *m - d, *m + d);
            // The minimum at an end of the point's window: the contact has moved further along the
            // stroke (a straight gash's X error is invisible on the face and may be millimetres).
            // Sweep the whole stroke then: the grid's nominal motions and 30 % of their span each way.
            bool retried = false;
            if (p.atRangeEnd) {
              retried = true;
              ++total.retried;
              p = strokeOracle->sweep(grid.r[i], grid.x[k], axes, lo - strokeMargin * span, hi + strokeMargin * span);
            }
            if (!p.found) {
              ++total.fails;
              std::fprintf(stderr, "scenario %d: oracle found no reach at r %g x %g\n", index, grid.r[i], grid.x[k]);
              continue;
            }
            const auto line = oracle->line(grid.r[i], grid.x[k]);
            auto atLib = oracle->reach(line, axes, e.phi);
            const double diff = (e.t - p.t) * 1000;
            ++total.points;
            total.maxAbs = std::max(total.maxAbs, std::abs(diff));
            total.sumSq += diff * diff;
            if (std::abs(diff) > 0.01) ++total.over;
            if (std::abs(diff) > 1) ++total.overLarge;
            std::printf(
                "%llu,%d,%s,%s,%s,%s,%s,%d,%d,%.9g,%.9g,%.12g,%.12g,%.6g,%.12g,%.12g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.6g,%d,"
                "%.6g,%d,%d,%d,%d,%.6g,%d,%d,%.9g,%d\n",
                static_cast<unsigned long long>(seed), index, className(s->spec.kind),
                j.setup.face.hand() == Hand::Left ? "left" : "right", j.setup.face.helical() ? "helical" : "straight",
                cond == 0 ? "nominal" : "error", grid.size() == j.grid.size() ? "probe" : "dense", i, k, grid.r[i], grid.x[k], e.t, p.t, diff,
                e.phi, p.phi, p.rho, p.u, oracle->uRoot(), oracle->uTip(), j.wheelRadius,
                j.setup.wheelEdge ? j.setup.wheelEdge->turnRadius : 0.0, p.curvature, p.localMinima,
                p.localMinima > 1 ? p.secondMinimum * 1000 : 0.0, p.atRangeEnd, p.atWindowEnd, p.wall,
                p.lowerEntry, atLib ? (*atLib - e.t) * 1000 : 1e9, p.piece, oracle->pieces(),
                oracle->turnU() ? *oracle->turnU() : 0.0, retried);
          }
      }
    }
    std::fflush(stdout);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr, "scenario %d done (%.1f s): %d points, max %.3g um, over 0.01 um %d\n", index, sec,
                 total.points, total.maxAbs, total.over);
  }
  std::fprintf(stderr, "swept over the whole stroke %d, ", total.retried);
  std::fprintf(stderr, "points %d, oracle failures %d, max |diff| %.4g um, rms %.4g um, over 0.01 um %d, over 1 um %d\n",
               total.points, total.fails, total.maxAbs, total.points ? std::sqrt(total.sumSq / total.points) : 0.0,
               total.over, total.overLarge);
  return 0;
}
