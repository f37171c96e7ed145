// The harmonic balance with a response held and the force unknown (hbm/response_control.hpp): a
// stuck oscillator against F = A (k - m w^2 + i c w), and round trips against the force-controlled
// solve where the contact sticks and slips, with the held DOF on the contact and away from it.
// Units: SI.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <utility>

#include "analysis/hbm_analysis.hpp"
#include "cases/case_spec.hpp"
#include "common/constants.hpp"
#include "friction_oscillator.hpp"
#include "hbm/response_control.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "pipeline/run_case.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

using Complex = std::complex<double>;

hbm::HarmonicBalance unit_system(friction::FrictionModel m, int harmonics = 1) {
  m.harmonic_load = Eigen::VectorXcd::Constant(m.mass.rows(), 0.0);
  m.harmonic_load[0] = 1.0;  // the first force, 1 N
  hbm::HbmOptions o;
  o.harmonics = harmonics;
  o.tolerance = 1e-12;
  o.aft.resolve_events = true;
  return hbm::HarmonicBalance(std::move(m), o);
}

test::FrictionOscillator oscillator(double mu) {
  test::FrictionOscillator o;
  o.mass = 1.0;
  o.damping = 20.0;
  o.stiffness = 1.0e6;
  o.force = 1.0;
  o.contact = {.kn = 1.0e6, .kt = 1.0e6, .mu = mu, .n0 = 30.0};
  return o;
}

TEST(ResponseControl, StuckOscillatorNeedsTheForceOfItsDynamicStiffness) {
  // mu = 100: the contact never slips; x = A cos(w t) needs F = A (k + kt - m w^2 + i c w).
  const hbm::HarmonicBalance s = unit_system(oscillator(100.0).model());
  for (double hz : {150.0, 225.0, 260.0}) {
    const double w = kTwoPi * hz, a = 2e-5;
    const hbm::ControlledSolution c = hbm::solve_controlled(s, w, {0, a});
    ASSERT_TRUE(c.solution.converged) << c.solution.failure;
    const Complex expected = a * Complex(2.0e6 - w * w, 20.0 * w);
    EXPECT_NEAR(std::abs(c.force - expected) / std::abs(expected), 0.0, 1e-9) << hz << " Hz";
    EXPECT_NEAR(std::hypot(c.solution.x[1], c.solution.x[2]), a, 1e-15);
    EXPECT_NEAR(c.solution.x[2], 0.0, 1e-18);  // phase 0: b_1 = 0
  }
}

// Force-controlled at F, then held at the amplitude it gave: the force comes back, its phase the
// opposite of the response's (the response is the clock).
void expect_round_trip(const friction::FrictionModel& model, Eigen::Index held, int harmonics, double force,
                       double hz) {
  friction::FrictionModel driven = model;
  driven.harmonic_load = Eigen::VectorXcd::Zero(model.mass.rows());
  driven.harmonic_load[0] = force;
  hbm::HbmOptions o;
  o.harmonics = harmonics;
  o.tolerance = 1e-12;
  o.aft.resolve_events = true;
  const hbm::HarmonicBalance fc(driven, o);
  const double w = kTwoPi * hz;
  const hbm::HbmSolution sol = hbm::solve_at_frequency(fc, w);
  ASSERT_TRUE(sol.converged) << sol.failure;
  const Eigen::MatrixXd q = fc.recover(sol.x, w);
  const Complex z(q(held, 1), -q(held, 2));
  const hbm::HarmonicBalance s = unit_system(model, harmonics);
  const hbm::ControlledSolution c = hbm::solve_controlled(s, w, {held, std::abs(z)});
  ASSERT_TRUE(c.solution.converged) << c.solution.failure;
  EXPECT_NEAR(std::abs(c.force) / force - 1.0, 0.0, 1e-8) << hz << " Hz";
  EXPECT_NEAR(std::arg(c.force), -std::arg(z), 1e-8) << hz << " Hz";
  // The held DOF's first harmonic is the asked amplitude at phase 0, recovered like any other.
  const Eigen::MatrixXd qc = [&] {
    friction::FrictionModel m = model;
    m.harmonic_load = Eigen::VectorXcd::Zero(model.mass.rows());
    m.harmonic_load[0] = c.force;
    return hbm::HarmonicBalance(m, o).recover(c.solution.x, w);
  }();
  EXPECT_NEAR(qc(held, 1), std::abs(z), 1e-10 * std::abs(z));
  EXPECT_NEAR(qc(held, 2), 0.0, 1e-10 * std::abs(z));
}

TEST(ResponseControl, StickSlipOscillatorGivesBackTheForceThatMadeTheResponse) {
  // 3 N: the contact sticks and slips over the cycle (slip limit mu n0 = 9 N against kt x ~ 1e1 N).
  for (double hz : {180.0, 200.0, 215.0, 240.0}) expect_round_trip(oscillator(0.3).model(), 0, 1, 3.0, hz);
  expect_round_trip(oscillator(0.3).model(), 0, 5, 3.0, 205.0);
}

