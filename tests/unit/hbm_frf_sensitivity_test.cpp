// Sensitivity columns of the hbm FRF tables (analysis key `sensitivities`, hbm/sensitivity.hpp)
// and the calibration that uses them as its Jacobian ([calibration] derivatives = "auto").
//   - The dlog columns of the 1-DOF friction oscillator (cases/verification/friction_oscillator_hbm.toml
//     in a shorter band) agree with central differences of whole re-runs of the case, at a stuck
//     (0.01 N) and a stick-slip (3 N) level.
//   - Paths the derivative does not cover are refused with file:line.
//   - The FRF round trip of curve_identification_test.cpp (same data, seeds and start values)
//     fitted with analytic derivatives recovers kt, mu and zeta within 2 sigma with fewer model
//     evaluations than central differences.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/case_results.hpp"
#include "common/errors.hpp"
#include "identify/calibrate_case.hpp"
#include "identify/synthetic_data.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

class HbmFrfSensitivity : public test::TempFolderTest {};

std::string oscillator_case(const std::string& levels, const std::string& extra) {
  return R"([case]
name = "frf_sensitivity"
[analysis]
type = "hbm"
frequency_hz = [150.0, 240.0]
step_hz = 1.0
harmonics = 1
time_samples = 256
tolerance = 1e-12
modal_damping = 0.01
forces = [{ dof = "A.x", amplitude = 1.0 }]
force_levels = )" + levels + R"(
responses = ["A.x"]
)" + extra + R"(
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
)";
}

Eigen::VectorXd column(const ResultTable& t, const std::string& name) {
  const auto c = t.column_index(name);
  if (!c) throw std::out_of_range("no column " + name + " in " + t.name);
  return t.values.col(*c);
}

ResultTables run(const toml::table& t, const std::filesystem::path& file) {
  const CaseSpec spec = parse_case_table(t, file);
  return compute_case_results(spec, build_model(spec)).tables;
}

TEST_F(HbmFrfSensitivity, DlogColumnsAgreeWithCentralDifferencesOfWholeRuns) {
  const std::vector<std::string> paths = {"analysis.contact.0.kt", "analysis.contact.0.mu", "analysis.contact.0.n0",
                                          "analysis.modal_damping"};
  const std::string list = R"(sensitivities = ["analysis.contact.0.kt", "analysis.contact.0.mu", "analysis.contact.0.n0", "analysis.modal_damping"])";
  const std::filesystem::path file = dir_ / "case.toml";
  const ResultTables analytic = run(toml::parse(oscillator_case("[0.01, 3.0]", list)), file);
  const toml::table plain = toml::parse(oscillator_case("[0.01, 3.0]", ""));
  // Step in log p: truncation h^2 ~ 1e-8 relative, solver noise 1e-12 / h ~ 1e-8.
  const double h = 1e-4;
  for (const std::string& path : paths) {
    toml::table up = plain, down = plain;
    const double p = node_at_path(up, path)->value<double>().value();
    *node_at_path(up, path)->as_floating_point() = p * std::exp(h);
    *node_at_path(down, path)->as_floating_point() = p * std::exp(-h);
    const ResultTables tu = run(up, file), td = run(down, file);
    for (const char* level : {"frf_0.01", "frf_3"}) {
      const ResultTable& a = analytic.at(level);
      for (const char* q : {"A.x_amp_m", "A.x_phase_deg"}) {
        const Eigen::VectorXd value = column(a, q);
        const Eigen::VectorXd exact = column(a, std::string(q) + "_dlog_" + path);
        Eigen::VectorXd fd = column(tu.at(level), q) - column(td.at(level), q);
        if (std::string(q) == "A.x_phase_deg") fd = fd.unaryExpr([](double d) { return std::remainder(d, 360.0); });
        fd /= 2 * h;
        ASSERT_EQ(exact.size(), fd.size());
        ASSERT_TRUE(exact.allFinite()) << level << " " << q << " " << path;
        // Relative to the column's scale: |z| itself for the amplitude, one degree for the phase.
        const double scale = std::string(q) == "A.x_amp_m" ? value.cwiseAbs().maxCoeff() : 1.0;
        const double error = (exact - fd).cwiseAbs().maxCoeff() / scale;
        std::printf("  %-9s %-14s d/dlog %-22s max |p d/dp| %.3e, max |analytic - FD| %.2e (relative to %s)\n", level, q, path.c_str(),
                    exact.cwiseAbs().maxCoeff() / scale, error, std::string(q) == "A.x_amp_m" ? "max |z|" : "1 deg");
        // Stuck: linear, exact to the FD's own error. Stick-slip: a sample of the 256-point AFT that
        // changes state inside the +-h step makes the FD itself wrong by O(1 / 256) of that sample's force.
        EXPECT_LT(error, std::string(level) == "frf_0.01" ? 1e-6 : 2e-4) << level << " " << q << " " << path;
      }
    }
  }
}

