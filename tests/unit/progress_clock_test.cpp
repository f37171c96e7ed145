// The time-left estimate of progress lines (common/progress_clock.hpp).
#include "common/progress_clock.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace bb {
namespace {

TEST(ProgressClock, SaysWhichItemRunsThenHowManyAreDoneAndWhatIsLeft) {
  ProgressClock clock(4);
  EXPECT_EQ(clock.status(), "1 of 4 running");
  clock.finished(1);
  EXPECT_NE(clock.status().find("1 of 4 done, about "), std::string::npos) << clock.status();
  EXPECT_NE(clock.status().find(" left"), std::string::npos) << clock.status();
  clock.finished(4);
  EXPECT_EQ(clock.status(), "4 of 4 done");
}

// An optimizer's iterations against its cap: the time left is a bound, said as one.
TEST(ProgressClock, BoundIsSaidAsABoundAndOnlyOnceTimeIsKnown) {
  ProgressClock clock(10);
  EXPECT_EQ(clock.bound(), "");
  clock.finished(3);
  EXPECT_TRUE(clock.bound().starts_with("at most ")) << clock.bound();
  EXPECT_TRUE(clock.bound().ends_with(" left")) << clock.bound();
  clock.finished(10);
  EXPECT_EQ(clock.bound(), "");
}

TEST(ProgressClock, AppendsItsStatusToEveryLineAndStaysSilentWithoutAReceiver) {
  ProgressClock clock(2);
  std::string seen;
  const std::function<void(const std::string&)> progress = [&](const std::string& line) { seen = line; };
  with_clock(progress, clock)("sweep at 180 Hz");
  EXPECT_EQ(seen, "sweep at 180 Hz  [1 of 2 running]");
  EXPECT_FALSE(with_clock(std::function<void(const std::string&)>{}, clock));
}

}  // namespace
}  // namespace bb
