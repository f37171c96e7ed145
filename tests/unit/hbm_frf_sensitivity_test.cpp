// Sensitivity columns of the hbm FRF tables (analysis key `sensitivities`, hbm/sensitivity.hpp)
// and the calibration that uses them as its Jacobian ([calibration] derivatives = "auto").
//   - The dlog columns of the 1-DOF friction oscillator (cases/verification/friction_oscillator_hbm.toml
//     in a shorter band) agree with central differences of whole re-runs of the case, at a stuck
//     (0.01 N) and a stick-slip (3 N) level; so do those of the two-blade model with the rigid
//     damper (damper.kt, damper.mu, zeta) at a slipping and a nearly stuck level; and those of the
//     lumped stiffness and mass.
//   - Paths the derivative does not cover are refused with file:line.
//   - The FRF round trip of curve_identification_test.cpp (same data, seeds and start values)
//     fitted with analytic derivatives recovers kt, mu and zeta within 2 sigma with fewer model
//     evaluations than central differences; with a parameter the analysis cannot differentiate,
//     "auto" takes that column by central differences and says why.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "cases/parse_calibration.hpp"
#include "common/errors.hpp"
#include "data_block.hpp"
#include "identify/fit_points.hpp"
#include "identify/synthetic_data.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "pipeline/calibrate_case.hpp"
#include "temp_folder.hpp"
#include "two_blade_rom_case.hpp"

