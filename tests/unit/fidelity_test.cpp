// The error estimates behind `run --fidelity auto`: Richardson extrapolation with a fitted order,
// and the pairing of two runs' result rows.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "common/power_law.hpp"
#include "pipeline/run_case.hpp"
#include "pipeline/run_fidelity.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

TEST(Fidelity, PowerLawErrorRecoversTheErrorOfAnAlgebraicSequence) {
  // e(x) = C x^-p on arithmetic levels (harmonics 3, 5, 7), where a geometric (Aitken) estimate errs.
  for (double p : {0.8, 1.3, 2.0, 4.0}) {
    const auto e = [&](double x) { return 0.05 * std::pow(x, -p); };
    const double estimate = power_law_error({3, 5, 7}, e(3) - e(5), e(5) - e(7));
    EXPECT_NEAR(estimate, e(5), 1e-8 * e(5)) << "p = " << p;
  }
  // Doubling levels (AFT samples): the same law.
  const auto e = [](double x) { return 3.0 / x; };
  EXPECT_NEAR(power_law_error({256, 512, 1024}, e(256) - e(512), e(512) - e(1024)), e(512), 1e-10);
}

TEST(Fidelity, PowerLawErrorIsInfiniteWhenTheDifferencesDoNotConverge) {
  EXPECT_TRUE(std::isinf(power_law_error({1, 2, 3}, 1e-3, 2e-3)));  // growing
  // Equal differences on doubling levels: slower than any power law allows.
  EXPECT_TRUE(std::isinf(power_law_error({1, 2, 4}, 1e-3, 1e-3)));
  EXPECT_TRUE(std::isinf(power_law_error({1, 2, 4}, 1e-3, std::nan(""))));
  EXPECT_EQ(power_law_error({1, 2, 4}, 1e-3, 0.0), 0.0);  // converged exactly
}

TEST(Fidelity, RelativeDifferencePairsRowsByKeyAndNamesAMissingColumn) {
  const ResultTable coarse = table_from_rows("frf_1", {"point", "amp"}, {{1, 1.00}, {2, 2.02}, {3, 5.0}});
  const ResultTable fine = table_from_rows("frf_1", {"point", "amp"}, {{2, 2.0}, {1, 1.0}});
  EXPECT_NEAR(relative_difference(coarse, fine, {"amp"}), 0.01, 1e-12);  // row 3 has no partner
  const ResultTable broken = table_from_rows("frf_1", {"point", "amp"}, {{1, std::nan("")}, {2, 2.0}});
  EXPECT_TRUE(std::isinf(relative_difference(broken, fine, {"amp"})));
  EXPECT_THROW(relative_difference(coarse, fine, {"phase"}), InputError);
  const ResultTable elsewhere = table_from_rows("frf_1", {"point", "amp"}, {{7, 1.0}});
  EXPECT_THROW(relative_difference(coarse, elsewhere, {"amp"}), InputError);
}

TEST(Fidelity, RelativeDifferencePairsSweepRowsByFrequencyNotByPointNumber) {
  // The finer sweep inserted a point at 201 Hz: its point numbers shift, its frequencies do not.
  const ResultTable coarse =
      table_from_rows("frf_1", {"point", "frequency_hz", "amp"}, {{1, 200, 1.0}, {2, 202, 2.0}, {3, 204, 3.0}});
  const ResultTable fine = table_from_rows("frf_1", {"point", "frequency_hz", "amp"},
                                           {{1, 200, 1.0}, {2, 201, 1.5}, {3, 202, 2.0}, {4, 204, 3.03}});
  EXPECT_NEAR(relative_difference(coarse, fine, {"amp"}, "frequency_hz"), 0.03 / 3.03, 1e-12);
  EXPECT_GT(relative_difference(coarse, fine, {"amp"}), 0.3);  // by point number: wrong partners
  EXPECT_THROW(relative_difference(coarse, fine, {"amp"}, "omega"), InputError);
}

