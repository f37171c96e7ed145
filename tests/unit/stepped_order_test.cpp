// One stepped sine (common/stepped_order.hpp): strictly up or strictly down, its direction taken
// from the first two values; the first value that breaks it is named, whichever way it goes.
#include "common/stepped_order.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace bb {
namespace {

TEST(SteppedOrder, UpAndDownSweepsAreOneSteppedSineAndTheFirstBreakIsNamed) {
  EXPECT_FALSE(first_unstepped(std::vector<double>{}));
  EXPECT_FALSE(first_unstepped(std::vector<double>{78.0}));
  EXPECT_FALSE(first_unstepped(std::vector<double>{77.0, 77.05, 77.1}));
  EXPECT_FALSE(first_unstepped(std::vector<double>{80.0, 79.95, 79.9}));
  const auto repeat = first_unstepped(std::vector<double>{77.0, 77.05, 77.05, 77.1});
  ASSERT_TRUE(repeat);
  EXPECT_EQ(repeat->index, 2u);
  EXPECT_FALSE(repeat->down);
  const auto turn = first_unstepped(std::vector<double>{80.0, 79.9, 79.8, 79.9});
  ASSERT_TRUE(turn);
  EXPECT_EQ(turn->index, 3u);
  EXPECT_TRUE(turn->down);
  const auto flat = first_unstepped(std::vector<double>{80.0, 80.0});
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->index, 1u);
}

}  // namespace
}  // namespace bb
