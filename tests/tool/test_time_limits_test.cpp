// A test's time limit in a mutant's tree: five times its own time on the unmutated tree, never
// below the floor; tests the baseline did not time get the limit for unknown tests.
#include "tool/test_time_limits.h"

#include <gtest/gtest.h>

namespace cc::tool {
namespace {

TEST(TestTimeLimits, FiveTimesItsOwnTimeAboveTheFloor) {
  TestTimeLimits limits;
  limits.floor_seconds = 10;
  limits.own_seconds = {{"corpus.ray_aabb", 0.4}, {"Generate.Slow", 68.5}, {"Quick", 2.5}};
  limits.unknown_seconds = 342.5;
  EXPECT_EQ(limits.limit("corpus.ray_aabb"), 10);  // 2 s: the floor
  EXPECT_EQ(limits.limit("Quick"), 12.5);          // its own, not the slowest test's
  EXPECT_EQ(limits.limit("Generate.Slow"), 342.5);
  EXPECT_EQ(limits.limit("New.Test"), 342.5);
  limits.floor_seconds = 500;
  EXPECT_EQ(limits.limit("New.Test"), 500);
  EXPECT_NE(limits.describe("Quick").find("5 times its 2.50 s on the unmutated tree"), std::string::npos)
      << limits.describe("Quick");
  EXPECT_NE(limits.describe("New.Test").find("not timed"), std::string::npos);
}

}  // namespace
}  // namespace cc::tool
