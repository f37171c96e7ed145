// Identification from measured curves ([[calibration.data]], identify/fit_points.hpp): how the
// points of a curve are matched to the model's table (interpolation, loop branches, levels), and
// a round trip on the 1-DOF friction oscillator: FRF curves (amplitude and phase) at a stuck and a
// slipping level, computed by the harmonic balance at known kt, mu and damping, written by
// write_synthetic_data with 2 % noise and two 30 % outliers, fitted from wrong start values with a
// Huber loss. Every parameter must come back within two standard deviations, for two noise draws.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "analysis/case_results.hpp"
#include "common/errors.hpp"
#include "identify/calibrate_case.hpp"
#include "identify/fit_points.hpp"
#include "identify/synthetic_data.hpp"
#include "oscillator_case.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

class CurveIdentification : public test::TempFolderTest {};

ResultTable table(const std::string& name, std::vector<std::string> columns, const std::vector<std::vector<double>>& rows) {
  return table_from_rows(name, std::move(columns), rows);
}

TEST_F(CurveIdentification, FrfPointsInterpolateTheComputedCurveAndWrapPhases) {
  write("# example\nfrequency [Hz],amplitude [mm],phase [deg]\n10.5,2.0,179\n11.0,3.0,-179\n", "frf.csv");
  CalibrationData d;
  d.name = "rig";
  d.data = read_measured_data(dir_ / "frf.csv", DataKind::frf);
  d.table = "frf_1";
  d.columns = {{"frequency", "frequency_hz"}, {"amplitude", "A.x_amp_m"}, {"phase", "A.x_phase_deg"}};
  ResultTables tables;
  tables.emplace("frf_1", table("frf_1", {"point", "frequency_hz", "A.x_amp_m", "A.x_phase_deg"},
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
  tables.emplace("hysteresis", table("hysteresis", {"instant", "relative_tangential_m", "tangential_force_n"}, rows));
  std::string csv = "relative_displacement [m],tangential_force [N]\n";
  for (int k = 0; k < 16; ++k) {
    const double theta = 2 * std::numbers::pi * (k + 0.5) / 16.0;
    csv += std::to_string(0.9 * std::cos(theta)) + ",0.5\n";
  }
  write(csv, "loop.csv");
  CalibrationData d;
  d.name = "loop";
  d.data = read_measured_data(dir_ / "loop.csv", DataKind::hysteresis);
  d.table = "hysteresis";
  d.columns = {{"relative_displacement", "relative_tangential_m"}, {"tangential_force", "tangential_force_n"}};
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
  CalibrationData d;
  d.name = "peaks";
  d.data = read_measured_data(dir_ / "peaks.csv", DataKind::peaks);
  d.table = "peaks";
  d.columns = {{"force", "fe_n"}, {"frequency", "peak_hz"}, {"amplitude", "peak_amp_per_n"}};
  ResultTables tables;
  tables.emplace("peaks", table("peaks", {"level", "fe_n", "peak_hz", "peak_amp_per_n"}, {{1, 0.1, 224.0, 3.6e-5}, {2, 3.0, 171.0, 4.1e-5}}));
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

std::string oscillator(double kt, double mu, double zeta, const std::string& data) {
  test::OscillatorCase c;
  c.kt = std::to_string(kt);
  c.mu = std::to_string(mu);
  c.zeta = std::to_string(zeta);
  c.levels = "[0.3, 10.0]";
  c.range = "[150.0, 240.0]";
  c.step = "0.5";
  c.extra = data;
  return test::oscillator_case_text(c);
}

class FrfRoundTrip : public CurveIdentification, public ::testing::WithParamInterface<unsigned> {};

TEST_P(FrfRoundTrip, KtMuAndDampingComeBackFromNoisyFrfCurvesWithOutliers) {
  const double truth[] = {1.5e6, 0.35, 0.01};
  const CaseSpec spec = parse_case_table(toml::parse(oscillator(truth[0], truth[1], truth[2], "")), dir_ / "truth.toml");
  const CaseResults r = compute_case_results(spec, build_model(spec));
  SyntheticOptions o;
  o.kind = DataKind::frf;
  o.noise = 0.02;
  o.phase_noise = 0.02;  // rad
  o.outliers = 2;
  o.every = 6;           // a point every 3 Hz
  o.columns = {{"frequency", "frequency_hz", "Hz"}, {"amplitude", "A.x_amp_m", "um"}, {"phase", "A.x_phase_deg", "deg"}};
  std::string blocks;
  for (const char* level : {"0.3", "10"}) {
    o.seed = GetParam() + static_cast<unsigned>(level[0]);
    write_synthetic_data(r.tables.at(std::string("frf_") + level), o, dir_ / (std::string("frf_") + level + ".csv"));
    blocks += std::string("[[calibration.data]]\nkind = \"frf\"\nfile = \"frf_") + level + ".csv\"\ntable = \"frf_" + level +
              "\"\ncolumns = { frequency = \"frequency_hz\", amplitude = \"A.x_amp_m\", phase = \"A.x_phase_deg\" }\n";
  }
  const std::string calibration = R"([calibration]
parameters = [{ path = "analysis.contact.0.kt", lower = 1.0e5, upper = 1.0e7 },
              { path = "analysis.contact.0.mu", lower = 0.05, upper = 2.0 },
              { path = "analysis.modal_damping", lower = 0.001, upper = 0.1 }]
loss = "huber"
loss_scale = 2.0
max_iterations = 40
function_tolerance = 1e-6
derivative_step = 1e-2
)";
  write(oscillator(5.0e5, 0.8, 0.03, calibration + blocks));  // wrong by 3x, 2.3x and 3x
  const CalibrationOutcome out = calibrate_case(dir_ / "case.toml", false);
  std::printf("  %s, %d evaluations, reduced chi-square %.3g\n", out.termination.c_str(), out.residual_evaluations, out.reduced_chi_square);
  ASSERT_TRUE(out.converged) << out.termination;
  for (size_t i = 0; i < 3; ++i) {
    std::printf("  %s: identified %.6g +- %.3g, truth %.6g (%.2f sigma)\n", out.spec.parameters[i].path.c_str(), out.values[i],
                out.std_devs[i], truth[i], std::abs(out.values[i] - truth[i]) / out.std_devs[i]);
    ASSERT_TRUE(std::isfinite(out.std_devs[i]));
    EXPECT_LT(std::abs(out.values[i] - truth[i]), 2 * out.std_devs[i]);
  }
}

INSTANTIATE_TEST_SUITE_P(NoiseDraws, FrfRoundTrip, ::testing::Values(3u, 8u));

}  // namespace
}  // namespace bb
