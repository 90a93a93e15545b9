// Errors as values: Outcome<T> holds a value or an Error, Outcome<void> only an optional Error.
#include <gtest/gtest.h>

#include "outcome.h"

namespace hobsharp {
namespace {

Outcome<void> atLeastOne(double v) {
  if (v < 1) return refuse("grid.radial", "must be at least 1.");
  return success();
}

Outcome<double> half(double v) {
  if (auto r = atLeastOne(v); !r) return r.error();
  return v / 2;
}

TEST(Outcome, VoidHoldsOnlyTheError) {
  const Outcome<void> fine = atLeastOne(3);
  EXPECT_TRUE(fine.ok());
  EXPECT_TRUE(static_cast<bool>(fine));
  const Outcome<void> refused = atLeastOne(0);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().field, "grid.radial");
  EXPECT_EQ(refused.error().message, "grid.radial: must be at least 1.");
  EXPECT_TRUE(success().ok());
  EXPECT_TRUE(Outcome<void>().ok());
}

TEST(Outcome, AnErrorPassesUpUnchanged) {
  auto ok = half(3);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, 1.5);
  auto refused = half(0.5);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().field, "grid.radial");
}

}  // namespace
}  // namespace hobsharp
