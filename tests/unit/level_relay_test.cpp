// The relay that hands each force level's first solution to the next level: level 0 has no
// neighbour, a level waits for its neighbour across threads, the first publication counts, and a
// level that ends without a solution still releases its successor.
#include "forced/level_relay.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace bb {
namespace {

LevelStart start_of(double value, int harmonics) { return {Eigen::VectorXd::Constant(3, value), harmonics}; }

TEST(LevelRelay, TheFirstLevelHasNoNeighbourAndOnlyTheFirstPublicationCounts) {
  LevelRelay relay(3);
  EXPECT_FALSE(relay.from_neighbour(0));
  relay.publish(0, start_of(1.0, 3));
  relay.publish(0, start_of(2.0, 5));  // a later sweep of the same level (another H) is ignored
  const std::optional<LevelStart> s = relay.from_neighbour(1);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->harmonics, 3);
  EXPECT_EQ(s->x[0], 1.0);
}

TEST(LevelRelay, ALevelWaitsForItsNeighbourOnAnotherThread) {
  LevelRelay relay(2);
  std::optional<LevelStart> received;
  std::thread successor([&] { received = relay.from_neighbour(1); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  relay.publish(0, start_of(4.0, 7));
  successor.join();
  ASSERT_TRUE(received);
  EXPECT_EQ(received->x[2], 4.0);
}

TEST(LevelRelay, ALevelThatEndsWithoutASolutionReleasesItsSuccessorWithNone) {
  LevelRelay relay(2);
  std::optional<LevelStart> received = start_of(9.0, 1);
  std::thread successor([&] { received = relay.from_neighbour(1); });
  { const LevelRelay::Guard ended(relay, 0); }
  successor.join();
  EXPECT_FALSE(received);
  // and a guard after a publication changes nothing
  LevelRelay other(2);
  {
    const LevelRelay::Guard ended(other, 0);
    other.publish(0, start_of(5.0, 1));
  }
  ASSERT_TRUE(other.from_neighbour(1));
  EXPECT_EQ(other.from_neighbour(1)->x[1], 5.0);
}

}  // namespace
}  // namespace bb
