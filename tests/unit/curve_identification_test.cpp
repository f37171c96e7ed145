// Identification from measured curves ([[calibration.data]], identify/fit_points.hpp): how the
// points of a curve are matched to the model's table (interpolation, loop branches, levels). The
// FRF round trip (analytic and central-difference Jacobians) is in hbm_frf_sensitivity_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "common/errors.hpp"
#include "data_block.hpp"
#include "identify/fit_points.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

class CurveIdentification : public test::TempFolderTest {};

TEST_F(CurveIdentification, FrfPointsInterpolateTheComputedCurveAndWrapPhases) {
  write("# example\nfrequency [Hz],amplitude [mm],phase [deg]\n10.5,2.0,179\n11.0,3.0,-179\n", "frf.csv");
  CalibrationData d = test::frf_block(dir_ / "frf.csv");
  ResultTables tables;
  tables.emplace("frf_1", table_from_rows("frf_1", {"point", "frequency_hz", "A.x_amp_m", "A.x_phase_deg"},
                                          {{1, 10.0, 1e-3, 170.0}, {2, 11.0, 3e-3, -170.0}, {3, 12.0, 2e-3, -160.0}}));
  const std::vector<FitPoint> p = data_points(d, tables);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(p[0].computed, 2e-3, 1e-15);  // halfway between 1 and 3 mm
  EXPECT_NEAR(p[0].measured, 2e-3, 1e-15);  // mm -> m
  EXPECT_NEAR(p[0].sigma, 0.02 * 2e-3, 1e-15);
  // 170 -> -170 deg crosses 180: unwrapped, the midpoint is 180 deg, 1 deg above the measured 179.
  EXPECT_NEAR(p[1].misfit(), std::numbers::pi / 180.0, 1e-12);
  // -170 vs -179 deg at 11 Hz: 9 deg, not 351.
  EXPECT_NEAR(p[3].misfit(), 9.0 * std::numbers::pi / 180.0, 1e-12);
  // A measured frequency outside the computed range names the data row.
  write("frequency [Hz],amplitude [mm]\n10.5,2.0\n12.5,1.0\n", "far.csv");
  d.data = read_measured_data(dir_ / "far.csv", DataKind::frf);
  d.columns.erase("phase");
  try {
    data_points(d, tables);
    FAIL() << "a frequency outside the computed range was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("far.csv:3"), std::string::npos) << e.what();
  }
}

TEST_F(CurveIdentification, HysteresisPointsUseTheBranchMovingTheSameWay) {
  // A rigid-plastic loop: T = +1 N while u increases, -1 N while it decreases.
  std::vector<std::vector<double>> rows;
  for (int k = 0; k <= 64; ++k) {
    const double theta = 2 * std::numbers::pi * k / 64.0;
    rows.push_back({static_cast<double>(k + 1), std::cos(theta), std::sin(theta) < 0 ? 1.0 : -1.0});
  }
  ResultTables tables;
  tables.emplace("hysteresis",
                 table_from_rows("hysteresis", {"instant", "relative_tangential_m", "tangential_force_n"}, rows));
  std::string csv = "relative_displacement [m],tangential_force [N]\n";
  for (int k = 0; k < 16; ++k) {
    const double theta = 2 * std::numbers::pi * (k + 0.5) / 16.0;
    csv += std::to_string(0.9 * std::cos(theta)) + ",0.5\n";
  }
  write(csv, "loop.csv");
  const CalibrationData d = test::data_block(
      dir_ / "loop.csv", DataKind::hysteresis, "hysteresis",
      {{"relative_displacement", "relative_tangential_m"}, {"tangential_force", "tangential_force_n"}});
  const std::vector<FitPoint> p = data_points(d, tables);
  ASSERT_EQ(p.size(), 16u);
  for (int k = 0; k < 16; ++k) {
    const bool loading = std::sin(2 * std::numbers::pi * (k + 0.5) / 16.0) < 0;
    EXPECT_DOUBLE_EQ(p[static_cast<size_t>(k)].computed, loading ? 1.0 : -1.0) << "point " << k;
    EXPECT_DOUBLE_EQ(p[static_cast<size_t>(k)].sigma, 0.02 * 0.5);  // relative to the largest measured |T|
  }
}

TEST_F(CurveIdentification, PeaksAreMatchedByForceLevel) {
  write("force [N],frequency [Hz],amplitude [um/N]\n3,170,40\n0.1,225,35\n", "peaks.csv");
  CalibrationData d = test::data_block(dir_ / "peaks.csv", DataKind::peaks, "peaks",
                                       {{"force", "fe_n"}, {"frequency", "peak_hz"}, {"amplitude", "peak_amp_per_n"}});
  ResultTables tables;
  tables.emplace("peaks", table_from_rows("peaks", {"level", "fe_n", "peak_hz", "peak_amp_per_n"},
                                          {{1, 0.1, 224.0, 3.6e-5}, {2, 3.0, 171.0, 4.1e-5}}));
  const std::vector<FitPoint> p = data_points(d, tables);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_DOUBLE_EQ(p[0].computed, 171.0);
  EXPECT_DOUBLE_EQ(p[0].sigma, 0.001 * 170.0);
  EXPECT_DOUBLE_EQ(p[3].computed, 3.6e-5);
  EXPECT_NEAR(p[3].measured, 3.5e-5, 1e-18);
  write("force [N],frequency [Hz],amplitude [um/N]\n5,170,40\n", "other.csv");
  d.data = read_measured_data(dir_ / "other.csv", DataKind::peaks);
  EXPECT_THROW(data_points(d, tables), InputError);  // no computed level at 5 N
}

}  // namespace
}  // namespace bb
