// The validation campaign's default run (seed 20261125, 204 scenarios, docs/validation.md) as a
// test: each target of issue 20 that the campaign meets is asserted at the share the issue asks
// for; each it does not yet meet is asserted at the share measured at this commit, so that a
// change that makes it worse fails. Natively the run takes about a second.
#include <cstdio>

#include <gtest/gtest.h>

#include "campaign.h"

namespace hobsharp::validation {
namespace {

constexpr std::uint64_t kSeed = 20261125;
constexpr int kScenarios = 204;

const Campaign& campaign() {
  static const Campaign c = [] {
    std::vector<ScenarioOutcome> outcomes;
    for (int i = 0; i < kScenarios; ++i) {
      auto s = makeScenario(kSeed, i);
      EXPECT_TRUE(s.ok()) << "scenario " << i << ": " << (s.ok() ? "" : s.error().message);
      if (s) outcomes.push_back(runScenario(*s));
    }
    return summarise(kSeed, std::move(outcomes), 0);
  }();
  return c;
}

const ClassSummary& classOf(ScenarioClass k) { return campaign().classes[static_cast<int>(k)]; }

// One test, so that the campaign runs once per CTest run (each test is a process of its own).
TEST(Validation, CampaignTargets) {
  int judged = 0;
  for (const ScenarioOutcome& o : campaign().outcomes) judged += o.judged ? 1 : 0;
  EXPECT_EQ(static_cast<int>(campaign().outcomes.size()), kScenarios);
  EXPECT_GE(judged, kScenarios - 2);  // a random error may leave a judging grid the wheel cannot grind

  // Met: the shares.
  for (const Target& t : classOf(ScenarioClass::Small).targets) EXPECT_GE(t.share(), t.required) << t.what;
  for (const Target& t : classOf(ScenarioClass::Noisy).targets) EXPECT_GE(t.share(), t.required) << t.what;
  EXPECT_GE(campaign().bounds[1].share(), 0.80) << campaign().bounds[1].what;

  // Not yet met (docs/validation.md): held at the share measured with g++ -O2, 25/33, 27/33, 16/34,
  // 31/34, 30/34, 160/197 and 222/265 of the 95, 90, 90, 95, 90, 90 and 90 %, less one
  // scenario (the sanitizer build's clang rounds differently, and a scenario at a threshold may
  // fall either way). The rounded axes' 27/33 is with the coefficients as the program carries them.
  EXPECT_GE(classOf(ScenarioClass::Medium).targets[0].share(), 24.0 / 33 - 1e-9);
  EXPECT_GE(classOf(ScenarioClass::Medium).targets[1].share(), 26.0 / 33 - 1e-9);
  EXPECT_GE(classOf(ScenarioClass::Large).targets[0].share(), 15.0 / 34 - 1e-9);
  EXPECT_GE(classOf(ScenarioClass::NoiseOnly).targets[0].share(), 30.0 / 34 - 1e-9);
  EXPECT_GE(classOf(ScenarioClass::Wheel).targets[0].share(), 29.0 / 34 - 1e-9);
  EXPECT_GE(campaign().bounds[0].share(), 159.0 / 197 - 1e-9);
  EXPECT_GE(campaign().bounds[2].share(), 221.0 / 265 - 1e-9);
  std::printf("%s", tableText(campaign()).c_str());
}

}  // namespace
}  // namespace hobsharp::validation
