// Stepped sines at a force per point (forced/hbm_stepped_sine.hpp) through the case pipeline: the
// stuck oscillator at drifting forces against its closed form, a stepped sine at one force against
// the level sweep at the same frequencies, up against down where the response is unique, and the
// fit of data measured at a force per point (identify/fit_points.hpp). Units: SI.
#include "forced/hbm_stepped_sine.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "analysis/hbm_analysis.hpp"
#include "cases/case_spec.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "identify/fit_points.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "pipeline/calibrate_case.hpp"
#include "pipeline/run_case.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

class HbmSteppedSineTest : public test::TempFolderTest {
 protected:
  HbmOutcome run(const test::OscillatorCase& c) {
    const CaseSpec spec = parse_case_file(write(test::oscillator_case_text(c)));
    return run_hbm(build_model(spec.model), std::get<HbmSpec>(spec.analysis));
  }
  static double column(const ResultTable& t, const std::string& name, Eigen::Index row) {
    const std::optional<int> c = t.column_index(name);
    if (!c) throw std::runtime_error("no column " + name);
    return t.values(row, *c);
  }
};

TEST_F(HbmSteppedSineTest, StuckOscillatorAtADriftingForceIsTheClosedFormAtEachPointsForce) {
  // 0.005-0.02 N move the contact far below mu n0 / kt = 9e-6 m: a linear oscillator with
  // k + kt = 2e6 N/m and c = 2 zeta sqrt(k m) = 20 N s/m, so |x| = F_i / |k + kt - w^2 + i w c|.
  test::OscillatorCase c;
  c.tolerance = "1e-12";
  c.levels = "[0.01]";
  c.analysis_extra =
      "[[analysis.stepped_sine]]\nname = \"down\"\nfrequency_hz = [230.0, 226.0, 225.0, 224.0, 210.0]\n"
      "force = [0.02, 0.015, 0.005, 0.01, 0.012]\n";
  const HbmOutcome o = run(c);
  ASSERT_EQ(o.stepped_sines.size(), 1u);
  const HbmSteppedSine& s = o.stepped_sines[0];
  ASSERT_EQ(s.frequency_hz.size(), 5u);
  EXPECT_TRUE(s.failed_hz.empty());
  const ResultTable& t = o.tables.at("frf_down");
  for (Eigen::Index i = 0; i < 5; ++i) {
    const double f = column(t, "frequency_hz", i), force = column(t, "force_n", i), w = kTwoPi * f;
    const std::complex<double> x = force / std::complex<double>(2.0e6 - w * w, w * 20.0);
    EXPECT_NEAR(column(t, "A.x_amp_m", i) / std::abs(x) - 1.0, 0.0, 1e-9) << f << " Hz";
    EXPECT_NEAR(column(t, "A.x_phase_deg", i), std::arg(x) * 180.0 / std::numbers::pi, 1e-7) << f << " Hz";
    EXPECT_EQ(column(t, "point", i), static_cast<double>(i + 1));
  }
  EXPECT_DOUBLE_EQ(column(t, "frequency_hz", 0), 230.0);  // in the order stepped
  EXPECT_DOUBLE_EQ(column(t, "force_n", 2), 0.005);
  EXPECT_EQ(o.tables.at("stepped_sine_cost").values(0, 2), 0.0);  // failed points
}

