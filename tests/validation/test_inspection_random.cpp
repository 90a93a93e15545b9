// The radial alignment and the rake error on hobs nobody chose (docs/inspection.md): the campaign's
// random hobs (docs/validation.md: modules 1 to 12 mm, straight and helical gashes of either hand,
// rake offsets, grids 5 to 9 by 7 to 17), each with a random rake error and a random turn about the
// hob axis built by hand (tests/hand_built_face.h), read by checkFace and by the standard's
// indicator in plane geometry. The share within 10 % of the standard's reading is asserted.
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "../hand_built_face.h"
#include "face_checks.h"
#include "scenario.h"
#include "sharpening_job.h"

namespace hobsharp::validation {
namespace {

constexpr std::uint64_t kSeed = 20261126;
constexpr int kHobs = 60;

TEST(InspectionOnRandomHobs, RadialAlignmentAndRakeErrorReadAsTheStandardReadsThem) {
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> unit(-1, 1);
  int alignmentWithin = 0, rakeWithin = 0, turnsQuiet = 0, hobs = 0;
  double worstAlignment = 0, worstRake = 0;
  for (int i = 0; i < kHobs; ++i) {
    auto s = makeScenario(kSeed, i);
    ASSERT_TRUE(s.ok()) << i << ": " << s.error().message;
    auto job = resolveJob(s->input);
    ASSERT_TRUE(job.ok()) << s->description << ": " << job.error().message;
    ++hobs;
    // A rake error of 0.02 to 0.12 mm of either sign; a turn up to 1 mrad.
    const double u = (0.02 + 0.1 * std::abs(unit(rng))) * (unit(rng) < 0 ? -1 : 1);
    const double theta = 1e-3 * unit(rng);
    const FaceLines lines = FaceLines::of(job->setup, job->grid);
    const bool helical = job->setup.face.helical();
    const test::HandBuiltInspection both = test::handBuiltInspection(job->setup, job->grid, u, theta);
    const FaceChecks got = checkFace(both.normal, lines, helical);
    const double alignmentError = std::abs(got.radialAlignment - both.reading) / std::abs(both.reading);
    const double rakeError = std::abs(got.rakeOffset + u) / std::abs(u);
    alignmentWithin += alignmentError <= 0.1;
    rakeWithin += rakeError <= 0.1;
    worstAlignment = std::max(worstAlignment, alignmentError);
    worstRake = std::max(worstRake, rakeError);
    // The turn alone: the standard reads nothing; the check within 2 % of what the rake error reads.
    const test::HandBuiltInspection turn = test::handBuiltInspection(job->setup, job->grid, 0, theta);
    const FaceChecks turned = checkFace(turn.normal, lines, helical);
    turnsQuiet += std::abs(turned.radialAlignment) <= 0.02 * std::abs(both.reading) + 0.01;
    EXPECT_LE(alignmentError, 0.1) << s->description << ", u = " << u << " mm, theta = " << theta << ": read "
                                   << got.radialAlignment << " µm, the standard " << both.reading << " µm";
  }
  std::printf("radial alignment within 10 %% of the standard's reading: %d of %d random hobs (worst %.2g %%); "
              "rake offset within 10 %%: %d (worst %.2g %%); a turn read as nothing: %d\n",
              alignmentWithin, hobs, 100 * worstAlignment, rakeWithin, 100 * worstRake, turnsQuiet);
  EXPECT_EQ(alignmentWithin, hobs);
  EXPECT_EQ(rakeWithin, hobs);
  EXPECT_EQ(turnsQuiet, hobs);
}

}  // namespace
}  // namespace hobsharp::validation
