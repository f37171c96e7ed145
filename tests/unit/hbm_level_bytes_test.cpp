// A swept force level as bytes (what MPI ranks send each other, forced/hbm_level_bytes.hpp): a
// level read back is the level written, every field bit for bit (its bytes written again are the
// same, and the fields the tables and plots read compare equal), and a record cut short or running
// on is refused rather than read as a level.
#include "forced/hbm_level_bytes.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "analysis/hbm_analysis.hpp"
#include "cases/case_spec.hpp"
#include "model/build_model.hpp"
#include "temp_folder.hpp"
#include "two_blades_case.hpp"

namespace bb {
namespace {

// The two blades at H = 3 over a narrower band, with the Floquet exponents of every path point:
// every optional part of a level set.
std::string blades_case() {
  std::string text = test::kTwoBladesCase;
  const auto swap = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  swap("frequency_hz = [140.0, 215.0]", "frequency_hz = [150.0, 200.0]");
  swap("step_hz = 0.2", "step_hz = 1.0");
  swap("harmonics = 1\n", "harmonics = 3\nstability = \"path\"\n");
  swap("time_samples = 128", "time_samples = 64");
  swap("force_levels = [0.01, 10.0, 1000.0]", "force_levels = [5.0, 200.0]");
  return text;
}

class HbmLevelBytes : public test::TempFolderTest {};

TEST_F(HbmLevelBytes, ALevelReadBackIsTheLevelWrittenBitForBit) {
  const CaseSpec spec = parse_case_file(write(blades_case()));
  const HbmOutcome o = run_hbm(build_model(spec.model), std::get<HbmSpec>(spec.analysis));
  ASSERT_EQ(o.levels.size(), 2u);
  for (const HbmLevel& level : o.levels) {
    const std::string bytes = to_bytes(level);
    const HbmLevel back = level_from_bytes(bytes);
    EXPECT_EQ(to_bytes(back), bytes);
    EXPECT_EQ(back.force, level.force);
    ASSERT_EQ(back.path.points.size(), level.path.points.size());
    EXPECT_EQ(back.path.points.back().x, level.path.points.back().x);
    EXPECT_EQ(back.amplitude, level.amplitude);
    EXPECT_EQ(back.components, level.components);
    EXPECT_EQ(back.floquet_max_real, level.floquet_max_real);
    ASSERT_EQ(back.peaks.size(), level.peaks.size());
    ASSERT_FALSE(level.peaks.empty());
    const HbmPeak& a = level.peaks.front();
    const HbmPeak& b = back.peaks.front();
    EXPECT_EQ(b.kind, a.kind);
    EXPECT_EQ(b.frequency_hz, a.frequency_hz);
    ASSERT_FALSE(a.solution.contacts.empty());
    EXPECT_EQ(b.solution.contacts.front().u, a.solution.contacts.front().u);
    EXPECT_EQ(b.solution.contacts.front().dtangential_du, a.solution.contacts.front().dtangential_du);
    EXPECT_EQ(b.solution.contacts.front().state, a.solution.contacts.front().state);
    EXPECT_EQ(b.energy.friction, a.energy.friction);
    EXPECT_EQ(b.truncation.share, a.truncation.share);
    ASSERT_TRUE(a.stability && b.stability);
    EXPECT_EQ(b.stability->exponents, a.stability->exponents);
    EXPECT_EQ(b.stability->stable, a.stability->stable);
  }
}

TEST_F(HbmLevelBytes, ARecordCutShortOrRunningOnIsRefused) {
  HbmLevel level;
  level.force = 30.0;
  level.path.points.resize(2);
  level.path.points[1].x = Eigen::VectorXd::Ones(5);
  level.peaks.resize(1);
  const std::string bytes = to_bytes(level);
  EXPECT_EQ(level_from_bytes(bytes).path.points[1].x, level.path.points[1].x);
  EXPECT_THROW(level_from_bytes(bytes.substr(0, bytes.size() - 3)), std::runtime_error);
  EXPECT_THROW(level_from_bytes(bytes + "x"), std::runtime_error);
}

}  // namespace
}  // namespace bb
