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

namespace bb {
namespace {

// Two blades coupled by a friction contact (stick to gross slip over the levels), H = 3, with the
// Floquet exponents of every path point and a second response: every optional part of a level set.
constexpr const char* kBladesCase = R"(
[case]
name = "blades"
[analysis]
type = "hbm"
frequency_hz = [150.0, 200.0]
step_hz = 1.0
harmonics = 3
time_samples = 64
tolerance = 1e-10
modal_damping = 0.01
stability = "path"
forces = [{ dof = "B.x", amplitude = 1.0 }]
force_levels = [5.0, 200.0]
responses = ["B.x", "A.x"]
ip_oop = { left = "A.x", right = "B.x" }
[analysis.model]
name = "blades"
dofs = ["A.x", "B.x"]
stiffness = [[1.1e6, -1.0e5], [-1.0e5, 1.1e6]]
mass = [[1.0, 0.0], [0.0, 1.0]]
[[analysis.contact]]
name = "platform"
tangential = { "A.x" = 1.0, "B.x" = -1.0 }
kn = 1.0e6
kt = 2.0e5
mu = 0.3
n0 = 20.0
)";

class HbmLevelBytes : public test::TempFolderTest {};

TEST_F(HbmLevelBytes, ALevelReadBackIsTheLevelWrittenBitForBit) {
  const CaseSpec spec = parse_case_file(write(kBladesCase));
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