TEST_F(HbmSteppedSineTest, OneForceUpOrDownIsTheLevelSweepAtTheSameFrequencies) {
  // Stick-slip at 3 N (the response is unique here): a grid sweep of the level, a stepped sine up
  // and one down on every fourth grid frequency; the three meet to the Newton tolerance.
  test::OscillatorCase c;
  c.tolerance = "1e-12";
  c.levels = "[3.0]";
  c.range = "[180.0, 240.0]";
  c.step = "0.5";
  std::string up, down;
  for (int k = 0; k <= 120; k += 4) up += fmt::format("{}{}", up.empty() ? "" : ", ", 180.0 + 0.5 * k);
  for (int k = 120; k >= 0; k -= 4) down += fmt::format("{}{}", down.empty() ? "" : ", ", 180.0 + 0.5 * k);
  c.analysis_extra = "[[analysis.stepped_sine]]\nname = \"up\"\nfrequency_hz = [" + up +
                     "]\nforce = 3.0\n[[analysis.stepped_sine]]\nname = \"down\"\nfrequency_hz = [" + down +
                     "]\nforce = 3.0\n";
  const HbmOutcome o = run(c);
  const ResultTable& level = o.tables.at("frf_3");
  const ResultTable& u = o.tables.at("frf_up");
  const ResultTable& d = o.tables.at("frf_down");
  ASSERT_EQ(u.values.rows(), 31);
  ASSERT_EQ(d.values.rows(), 31);
  for (Eigen::Index i = 0; i < 31; ++i) {
    const Eigen::Index row = 4 * i, back = 30 - i;
    ASSERT_DOUBLE_EQ(column(level, "frequency_hz", row), column(u, "frequency_hz", i));
    ASSERT_DOUBLE_EQ(column(u, "frequency_hz", i), column(d, "frequency_hz", back));
    const double a = column(level, "A.x_amp_m", row);
    EXPECT_NEAR(column(u, "A.x_amp_m", i) / a - 1.0, 0.0, 1e-8) << column(u, "frequency_hz", i) << " Hz";
    EXPECT_NEAR(column(d, "A.x_amp_m", back) / a - 1.0, 0.0, 1e-8) << column(u, "frequency_hz", i) << " Hz";
  }
}

TEST_F(HbmSteppedSineTest, SensitivitiesOfAPointAreThoseOfTheLevelAtTheSameFrequencyAndForce) {
  test::OscillatorCase c;
  c.tolerance = "1e-12";
  c.levels = "[3.0]";
  c.range = "[200.0, 220.0]";
  c.step = "1.0";
  c.analysis_extra =
      "sensitivities = [\"analysis.contact.0.kt\", \"analysis.contact.0.mu\", \"analysis.modal_damping\"]\n"
      "[[analysis.stepped_sine]]\nname = \"s\"\nfrequency_hz = [205.0, 210.0, 215.0]\nforce = 3.0\n";
  const HbmOutcome o = run(c);
  const ResultTable& level = o.tables.at("frf_3");
  const ResultTable& s = o.tables.at("frf_s");
  for (const char* p : {"analysis.contact.0.kt", "analysis.contact.0.mu", "analysis.modal_damping"})
    for (Eigen::Index i = 0; i < 3; ++i) {
      const std::string col = std::string("A.x_amp_m_dlog_") + p;
      const double expected = column(level, col, 5 + 5 * i);
      EXPECT_NEAR(column(s, col, i), expected, 1e-6 * std::abs(expected) + 1e-15) << p;
    }
}

