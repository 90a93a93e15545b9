// A campaign scenario's pass written as a case file (case_file.h; `./hobsharp.sh validate --index I
// --cases DIR`) evaluates, through the case reader, to the very correction the campaign computed
// for it: the same proposed axes, bound and verdict, to the last bit. One scenario of each class of
// the default seed, every pass (a second pass's file holds the first in `passes`; a wheel pass's,
// the dressing in `wheel.profileOffset`).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "case_file.h"
#include "evaluation.h"
#include "result_model.h"
#include "run_scenario.h"
#include "sharpening_job.h"

namespace hobsharp::validation {
namespace {

TEST(ScenarioCaseFile, APassEvaluatesFromItsFileAsInTheCampaign) {
  int files = 0, later = 0;
  for (int index = 0; index < kScenarioClasses; ++index) {
    auto s = makeScenario(20261125, index);
    ASSERT_TRUE(s) << s.error().message;
    std::vector<CaseInput> cases;
    const ScenarioOutcome outcome = runScenario(*s, &cases);
    ASSERT_EQ(cases.size(), outcome.passes.size()) << "scenario " << index;
    for (size_t k = 0; k < cases.size(); ++k) {
      auto direct = resolveJob(cases[k]);
      ASSERT_TRUE(direct) << direct.error().message;
      auto inMemory = evaluate(*direct);
      auto fromFile = evaluateCase(caseFile(cases[k]).dump(1));
      ASSERT_TRUE(inMemory && fromFile) << "scenario " << index << " pass " << k + 1 << ": "
                                        << (fromFile ? inMemory.error().message : fromFile.error().message);
      ASSERT_TRUE(inMemory->correction && fromFile->correction);
      const Correction &a = *inMemory->correction, &b = *fromFile->correction;
      EXPECT_EQ(b.predictedRmsHigh, a.predictedRmsHigh) << "scenario " << index << " pass " << k + 1;
      EXPECT_EQ(b.predictedRmsHigh, outcome.passes[k].predictedRmsHigh);
      EXPECT_EQ(b.verdict, a.verdict);
      for (Axis ax : kAxes)
        for (int d = 0; d <= cases[k].degree; ++d)
          EXPECT_EQ(b.axes[ax].coefficient(d), a.axes[ax].coefficient(d)) << axisName(ax) << " a" << d;
      ++files;
      later += k > 0 ? 1 : 0;
    }
  }
  EXPECT_GE(files, 8);  // two passes of the 150 µm and the wheel classes
  EXPECT_GE(later, 2);
}

}  // namespace
}  // namespace hobsharp::validation