namespace bb {
namespace {

class HbmFrfSensitivity : public test::TempFolderTest {};

std::string sensitivity_case(const std::string& levels, const std::string& analysis_extra) {
  test::OscillatorCase c;
  c.levels = levels;
  c.range = "[150.0, 240.0]";
  c.step = "1.0";
  c.samples = "256";
  c.tolerance = "1e-12";
  c.analysis_extra = analysis_extra;
  return test::oscillator_case_text(c);
}

Eigen::VectorXd column(const ResultTable& t, const std::string& name) {
  const auto c = t.column_index(name);
  if (!c) throw std::out_of_range("no column " + name + " in " + t.name);
  return t.values.col(*c);
}

ResultTables run(const toml::table& t, const std::filesystem::path& file) {
  const CaseSpec spec = parse_case_table(t, file);
  return run_analysis(spec.analysis, build_model(spec.model)).tables;
}

// Central differences in log p of every table, at two steps. The AFT map is piecewise smooth (a
// time sample sticks or slips): a step that moves a sample across a switch averages two slopes, so
// each point is compared with the nearer of the two differences; a switch within 1e-6 of a point is
// rare (the samples are 2 pi / 256 apart and a switch instant moves O(1) rad per unit log p).
struct CentralDifferences {
  // Truncation h^2 |f'''| / 6 (|f'''| ~ 1e4 |z| at a resonance with zeta = 0.01) against the
  // solver's noise, 1e-12 / h relative.
  static constexpr double steps[2] = {1e-5, 1e-6};
  ResultTables up[2], down[2];
  CentralDifferences(const toml::table& plain, const std::string& path, const std::filesystem::path& file) {
    for (int k = 0; k < 2; ++k) {
      toml::table u = plain, d = plain;
      const double p = node_at_path(u, path)->value<double>().value();
      *node_at_path(u, path)->as_floating_point() = p * std::exp(steps[k]);
      *node_at_path(d, path)->as_floating_point() = p * std::exp(-steps[k]);
      up[k] = run(u, file);
      down[k] = run(d, file);
    }
  }
  // max over the table's points of min over the steps of |exact - FD|, in the column's unit.
  double error(const std::string& table, const std::string& q, const Eigen::VectorXd& exact) const {
    Eigen::VectorXd best = Eigen::VectorXd::Constant(exact.size(), INFINITY);
    for (int k = 0; k < 2; ++k) {
      Eigen::VectorXd fd = column(up[k].at(table), q) - column(down[k].at(table), q);
      if (fd.size() != exact.size()) return INFINITY;
      if (q.ends_with("_deg")) fd = fd.unaryExpr([](double d) { return std::remainder(d, 360.0); });
      best = best.cwiseMin((exact - fd / (2 * steps[k])).cwiseAbs());
    }
    return best.maxCoeff();
  }
};

// The dlog columns of `paths` on the oscillator at a stuck (0.01 N) and a stick-slip (3 N) level
// against central differences of whole runs.
void expect_dlog_columns_match_whole_runs(const std::vector<std::string>& paths, const std::filesystem::path& file) {
  std::string list = "sensitivities = [";
  for (const std::string& p : paths) list += "\"" + p + "\", ";
  list += "]";
  const ResultTables analytic = run(toml::parse(sensitivity_case("[0.01, 3.0]", list)), file);
  const toml::table plain = toml::parse(sensitivity_case("[0.01, 3.0]", ""));
  for (const std::string& path : paths) {
    const CentralDifferences fd(plain, path, file);
    for (const char* level : {"frf_0.01", "frf_3"}) {
      const ResultTable& a = analytic.at(level);
      for (const char* q : {"A.x_amp_m", "A.x_phase_deg"}) {
        const Eigen::VectorXd value = column(a, q);
        const Eigen::VectorXd exact = column(a, std::string(q) + "_dlog_" + path);
        ASSERT_TRUE(exact.allFinite()) << level << " " << q << " " << path;
        // Relative to the column's scale: |z| itself for the amplitude, one degree for the phase.
        const double scale = std::string(q) == "A.x_amp_m" ? value.cwiseAbs().maxCoeff() : 1.0;
        const double error = fd.error(level, q, exact) / scale;
        std::printf("  %-9s %-14s d/dlog %-28s max |p d/dp| %.3e, max |analytic - FD| %.2e (relative to %s)\n", level,
                    q, path.c_str(), exact.cwiseAbs().maxCoeff() / scale, error,
                    std::string(q) == "A.x_amp_m" ? "max |z|" : "1 deg");
        // The analytic columns are exact; what is left is the differences' own error (measured:
        // <= 1e-8 of max |z| and <= 8e-7 deg). A wrong term would show at 1e-3 of the derivative.
        EXPECT_LT(error, q == std::string("A.x_amp_m") ? 1e-6 : 1e-4) << level << " " << q << " " << path;
      }
    }
  }
}

TEST_F(HbmFrfSensitivity, DlogColumnsAgreeWithCentralDifferencesOfWholeRuns) {
  expect_dlog_columns_match_whole_runs(
      {"analysis.contact.0.kt", "analysis.contact.0.mu", "analysis.contact.0.n0", "analysis.modal_damping"},
      dir_ / "case.toml");
}

// An entry of the lumped K or M moves the modal damping built from them too (its derivative by
// differences of that construction): the columns still meet whole runs.
TEST_F(HbmFrfSensitivity, LumpedMatrixDlogColumnsAgreeWithCentralDifferencesOfWholeRuns) {
  expect_dlog_columns_match_whole_runs({"analysis.model.stiffness.0.0", "analysis.model.mass.0.0"}, dir_ / "case.toml");
}

// The oscillator written as a modal model (frequency 1e3 / (2 pi) Hz and modal mass 1 kg: the same
// K and M) with its damping given per mode: the modal frequency (K alone, twice its log-derivative),
// the modal mass (M and K together) and the mode's own ratio meet whole runs.
TEST_F(HbmFrfSensitivity, ModalModelDlogColumnsAgreeWithCentralDifferencesOfWholeRuns) {
  const auto modal = [](std::string text) {
    const auto replace = [&](const std::string& from, const std::string& to) {
      const size_t at = text.find(from);
      if (at == std::string::npos) throw std::logic_error("oscillator case without " + from);
      text.replace(at, from.size(), to);
    };
    replace("stiffness = [[1.0e6]]\nmass = [[1.0]]", "frequency_hz = [159.15494309189535]\nmodal_mass = [1.0]");
    replace("modal_damping = 0.01", "modal_damping = [0.01]");
    return text;
  };
  const std::vector<std::string> paths = {"analysis.model.frequency_hz.0", "analysis.model.modal_mass.0",
                                          "analysis.modal_damping.0"};
  std::string list = "sensitivities = [";
  for (const std::string& p : paths) list += "\"" + p + "\", ";
  list += "]";
  const std::filesystem::path file = dir_ / "case.toml";
  const ResultTables analytic = run(toml::parse(modal(sensitivity_case("[0.01, 3.0]", list))), file);
  const toml::table plain = toml::parse(modal(sensitivity_case("[0.01, 3.0]", "")));
  for (const std::string& path : paths) {
    const CentralDifferences fd(plain, path, file);
    for (const char* level : {"frf_0.01", "frf_3"}) {
      const ResultTable& a = analytic.at(level);
      for (const char* q : {"A.x_amp_m", "A.x_phase_deg"}) {
        const Eigen::VectorXd exact = column(a, std::string(q) + "_dlog_" + path);
        ASSERT_TRUE(exact.allFinite()) << level << " " << q << " " << path;
        const double scale = std::string(q) == "A.x_amp_m" ? column(a, q).cwiseAbs().maxCoeff() : 1.0;
        EXPECT_GT(exact.cwiseAbs().maxCoeff() / scale, 1e-3) << "a column that moves: " << path;
        EXPECT_LT(fd.error(level, q, exact) / scale, q == std::string("A.x_amp_m") ? 1e-6 : 1e-4)
            << level << " " << q << " " << path;
      }
    }
  }
}

// The two-blade reduced model with the rigid underplatform damper of cases/thesis/table11_calibrate_contact.toml
// (three contacts of one law, CF = 300 N), at a slipping (300 N) and a nearly stuck (30 N) level.
std::string damper_case(const std::string& analysis_extra) {
  test::TwoBladeRomCase c;
  c.levels = "[300.0, 30.0]";
  c.range = "[172.0, 188.0]";
  c.step = "0.5";
  c.tolerance = "1e-12";
  c.analysis_extra = analysis_extra;
  return test::two_blade_rom_case_text(c);
}

TEST_F(HbmFrfSensitivity, DamperDlogColumnsAgreeWithCentralDifferencesOfWholeRuns) {
  const std::vector<std::string> paths = {"analysis.damper.kt", "analysis.damper.mu", "analysis.modal_damping"};
  const std::filesystem::path file = dir_ / "case.toml";
  const ResultTables analytic =
      run(toml::parse(
              damper_case(R"(sensitivities = ["analysis.damper.kt", "analysis.damper.mu", "analysis.modal_damping"])")),
          file);
  const toml::table plain = toml::parse(damper_case(""));
  for (const std::string& path : paths) {
    const CentralDifferences fd(plain, path, file);
    for (const char* level : {"frf_300", "frf_30"}) {
      const ResultTable& a = analytic.at(level);
      for (const char* q : {"T2.x_amp_m", "T1.x_phase_deg"}) {
        const bool amplitude = std::string(q).ends_with("_amp_m");
        const Eigen::VectorXd value = column(a, q);
        const Eigen::VectorXd exact = column(a, std::string(q) + "_dlog_" + path);
        ASSERT_TRUE(exact.allFinite()) << level << " " << q << " " << path;
        const double scale = amplitude ? value.cwiseAbs().maxCoeff() : 1.0;
        const double error = fd.error(level, q, exact) / scale;
        std::printf("  %-8s %-15s d/dlog %-22s max |p d/dp| %.3e, max |analytic - FD| %.2e\n", level, q, path.c_str(),
                    exact.cwiseAbs().maxCoeff() / scale, error);
        EXPECT_LT(error, amplitude ? 1e-6 : 1e-4) << level << " " << q << " " << path;  // measured <= 2e-9, 4e-7 deg
      }
    }
  }
}

TEST_F(HbmFrfSensitivity, UnsupportedPathsAreRefusedWithTheirLine) {
  for (const char* bad : {R"(sensitivities = ["analysis.contact.1.kt"])", R"(sensitivities = ["analysis.damper.kt"])",
                          R"(sensitivities = ["analysis.model.mass"])",
                          R"(sensitivities = ["analysis.contact.0.kt", "analysis.contact.0.kt"])"}) {
    const std::filesystem::path file = write(sensitivity_case("[1.0]", bad));
    try {
      (void)parse_case_table(read_case_table(file), file);
      FAIL() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("case.toml:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("sensitivities"), std::string::npos) << e.what();
    }
  }
  std::string rayleigh = sensitivity_case("[1.0]", R"(sensitivities = ["analysis.modal_damping"])");
  rayleigh.replace(rayleigh.find("modal_damping = 0.01"), 20,
                   "rayleigh = { frequency_hz = [100.0, 300.0], zeta = [0.01, 0.01] }");
  const std::filesystem::path file = write(rayleigh);
  EXPECT_THROW((void)parse_case_table(read_case_table(file), file), InputError);
}

TEST_F(HbmFrfSensitivity, FrfPointGradientsInterpolateTheDlogColumnsInSiOverSigma) {
  write("frequency [Hz],amplitude [mm],phase [deg]\n10.5,2.0,10\n", "frf.csv");
  const CalibrationData d = test::frf_block(dir_ / "frf.csv");
  ResultTables tables;
  tables.emplace("frf_1", table_from_rows("frf_1",
                                          {"point", "frequency_hz", "A.x_amp_m", "A.x_phase_deg", "A.x_amp_m_dlog_k",
                                           "A.x_phase_deg_dlog_k"},
                                          {{1, 10.0, 1e-3, 0.0, 2e-3, 30.0}, {2, 11.0, 3e-3, 20.0, 4e-3, 90.0}}));
  const std::vector<FitPoint> p = data_points(d, tables, {"k"});
  ASSERT_EQ(p.size(), 2u);
  ASSERT_EQ(p[0].gradient.size(), 1u);
  EXPECT_NEAR(p[0].gradient[0], 3e-3 / (0.02 * 2e-3), 1e-9);  // halfway, over the amplitude's sigma
  EXPECT_NEAR(p[1].gradient[0], 60.0 * std::numbers::pi / 180.0 / p[1].sigma, 1e-9);  // degrees -> radians
  EXPECT_TRUE(data_points(d, tables, {"k", "other"})[0].gradient.empty());  // a parameter without columns: none
  EXPECT_TRUE(data_points(d, tables)[0].gradient.empty());
}

// The round-trip oscillator: two levels, 0.5 Hz grid.
std::string round_trip_case(double kt, double mu, double zeta, const std::string& data) {
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

// Synthetic FRF data of the round-trip oscillator at the truth, written beside the case; returns
// the [[calibration.data]] blocks.
std::string write_round_trip_data(const std::filesystem::path& dir, unsigned seed) {
  const CaseSpec spec = parse_case_table(toml::parse(round_trip_case(1.5e6, 0.35, 0.01, "")), dir / "truth.toml");
  const AnalysisResults r = run_analysis(spec.analysis, build_model(spec.model));
  SyntheticOptions o;
  o.kind = DataKind::frf;
  o.noise = 0.02;
  o.phase_noise = 0.02;  // rad
  o.outliers = 2;
  o.every = 6;
  o.columns = {
      {"frequency", "frequency_hz", "Hz"}, {"amplitude", "A.x_amp_m", "um"}, {"phase", "A.x_phase_deg", "deg"}};
  std::string blocks;
  for (const char* level : {"0.3", "10"}) {
    o.seed = seed + static_cast<unsigned>(level[0]);  // as FrfRoundTrip
    write_synthetic_data(r.tables.at(std::string("frf_") + level), o, dir / (std::string("frf_") + level + ".csv"));
    blocks += std::string("[[calibration.data]]\nkind = \"frf\"\nfile = \"frf_") + level + ".csv\"\ntable = \"frf_" +
              level +
              "\"\ncolumns = { frequency = \"frequency_hz\", amplitude = \"A.x_amp_m\", phase = \"A.x_phase_deg\" }\n";
  }
  return blocks;
}

// A parameter the analysis does not differentiate takes its column by central differences (named
// with why) beside the exact ones; with none differentiated the whole Jacobian is differences.
TEST_F(HbmFrfSensitivity, AutoTakesCentralDifferencesForTheColumnOfAParameterWithoutSensitivity) {
  const std::string blocks = write_round_trip_data(dir_, 3u);
  write(round_trip_case(5.0e5, 0.8, 0.03, R"([calibration]
parameters = [{ path = "analysis.contact.0.kt", lower = 1.0e5, upper = 1.0e7 },
              { path = "analysis.forces.0.amplitude", lower = 0.5, upper = 2.0 }]
max_iterations = 1
)" + blocks));
  const CalibrationOutcome mixed = calibrate_case(dir_ / "case.toml");
  EXPECT_EQ(mixed.derivatives.rfind("analytic", 0), 0u) << mixed.derivatives;
  EXPECT_NE(mixed.derivatives.find("central differences (relative step 0.0001) for the columns of "
                                   "'analysis.forces.0.amplitude': not differentiated"),
            std::string::npos)
      << mixed.derivatives;
  write(round_trip_case(5.0e5, 0.8, 0.03, R"([calibration]
parameters = [{ path = "analysis.forces.0.amplitude", lower = 0.5, upper = 2.0 }]
max_iterations = 1
)" + blocks));
  const CalibrationOutcome numeric = calibrate_case(dir_ / "case.toml");
  EXPECT_EQ(numeric.derivatives.rfind("central differences", 0), 0u) << numeric.derivatives;
  EXPECT_NE(numeric.derivatives.find("analysis.forces.0.amplitude"), std::string::npos) << numeric.derivatives;
}

class AnalyticRoundTrip : public HbmFrfSensitivity, public ::testing::WithParamInterface<unsigned> {};

TEST_P(AnalyticRoundTrip, RecoversKtMuAndDampingWithFewerEvaluationsThanCentralDifferences) {
  const double truth[] = {1.5e6, 0.35, 0.01};
  const std::string blocks = write_round_trip_data(dir_, GetParam());
  const auto calibration = [](const char* derivatives) {
    return std::string(R"([calibration]
parameters = [{ path = "analysis.contact.0.kt", lower = 1.0e5, upper = 1.0e7 },
              { path = "analysis.contact.0.mu", lower = 0.05, upper = 2.0 },
              { path = "analysis.modal_damping", lower = 0.001, upper = 0.1 }]
loss = "huber"
loss_scale = 2.0
max_iterations = 40
function_tolerance = 1e-6
derivative_step = 1e-2
derivatives = ")") +
           derivatives + "\"\n";
  };
  CalibrationOutcome out[2];
  const char* modes[] = {"auto", "numeric"};
  for (int m = 0; m < 2; ++m) {
    write(round_trip_case(5.0e5, 0.8, 0.03, calibration(modes[m]) + blocks));
    const auto t0 = std::chrono::steady_clock::now();
    out[m] = calibrate_case(dir_ / "case.toml");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  derivatives = %s: %s; %d evaluations, %.2f s, %s\n", modes[m], out[m].derivatives.c_str(),
                out[m].residual_evaluations, seconds, out[m].termination.c_str());
    for (size_t i = 0; i < 3; ++i)
      std::printf("    %s: identified %.6g +- %.3g, truth %.6g (%.2f sigma)\n", out[m].spec.parameters[i].path.c_str(),
                  out[m].values[i], out[m].std_devs[i], truth[i],
                  std::abs(out[m].values[i] - truth[i]) / out[m].std_devs[i]);
  }
  EXPECT_EQ(out[0].derivatives.rfind("analytic", 0), 0u) << out[0].derivatives;
  EXPECT_EQ(out[1].derivatives.rfind("central differences", 0), 0u) << out[1].derivatives;
  ASSERT_TRUE(out[0].converged) << out[0].termination;
  for (size_t i = 0; i < 3; ++i) {
    ASSERT_TRUE(std::isfinite(out[0].std_devs[i]));
    EXPECT_LT(std::abs(out[0].values[i] - truth[i]), 2 * out[0].std_devs[i]) << out[0].spec.parameters[i].path;
  }
  EXPECT_LT(out[0].residual_evaluations, out[1].residual_evaluations);
}

INSTANTIATE_TEST_SUITE_P(NoiseDraws, AnalyticRoundTrip, ::testing::Values(3u, 8u));

}  // namespace
}  // namespace bb