TEST_F(HbmSteppedSineTest, StepsThatAreNotOneSweepOrNameATableTwiceAreRefusedWithTheKey) {
  const auto refusal = [&](const std::string& extra) {
    test::OscillatorCase c;
    c.levels = "[3.0]";
    c.analysis_extra = extra;
    try {
      parse_case_file(write(test::oscillator_case_text(c)));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(refusal("[[analysis.stepped_sine]]\nname = \"a\"\nfrequency_hz = [200.0, 210.0, 205.0]\nforce = 1.0\n")
                .find("frequency 205 Hz (entry 3) is not above the one before (210 Hz)"),
            std::string::npos);
  EXPECT_NE(refusal("[[analysis.stepped_sine]]\nname = \"a\"\nfrequency_hz = [200.0, 210.0]\nforce = [1.0]\n")
                .find("1 forces for 2 frequencies"),
            std::string::npos);
  EXPECT_NE(refusal("[[analysis.stepped_sine]]\nname = \"a\"\nfrequency_hz = [200.0]\nforce = -1.0\n")
                .find("every force must be positive"),
            std::string::npos);
  EXPECT_NE(refusal("[[analysis.stepped_sine]]\nname = \"3\"\nfrequency_hz = [200.0]\nforce = 1.0\n")
                .find("table 'frf_3' is already written"),
            std::string::npos);
  EXPECT_NE(refusal("[[analysis.stepped_sine]]\nname = \"a b\"\nfrequency_hz = [200.0]\nforce = 1.0\n")
                .find("use letters, digits"),
            std::string::npos);
}

// Data measured at a force per point, fitted against a stepped sine down: the interpolation runs
// on the reversed table, and a table solved at other forces is refused.
TEST_F(HbmSteppedSineTest, DataWithAForcePerPointAreComparedWithTheStepAtThatForce) {
  ResultTable t = table_from_rows("frf_down", {"point", "frequency_hz", "force_n", "A.x_amp_m"},
                                  {{1, 230.0, 0.2, 3e-6}, {2, 220.0, 0.25, 5e-6}, {3, 210.0, 0.3, 4e-6}});
  ResultTables tables;
  tables.emplace("frf_down", t);
  const std::filesystem::path file = write(
      "frequency [Hz], amplitude [m], force [N]\n230, 3.1e-6, 0.2\n"
      "215, 4.4e-6, 0.27\n210, 4e-6, 0.3\n",
      "down.csv");
  CalibrationData d;
  d.name = "down";
  d.table = "frf_down";
  d.data = read_measured_data(file, DataKind::frf);
  d.columns = {{"frequency", "frequency_hz"}, {"amplitude", "A.x_amp_m"}, {"force", "force_n"}};
  const std::vector<FitPoint> points = data_points(d, tables);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_DOUBLE_EQ(points[0].computed, 3e-6);
  EXPECT_NEAR(points[1].computed, 4.5e-6, 1e-18);  // between 220 and 210 Hz
  EXPECT_DOUBLE_EQ(points[2].computed, 4e-6);
  tables.at("frf_down").values(2, 2) = 0.31;  // the table solved 210 Hz at another force
  try {
    data_points(d, tables);
    FAIL() << "a table at other forces was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("measured at 0.3 N, but table 'frf_down' solved 210 Hz at 0.31 N"),
              std::string::npos)
        << e.what();
  }
}

// A response-controlled curve measured the force: against a table with held_m the force and the
// phase are fitted, with the force's own sigma, and the held amplitude is not.
TEST_F(HbmSteppedSineTest, AResponseControlledCurveFitsTheForceThatHeldTheAmplitude) {
  ResultTable t =
      table_from_rows("frf_rc", {"point", "frequency_hz", "force_n", "held_m", "A.x_amp_m", "A.x_phase_deg"},
                      {{1, 78.0, 0.30, 1e-4, 1e-4, -60.0}, {2, 79.0, 0.20, 1e-4, 1e-4, -90.0}});
  ResultTables tables;
  tables.emplace("frf_rc", t);
  CalibrationData d;
  d.name = "rc";
  d.table = "frf_rc";
  d.data = read_measured_data(write("frequency [Hz], amplitude [m], phase [deg], force [N], force_sigma [N]\n"
                                    "78.5, 1e-4, -80, 0.27, 0.01\n",
                                    "rc.csv"),
                              DataKind::frf);
  d.columns = {
      {"frequency", "frequency_hz"}, {"amplitude", "A.x_amp_m"}, {"phase", "A.x_phase_deg"}, {"force", "force_n"}};
  const std::vector<FitPoint> points = data_points(d, tables);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].quantity, "force");
  EXPECT_NEAR(points[0].computed, 0.25, 1e-15);
  EXPECT_DOUBLE_EQ(points[0].measured, 0.27);
  EXPECT_DOUBLE_EQ(points[0].sigma, 0.01);
  EXPECT_EQ(points[1].quantity, "phase");
  EXPECT_NEAR(points[1].computed, -75.0 * std::numbers::pi / 180.0, 1e-12);
}