TEST(Fidelity, RelativeDifferenceMeasuresNumericalZerosOnTheColumnsScale) {
  // Rigid-body modes: exactly 0 Hz on one mesh, 3e-5 Hz on the next. Their change is 1.5e-7 of the
  // largest frequency, not 100 % of itself; the elastic mode's 1 % still counts on its own value.
  const ResultTable coarse = table_from_rows("frequencies", {"mode", "f"}, {{1, 0.0}, {2, 202.0}});
  const ResultTable fine = table_from_rows("frequencies", {"mode", "f"}, {{1, 3e-5}, {2, 200.0}});
  EXPECT_NEAR(relative_difference(coarse, fine, {"f"}), 0.01, 1e-12);
  const ResultTable fine_rigid_only = table_from_rows("frequencies", {"mode", "f"}, {{1, 3e-5}, {2, 202.0}});
  EXPECT_NEAR(relative_difference(coarse, fine_rigid_only, {"f"}), 3e-5 / 202.0, 1e-15);
  // Above 1e-6 of the scale a value is its own measure.
  const ResultTable small = table_from_rows("frequencies", {"mode", "f"}, {{1, 1e-3}, {2, 202.0}});
  const ResultTable small_fine = table_from_rows("frequencies", {"mode", "f"}, {{1, 2e-3}, {2, 202.0}});
  EXPECT_NEAR(relative_difference(small, small_fine, {"f"}), 0.5, 1e-12);
}

// A friction oscillator integrated in time for at most 40 periods per frequency: a 1e-2
// cycle-to-cycle change is reached there, 1e-8 and 1e-9 are not, and a peak on a frequency that is
// not steady is a solver failure.
std::string time_case(const std::string& tolerances) {
  return R"([case]
name = "time_fidelity"
[analysis]
type = "time"
frequency_hz = [150.0, 170.0]
step_hz = 2.0
steps_per_period = 64
steady_tolerance = 1e-2
max_cycles = 40
modal_damping = 0.05
forces = [{ dof = "A.x", amplitude = 1.0 }]
force_levels = [10.0]
responses = ["A.x"]
[analysis.model]
name = "oscillator"
dofs = ["A.x"]
stiffness = [[1.0e6]]
mass = [[1.0]]
[[analysis.contact]]
name = "ground"
tangential = { "A.x" = 1.0 }
kn = 1.0e6
kt = 1.0e6
mu = 0.3
n0 = 30.0
[fidelity]
target = 1e-2
result = "frf"
columns = ["A.x_amp_m"]
key = "frequency_hz"
axes = [{ setting = "analysis.steady_tolerance", levels = )" +
         tolerances + " }]\n";
}

class FidelityClimb : public test::TempFolderTest {
 protected:
  RunOutcome run_auto(const std::string& tolerances) const {
    RunOptions opt;
    opt.out_dir = dir_ / "out";
    opt.plots = false;
    opt.fidelity = FidelityMode::automatic;
    return run_case(write(time_case(tolerances)), opt);
  }
};

TEST_F(FidelityClimb, AFinerLevelThatFailsIsPassedOverAndTheTargetIsNotMet) {
  const RunOutcome o = run_auto("[1e-2, 1e-9]");
  // The 1e-2 run stands; its error is unknown, so the target check fails (exit 1, not 3).
  EXPECT_EQ(o.record.status, RunStatus::fail);
  EXPECT_NE(o.record.fidelity.find("steady_tolerance = 0.01"), std::string::npos) << o.record.fidelity;
  bool warned = false;
  for (const std::string& w : o.record.warnings) warned |= w.find("passed over because its solve failed") != w.npos;
  EXPECT_TRUE(warned);
  ASSERT_TRUE(std::filesystem::exists(dir_ / "out" / "frontier.csv"));
}

TEST_F(FidelityClimb, WhenEveryLevelFailsTheRunIsASolverFailure) {
  const RunOutcome o = run_auto("[1e-8, 1e-9]");
  EXPECT_EQ(o.record.status, RunStatus::solver_failed);
  EXPECT_NE(o.record.message.find("failed"), std::string::npos) << o.record.message;
}

}  // namespace
}  // namespace bb