TEST_F(HbmFrfSensitivity, UnsupportedPathsAreRefusedWithTheirLine) {
  for (const char* bad : {R"(sensitivities = ["analysis.contact.1.kt"])", R"(sensitivities = ["analysis.damper.kt"])",
                          R"(sensitivities = ["analysis.model.mass"])", R"(sensitivities = ["analysis.contact.0.kt", "analysis.contact.0.kt"])"}) {
    const std::filesystem::path file = write(oscillator_case("[1.0]", bad));
    try {
      (void)parse_case_table(read_case_table(file), file);
      FAIL() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("case.toml:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("sensitivities"), std::string::npos) << e.what();
    }
  }
  std::string rayleigh = oscillator_case("[1.0]", R"(sensitivities = ["analysis.modal_damping"])");
  rayleigh.replace(rayleigh.find("modal_damping = 0.01"), 20, "rayleigh = { frequency_hz = [100.0, 300.0], zeta = [0.01, 0.01] }");
  const std::filesystem::path file = write(rayleigh);
  EXPECT_THROW((void)parse_case_table(read_case_table(file), file), InputError);
}

// The case of curve_identification_test.cpp's FrfRoundTrip.
std::string round_trip_case(double kt, double mu, double zeta, const std::string& data) {
  return R"([case]
name = "frf_identification"
[analysis]
type = "hbm"
frequency_hz = [150.0, 240.0]
step_hz = 0.5
harmonics = 1
time_samples = 128
modal_damping = )" + std::to_string(zeta) + R"(
forces = [{ dof = "A.x", amplitude = 1.0 }]
force_levels = [0.3, 10.0]
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
kt = )" + std::to_string(kt) + R"(
mu = )" + std::to_string(mu) + R"(
n0 = 30.0
)" + data;
}

TEST_F(HbmFrfSensitivity, AnalyticJacobianRecoversKtMuAndDampingWithFewerEvaluations) {
  const double truth[] = {1.5e6, 0.35, 0.01};
  const CaseSpec spec = parse_case_table(toml::parse(round_trip_case(truth[0], truth[1], truth[2], "")), dir_ / "truth.toml");
  const CaseResults r = compute_case_results(spec, build_model(spec));
  SyntheticOptions o;
  o.kind = DataKind::frf;
  o.noise = 0.02;
  o.phase_noise = 0.02;  // rad
  o.outliers = 2;
  o.every = 6;
  o.columns = {{"frequency", "frequency_hz", "Hz"}, {"amplitude", "A.x_amp_m", "um"}, {"phase", "A.x_phase_deg", "deg"}};
  std::string blocks;
  for (const char* level : {"0.3", "10"}) {
    o.seed = 3u + static_cast<unsigned>(level[0]);  // FrfRoundTrip's first draw
    write_synthetic_data(r.tables.at(std::string("frf_") + level), o, dir_ / (std::string("frf_") + level + ".csv"));
    blocks += std::string("[[calibration.data]]\nkind = \"frf\"\nfile = \"frf_") + level + ".csv\"\ntable = \"frf_" + level +
              "\"\ncolumns = { frequency = \"frequency_hz\", amplitude = \"A.x_amp_m\", phase = \"A.x_phase_deg\" }\n";
  }
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
derivatives = ")") + derivatives + "\"\n";
  };
  CalibrationOutcome out[2];
  const char* modes[] = {"auto", "numeric"};
  for (int m = 0; m < 2; ++m) {
    write(round_trip_case(5.0e5, 0.8, 0.03, calibration(modes[m]) + blocks));
    const auto t0 = std::chrono::steady_clock::now();
    out[m] = calibrate_case(dir_ / "case.toml", false);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  derivatives = %s: %s; %d evaluations, %.2f s, %s\n", modes[m], out[m].derivatives.c_str(), out[m].residual_evaluations,
                seconds, out[m].termination.c_str());
    for (size_t i = 0; i < 3; ++i)
      std::printf("    %s: identified %.6g +- %.3g, truth %.6g (%.2f sigma)\n", out[m].spec.parameters[i].path.c_str(), out[m].values[i],
                  out[m].std_devs[i], truth[i], std::abs(out[m].values[i] - truth[i]) / out[m].std_devs[i]);
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

}  // namespace
}  // namespace bb
