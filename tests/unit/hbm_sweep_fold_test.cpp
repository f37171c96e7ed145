// Grid sweeps through folds (forced/hbm_grid_sweep.cpp, hbm/continuation.hpp) on the Table XI
// model with kt = 8.09e7, mu = 0.7231 (identified until 2026-11-28), events AFT: a smooth fold that runs back further
// than half a grid step, a non-smooth one where the branch turns back at a kink, and (at a calibration's trial values)
// a fold the branch never comes back from, where the response jumps.
#include <gtest/gtest.h>

#include <string>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "model/build_model.hpp"
#include "temp_folder.hpp"
#include "two_blade_rom_case.hpp"

namespace bb {
namespace {

class HbmSweepFold : public test::TempFolderTest {
 protected:
  // One force level of the model with kt and mu (by default those identified until 2026-11-28), events AFT, at H
  // harmonics.
  AnalysisResults sweep(const std::string& level, const std::string& range, int harmonics, int samples,
                        const std::string& kt = "8.090e7", const std::string& mu = "0.7231") const {
    test::TwoBladeRomCase c;
    c.kt = kt;
    c.mu = mu;
    c.levels = "[" + level + "]";
    c.range = range;
    c.harmonics = std::to_string(harmonics);
    c.samples = std::to_string(samples);
    c.analysis_extra = "aft = \"events\"\n";
    const std::filesystem::path file = write(test::two_blade_rom_case_text(c));
    const CaseSpec spec = parse_case_table(read_case_table(file), file);
    return run_analysis(spec.analysis, build_model(spec.model));
  }
};

double fold_cell(const ResultTable& t, const std::string& column, Eigen::Index row) {
  const auto c = t.column_index(column);
  EXPECT_TRUE(c.has_value()) << column;
  return c ? t.values(row, static_cast<Eigen::Index>(*c)) : 0.0;
}

Eigen::VectorXd frequencies(const ResultTable& frf) {
  const auto f = frf.column_index("frequency_hz");
  EXPECT_TRUE(f.has_value());
  return f ? Eigen::VectorXd(frf.values.col(static_cast<Eigen::Index>(*f))) : Eigen::VectorXd();
}

// The level's sweep reached 190 Hz within `iterations` corrector iterations, with every grid
// frequency of 170-190 Hz (0.05 Hz) in its frf table.
void expect_whole_band_within(const AnalysisResults& r, const std::string& frf, double iterations) {
  const ResultTable& cost = r.tables.at("sweep_cost");
  EXPECT_EQ(fold_cell(cost, "reached_end", 0), 1.0);
  EXPECT_LT(fold_cell(cost, "corrector_iterations", 0), iterations);
  const Eigen::VectorXd hz = frequencies(r.tables.at(frf));
  for (int i = 0; i <= 400; ++i) {
    const double grid = 170.0 + 0.05 * i;
    EXPECT_LT((hz.array() - grid).abs().minCoeff(), 1e-9) << grid;
  }
}

// 80 N, H = 3: at 183.646 Hz the branch turns back in frequency, runs back to about 183.58 Hz and
// turns forward again (an S-shaped response with three solutions). The arclength bridge used to
// stop when the path ran back more than half a grid step, and 183.65 Hz was lost.
TEST_F(HbmSweepFold, TheGridSweepFollowsAFoldBackAndForwardAndSolvesEveryGridFrequency) {
  const AnalysisResults r = sweep("80.0", "[183.3, 183.75]", 3, 32);
  const ResultTable& cost = r.tables.at("sweep_cost");
  EXPECT_EQ(fold_cell(cost, "reached_end", 0), 1.0);
  EXPECT_GE(fold_cell(cost, "turning_points", 0), 2.0);  // back at the fold, forward again below it
  const ResultTable& frf = r.tables.at("frf_80");
  const Eigen::VectorXd hz = frequencies(frf);
  // Every grid frequency is on the path, and the path ran back below the fold.
  for (const double grid : {183.3, 183.5, 183.6, 183.65, 183.7, 183.75})
    EXPECT_LT((hz.array() - grid).abs().minCoeff(), 1e-9) << grid;
  const Eigen::Index last = hz.size() - 1;
  EXPECT_LT((hz.head(last).array() - hz.tail(last).array()).minCoeff(), -0.03);  // ran back by more than a half step
  const auto residual = frf.column_index("residual_n");
  ASSERT_TRUE(residual.has_value());
  EXPECT_LT(frf.values.col(static_cast<Eigen::Index>(*residual)).maxCoeff(), 1e-6);  // tolerance 1e-9 x 360 N
}

// At 60 N, H = 5, the branch meets a kink near 173.217 Hz (a slip phase appears) and turns back in
// frequency at it by about 120 degrees: no point on the corrector's plane normal to the old tangent
// lies on the branch beyond, however small the step. The bridge turns the corner, runs back to
// about 171.7 Hz and forward again past 173.3 Hz. Before corners were turned the sweep lost 6
// frequencies here (173.25-173.5 Hz).
TEST_F(HbmSweepFold, TheBridgeTurnsAtACornerWhereTheBranchRunsBackInFrequency) {
  const AnalysisResults r = sweep("60.0", "[171.5, 173.3]", 5, 44);
  const ResultTable& cost = r.tables.at("sweep_cost");
  EXPECT_EQ(fold_cell(cost, "reached_end", 0), 1.0);
  EXPECT_GE(fold_cell(cost, "corners", 0), 1.0);
  EXPECT_GE(fold_cell(cost, "turning_points", 0), 4.0);
  const Eigen::VectorXd hz = frequencies(r.tables.at("frf_60"));
  const Eigen::Index grid_points = 37;     // 171.5, 171.55, ..., 173.3
  EXPECT_GT(hz.size(), grid_points + 50);  // the arc back and forth besides the grid (89 points)
  for (Eigen::Index i = 0; i < grid_points; ++i) {
    const double grid = 171.5 + 0.05 * static_cast<double>(i);
    EXPECT_LT((hz.array() - grid).abs().minCoeff(), 1e-9) << grid;
  }
}

// 30 N, H = 1, kt = 1e8, mu = 0.503 (a calibration's Jacobian run): at 172.38 Hz the branch turns
// back and runs out of the band below (a jump of the response); the next branch is met by Newton at
// a higher frequency, and the frequencies between are solved from above. The forward pass tried
// every fallback from the last point below the fold again at each of the 39 frequencies between
// (substeps, a bridge that ran back out of the band, patient Newton): 28 117 corrector iterations
// for this level, where the other levels take about 450.
TEST_F(HbmSweepFold, AFoldTheBranchDoesNotComeBackFromIsBridgedOnceNotAtEveryFrequencyBeyondIt) {
  expect_whole_band_within(sweep("30.0", "[170.0, 190.0]", 1, 64, "1.0e8", "0.503478"), "frf_30", 6000.0);
}

// 80 N at kt = 3.37e8, mu = 2 (a calibration start's trial values): the bridge from 188.40 Hz turns
// back and forth 13 times along kinks near 188.3 Hz without arriving, whatever grid frequency it
// aims at, and each of the 20 frequencies up to 189.40 Hz (where Newton from the guess converges)
// tried it again from that point: 117 541 iterations, 20 s. Bridged once (the later frequencies
// still try their substeps and patient Newton): 13 599.
TEST_F(HbmSweepFold, ABridgeThatWandersAlongKinksIsNotTriedAgainFromTheSamePoint) {
  expect_whole_band_within(sweep("80.0", "[170.0, 190.0]", 1, 64, "3.36785e8", "2.0"), "frf_80", 20000.0);
}

}  // namespace
}  // namespace bb