TEST(ResponseControl, HeldDofAwayFromTheContactIsRecoveredFromTheContactDofs) {
  // Two masses: A on the ground by k and the contact, B on A by a spring; forced on A, B held.
  friction::FrictionModel m;
  m.mass = Eigen::Matrix2d::Identity();
  m.stiffness = (Eigen::Matrix2d() << 1.5e6, -5.0e5, -5.0e5, 5.0e5).finished();
  m.damping = 1e-5 * m.stiffness + 2.0 * m.mass;
  m.contacts.push_back({.point = {.kn = 1.0e6, .kt = 1.0e6, .mu = 0.3, .n0 = 30.0},
                        .tangential = (Eigen::RowVector2d() << 1.0, 0.0).finished(),
                        .normal = Eigen::RowVector2d::Zero()});
  for (double hz : {80.0, 110.0, 150.0, 230.0}) expect_round_trip(m, 1, 1, 3.0, hz);
}

class ResponseControlAnalysis : public test::TempFolderTest {
 protected:
  static double column(const ResultTable& t, const std::string& name, Eigen::Index row) {
    const std::optional<int> c = t.column_index(name);
    if (!c) throw std::runtime_error("no column " + name);
    return t.values(row, *c);
  }
  // y(x) linear between the two rows of `t` whose column xs brackets x (xs monotonic), or NaN.
  static double at(const ResultTable& t, const std::string& xs, const std::string& ys, double x, bool log_x = false) {
    const auto f = [&](double v) { return log_x ? std::log(v) : v; };
    for (Eigen::Index r = 1; r < t.values.rows(); ++r) {
      const double x0 = column(t, xs, r - 1), x1 = column(t, xs, r);
      if ((x0 - x) * (x1 - x) > 0.0 || x0 == x1) continue;
      const double s = (f(x) - f(x0)) / (f(x1) - f(x0));
      return column(t, ys, r - 1) + s * (column(t, ys, r) - column(t, ys, r - 1));
    }
    return std::nan("");
  }
};

TEST_F(ResponseControlAnalysis, PhaseResonanceOfAHeldAmplitudeIsTheNonlinearModeThere) {
  // One DOF, H = 1: the force that holds x = A cos(w t) is A (k_eq(A) - w^2 + i (c w + d_eq(A))),
  // in quadrature with x where w^2 = k_eq(A): the nonlinear mode's frequency at that amplitude
  // (EPMC), and there |F| = kappa w A, the mode's force_for_peak. Stick-slip at both amplitudes
  // (the slip limit is mu n0 / kt = 9e-6 m).
  test::OscillatorCase c;
  c.tolerance = "1e-12";
  c.levels = "[1.0]";
  c.analysis_extra =
      "[[analysis.response_control]]\nname = \"a20\"\ndof = \"A.x\"\ndisplacement = 2.0e-5\n"
      "frequency_hz = [150.0, 240.0]\nstep_hz = 0.1\n"
      "[[analysis.response_control]]\nname = \"a50\"\ndof = \"A.x\"\ndisplacement = 5.0e-5\n"
      "frequency_hz = [240.0, 150.0]\nstep_hz = 0.1\n"
      "[analysis.nonlinear_modes]\nlinear_modes = [1]\nmodal_amplitude = [1.0e-6, 1.0e-3]\npoints = 400\n";
  const CaseSpec spec = parse_case_file(write(test::oscillator_case_text(c)));
  const HbmOutcome o = run_hbm(build_model(spec.model), std::get<HbmSpec>(spec.analysis));
  const ResultTable& modes = o.tables.at("nonlinear_modes");
  for (const auto& [name, amplitude] : {std::pair{"frf_a20", 2.0e-5}, std::pair{"frf_a50", 5.0e-5}}) {
    const ResultTable& t = o.tables.at(name);
    EXPECT_EQ(t.values.rows(), 901) << name;
    for (Eigen::Index r = 0; r < t.values.rows(); r += 100)
      EXPECT_NEAR(column(t, "A.x_amp_m", r) / amplitude - 1.0, 0.0, 1e-9) << name;
    const double hz = at(t, "force_phase_deg", "frequency_hz", 90.0);
    const double force = at(t, "force_phase_deg", "force_n", 90.0);
    const double mode_hz = at(modes, "A.x_amp_m", "frequency_hz", amplitude, true);
    const double mode_force = at(modes, "A.x_amp_m", "force_for_peak_n", amplitude, true);
    std::printf("  %s: phase resonance %.6f Hz at %.6g N; nonlinear mode %.6f Hz, force for its peak %.6g N\n", name,
                hz, force, mode_hz, mode_force);
    // What is left is the interpolation of either table (0.1 Hz grid, 400 amplitudes over 3 decades).
    EXPECT_NEAR(hz / mode_hz - 1.0, 0.0, 1e-5) << name;
    EXPECT_NEAR(force / mode_force - 1.0, 0.0, 1e-4) << name;
  }
  // The smallest force lies next to the phase resonance (the viscous term shifts it by O(zeta^2)).
  const ResultTable& summary = o.tables.at("response_control");
  for (Eigen::Index r = 0; r < 2; ++r) {
    EXPECT_EQ(column(summary, "min_interior", r), 1.0);
    EXPECT_NEAR(column(summary, "min_phase_deg", r), -90.0, 1.0);
  }
}

}  // namespace
}  // namespace bb
