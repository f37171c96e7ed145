// How the peaks move with the parameters (forced/hbm_peak_sensitivity.hpp): the peaks table's
// _dlog_ columns.
//   - A stuck contact makes the friction oscillator linear: its peak frequency and amplitude and
//     their derivatives in kt and the damping have closed forms, which the columns meet to 1e-6.
//   - On the two-blade model with the damper (slipping at 300 N) they agree with central
//     differences of whole runs.
//   - A calibration against peaks then takes its Jacobian from them: one run per evaluation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "temp_folder.hpp"
#include "two_blade_rom_case.hpp"

namespace bb {
namespace {

class HbmPeakSensitivity : public test::TempFolderTest {};

ResultTables run(const std::string& text, const std::filesystem::path& file) {
  const CaseSpec spec = parse_case_table(toml::parse(text), file);
  return run_analysis(spec.analysis, build_model(spec.model)).tables;
}

double cell(const ResultTable& t, const std::string& column, Eigen::Index row = 0) {
  const auto c = t.column_index(column);
  if (!c) throw std::out_of_range("no column " + column + " in " + t.name);
  return t.values(row, *c);
}

TEST_F(HbmPeakSensitivity, AStuckOscillatorMeetsTheClosedFormsOfALinearPeak) {
  test::OscillatorCase c;
  c.levels = "[0.01]";  // 3.5e-7 m at the peak: far inside the 9e-6 m the contact holds
  c.range = "[200.0, 250.0]";
  c.step = "0.5";
  c.tolerance = "1e-12";
  c.analysis_extra = R"(sensitivities = ["analysis.contact.0.kt", "analysis.contact.0.mu", "analysis.modal_damping"])";
  const ResultTable peaks = run(test::oscillator_case_text(c), dir_ / "case.toml").at("peaks");
  // m x'' + c x' + (k + kt) x = F cos(w t), c = 2 zeta sqrt(k m) (modal damping of the model without
  // the contact): |x| peaks at w*^2 = K / m - c^2 / (2 m^2) with |x|* = F / (c sqrt(K / m - c^2 / (4 m^2))).
  const double m = 1.0, k = 1e6, kt = 1e6, zeta = 0.01, f = 0.01, K = k + kt, cv = 2 * zeta * std::sqrt(k * m);
  const double w2 = K / m - cv * cv / (2 * m * m), w = std::sqrt(w2), q = K / m - cv * cv / (4 * m * m);
  const double amp = f / (cv * std::sqrt(q));
  // d/dlog kt: d(w2) = kt / m, d(q) = kt / m; d/dlog zeta: d(w2) = -c^2 / m^2, d(q) = -c^2 / (2 m^2).
  const double dw_kt = kt / m / (2 * w), dw_zeta = -cv * cv / (m * m) / (2 * w);
  const double damp_kt = -amp * (kt / m) / (2 * q), damp_zeta = -amp * (1.0 + (-cv * cv / (2 * m * m)) / (2 * q));
  constexpr double two_pi = 2 * std::numbers::pi;
  EXPECT_NEAR(cell(peaks, "peak_hz"), w / two_pi, 1e-7 * w / two_pi);
  const std::string p_kt = "_dlog_analysis.contact.0.kt", p_mu = "_dlog_analysis.contact.0.mu",
                    p_zeta = "_dlog_analysis.modal_damping";
  EXPECT_NEAR(cell(peaks, "peak_hz" + p_kt), dw_kt / two_pi, 1e-6 * dw_kt / two_pi);
  EXPECT_NEAR(cell(peaks, "peak_hz" + p_zeta), dw_zeta / two_pi, 1e-4 * std::abs(dw_zeta) / two_pi);
  EXPECT_NEAR(cell(peaks, "peak_amp_m" + p_kt), damp_kt, 1e-6 * std::abs(damp_kt));
  EXPECT_NEAR(cell(peaks, "peak_amp_m" + p_zeta), damp_zeta, 1e-6 * std::abs(damp_zeta));
  EXPECT_NEAR(cell(peaks, "peak_amp_per_n" + p_kt), damp_kt / f, 1e-6 * std::abs(damp_kt / f));
  EXPECT_EQ(cell(peaks, "peak_hz" + p_mu), 0.0);  // a stuck contact does not feel mu
  EXPECT_EQ(cell(peaks, "peak_amp_m" + p_mu), 0.0);
}

TEST_F(HbmPeakSensitivity, DamperPeaksMoveAsCentralDifferencesOfWholeRunsSay) {
  const auto text = [](const std::string& kt, const std::string& mu, const std::string& extra) {
    test::TwoBladeRomCase c;
    c.kt = kt;
    c.mu = mu;
    c.levels = "[300.0]";
    c.range = "[172.0, 180.0]";
    c.step = "0.1";
    c.ip_oop = true;
    c.tolerance = "1e-12";
    c.analysis_extra = extra;
    return test::two_blade_rom_case_text(c);
  };
  const std::filesystem::path file = dir_ / "case.toml";
  const ResultTable exact =
      run(text("8.09e7", "0.7231", R"(sensitivities = ["analysis.damper.kt", "analysis.damper.mu"])"), file)
          .at("peaks");
  // A peak is found to 1e-7 of its frequency by golden section, which is the differences' noise:
  // 2e-5 Hz / 2h. Steps of 1e-3 (noise 9e-3 Hz) and 1e-2 (truncation) bracket the derivative.
  for (const double h : {1e-3, 1e-2}) {
    const double e = std::exp(h);
    const ResultTable kt_up = run(text(std::to_string(8.09e7 * e), "0.7231", ""), file).at("peaks");
    const ResultTable kt_down = run(text(std::to_string(8.09e7 / e), "0.7231", ""), file).at("peaks");
    const ResultTable mu_up = run(text("8.09e7", std::to_string(0.7231 * e), ""), file).at("peaks");
    const ResultTable mu_down = run(text("8.09e7", std::to_string(0.7231 / e), ""), file).at("peaks");
    for (const char* q : {"ip_hz", "oop_hz", "ip_amp_m", "oop_amp_m"}) {
      const bool hz = std::string(q).ends_with("_hz");
      const double fd_kt = (cell(kt_up, q) - cell(kt_down, q)) / (2 * h);
      const double fd_mu = (cell(mu_up, q) - cell(mu_down, q)) / (2 * h);
      const double a_kt = cell(exact, std::string(q) + "_dlog_analysis.damper.kt");
      const double a_mu = cell(exact, std::string(q) + "_dlog_analysis.damper.mu");
      // Hertz: the noise above (measured within 2.1e-3 Hz); amplitudes: 3e-3 of the derivative
      // (measured within 1.6e-3: the amplitude is read at the peak of the component, where it
      // still slopes, so the peak's placement noise shows in it too).
      const double tol_kt = hz ? 0.01 : 3e-3 * std::abs(a_kt), tol_mu = hz ? 0.01 : 3e-3 * std::abs(a_mu);
      std::printf("  h %.0e %-9s kt: exact %+.6e FD %+.6e   mu: exact %+.6e FD %+.6e\n", h, q, a_kt, fd_kt, a_mu,
                  fd_mu);
      EXPECT_NEAR(a_kt, fd_kt, tol_kt) << q;
      EXPECT_NEAR(a_mu, fd_mu, tol_mu) << q;
    }
  }
}

}  // namespace
}  // namespace bb