// The committed rig case (cases/verification/rig_force_controlled_identify.toml) with its data
// read from the source tree, one start and no cross-check (ctest's
// calibrate.verification.rig_force_controlled_identify runs those); `parameters` replaces its list.
std::string rig_case(const std::string& parameters = {}) {
  const std::filesystem::path cases = std::filesystem::path(BB_SOURCE_DIR) / "cases" / "verification";
  std::ifstream in(cases / "rig_force_controlled_identify.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(text.empty());
  const std::string folder = cases.generic_string() + "/";
  for (std::string::size_type at = 0; (at = text.find("\"data/rig/", at)) != std::string::npos;)
    text.insert(at + 1, folder), at += folder.size() + 10;
  text.replace(text.find("starts = 3"), 10, "starts = 1");
  const auto line = [&](const std::string& key) {
    const auto at = text.find(key);
    return std::pair{at, text.find('\n', at) - at};
  };
  const auto [cross, cross_n] = line("cross_check");
  text.erase(cross, cross_n);
  if (!parameters.empty()) {
    const auto at = text.find("parameters = [");
    text.replace(at, text.find("]\n", text.find("},\n]", at)) + 1 - at, parameters);
  }
  return text;
}

// The truth of the rig's synthetic data (data/rig/rig_joint_truth.toml) comes back within two
// standard deviations when each point is solved at the force the shaker held there.
TEST_F(HbmSteppedSineTest, RigJointComesBackFromCurvesWithDriftingForce) {
  const CalibrationOutcome o = calibrate_case(write(rig_case()));
  ASSERT_TRUE(o.converged) << o.termination;
  const double truth[] = {5.0e3, 0.5, 0.0015, 2.4e5, 1.0};
  ASSERT_EQ(o.values.size(), 5u);
  for (size_t i = 0; i < 5; ++i) {
    std::printf("  %s: identified %.6g +- %.3g, truth %.6g (%.2f sigma)\n", o.spec.parameters[i].path.c_str(),
                o.values[i], o.std_devs[i], truth[i], std::abs(o.values[i] - truth[i]) / o.std_devs[i]);
    ASSERT_TRUE(std::isfinite(o.std_devs[i]) && o.std_devs[i] > 0.0);
    EXPECT_LT(std::abs(o.values[i] - truth[i]), 2 * o.std_devs[i]);
  }
  // The held-out response-controlled curves are predicted, not fitted: their points are reported
  // apart, and at the identified values their forces lie within the data's noise (2 %, 1 sigma).
  size_t held = 0;
  for (const FitPoint& p : o.after) {
    if (!p.held_out) continue;
    ++held;
    if (p.quantity == "force") {
      EXPECT_LT(std::abs(p.residual()), 5.0) << p.set << " " << p.label;
    }
  }
  EXPECT_EQ(held, 8u * 61u * 2u);  // force and phase
}

// A stated prior holds a parameter near what is known of it: a tight prior away from the truth
// wins over the data, and the standard deviation is at most the prior's (scaled as every one is).
TEST_F(HbmSteppedSineTest, ATightPriorHoldsItsParameterAndBoundsItsSpread) {
  const CalibrationOutcome o = calibrate_case(write(rig_case(
      "parameters = [\n  { path = \"analysis.contact.0.kt\", lower = 1.0e3, upper = 1.0e5 },\n"
      "  { path = \"analysis.contact.0.mu\", lower = 0.05, upper = 2.0, prior = { value = 0.45, sigma = 1.0e-4 } },\n"
      "  { path = \"analysis.modal_damping\", lower = 1.0e-4, upper = 0.02 },\n]")));
  ASSERT_TRUE(o.converged) << o.termination;
  EXPECT_NEAR(o.values[1], 0.45, 5e-4);  // 0.5 by the data alone, 0.0052 apart
  // (the standard deviations are scaled by sqrt(reduced chi-square) when that exceeds 1)
  EXPECT_LE(o.std_devs[1], 1.0e-4 * std::max(1.0, std::sqrt(o.reduced_chi_square)) * 1.0001);
  EXPECT_TRUE(std::any_of(o.after.begin(), o.after.end(), [](const FitPoint& p) { return p.set == "priors"; }));
}

}  // namespace
}  // namespace bb
