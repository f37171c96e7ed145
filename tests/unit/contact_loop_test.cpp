// The friction-contact test rig (analysis/contact_loop_analysis): the sampled Jenkins loop under
// imposed motion against its closed forms at constant normal load (energy, describing function,
// stick slope, slip plateau) within the sampling error bounds, the frictionless and rigid-plastic
// limits, the odd symmetry of the loop, and lift-off (no force while open, the open fraction).
// Units: SI.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/contact_loop_analysis.hpp"
#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "common/constants.hpp"

namespace bb {
namespace {

ContactLoopSpec rig(double u_amp, double v_amp = 0.0, int samples = 256) {
  ContactLoopSpec s;
  s.point = {.kn = 1e8, .kt = 5e7, .mu = 0.5, .n0 = 100.0};  // Fs = 50 N, xs = 1e-6 m
  s.tangential_amplitude = u_amp;
  s.normal_amplitude = v_amp;
  s.samples = samples;
  return s;
}

double h_of(const ContactLoopSpec& s) { return 2 * kPi / s.samples; }

TEST(ContactLoop, EnergyMatchesClosedFormFromBelowWithinTheCornerBound) {
  // The trapezoid chord cuts the two stick/slip corners: low by at most 2 kt du^2 / 8.
  for (double ratio : {1.5, 3.0, 20.0, 200.0}) {
    const ContactLoopSpec s = rig(ratio * 1e-6);
    const ContactLoopOutcome o = run_contact_loop(s);
    const JenkinsLoopClosedForm cf = jenkins_loop_closed_form(s.point, s.tangential_amplitude);
    EXPECT_DOUBLE_EQ(cf.energy, 4 * 50.0 * (s.tangential_amplitude - 1e-6));
    const double beta = std::acos(1 - 2 / ratio), h = h_of(s);
    const double du = s.tangential_amplitude * h * (std::sin(beta) + h);
    const double bound = 2 * s.point.kt * du * du / 8;
    EXPECT_LE(o.summary.dissipated_energy, cf.energy * (1 + 1e-12)) << ratio;
    EXPECT_GE(o.summary.dissipated_energy, cf.energy - bound) << ratio;
    EXPECT_TRUE(o.aft.closed);
  }
}

TEST(ContactLoop, StuckContactIsTheSpringKtAndDissipatesNothing) {
  const ContactLoopSpec s = rig(0.5e-6);  // U < xs
  const ContactLoopOutcome o = run_contact_loop(s);
  EXPECT_EQ(jenkins_loop_closed_form(s.point, s.tangential_amplitude).energy, 0.0);
  EXPECT_NEAR(o.summary.dissipated_energy, 0.0, 1e-12 * 50.0 * s.tangential_amplitude);
  EXPECT_DOUBLE_EQ(o.summary.stick_fraction, 1.0);
  EXPECT_NEAR(o.summary.stick_slope / s.point.kt, 1.0, 1e-12);
  EXPECT_NEAR(o.summary.equivalent_stiffness / s.point.kt, 1.0, 1e-12);
  EXPECT_NEAR(o.summary.equivalent_damping, 0.0, 1e-9 * s.point.kt);
}

TEST(ContactLoop, DescribingFunctionMatchesGriffinWithinTheKinkBound) {
  // Rectangle rule with two derivative kinks of jump J: |error| <= 2 J h^2 / 12 (B2 <= 1/6), over pi U.
  for (double ratio : {1.5, 3.0, 20.0, 200.0}) {
    for (int samples : {256, 1024}) {
      const ContactLoopSpec s = rig(ratio * 1e-6, 0.0, samples);
      const ContactLoopOutcome o = run_contact_loop(s);
      const JenkinsLoopClosedForm cf = jenkins_loop_closed_form(s.point, s.tangential_amplitude);
      const double beta = std::acos(1 - 2 / ratio), h = h_of(s), kt = s.point.kt;
      const double k_bound = kt * std::sin(beta) * std::abs(std::cos(beta)) * h * h / (6 * kPi) + kt * h * h * h / 10;
      const double c_bound = kt * std::sin(beta) * std::sin(beta) * h * h / (6 * kPi) + kt * h * h * h / 10;
      EXPECT_NEAR(o.summary.equivalent_stiffness, cf.stiffness, k_bound) << ratio << " " << samples;
      EXPECT_NEAR(o.summary.equivalent_damping, cf.damping, c_bound) << ratio << " " << samples;
    }
  }
}

TEST(ContactLoop, StickSlopeIsKtAndTheSlipPlateauIsMuN0) {
  const ContactLoopOutcome o = run_contact_loop(rig(2e-5));
  EXPECT_NEAR(o.summary.stick_slope / 5e7, 1.0, 1e-12);
  EXPECT_NEAR(o.summary.max_tangential_force, 50.0, 1e-12);
  EXPECT_NEAR(o.summary.max_t_over_mu_n, 1.0, 1e-12);
  EXPECT_GT(o.summary.slip_fraction, 0.0);
  EXPECT_DOUBLE_EQ(o.summary.stick_fraction + o.summary.slip_fraction + o.summary.lift_off_fraction, 1.0);
}

TEST(ContactLoop, FrictionlessContactCarriesNoForceAndDissipatesNothing) {
  ContactLoopSpec s = rig(2e-5);
  s.point.mu = 0.0;
  const ContactLoopOutcome o = run_contact_loop(s);
  EXPECT_EQ(o.summary.max_tangential_force, 0.0);
  EXPECT_EQ(o.summary.dissipated_energy, 0.0);
  EXPECT_EQ(jenkins_loop_closed_form(s.point, s.tangential_amplitude).energy, 0.0);
  EXPECT_NEAR(o.summary.equivalent_stiffness, 0.0, 1e-12);
}

TEST(ContactLoop, RigidContactGivesTheRigidPlasticEnergy) {
  // kt -> infinity: a square loop of height 2 mu n0 and width 2 U, energy 4 mu n0 U. Sampled, the
  // force jumps within the first interval after each reversal: the chord loses at most mu n0 du per
  // reversal, du = U (1 - cos h) <= U h^2 / 2.
  ContactLoopSpec s = rig(2e-5);
  s.point.kt = 1e16;
  const ContactLoopOutcome o = run_contact_loop(s);
  const double exact = 4 * 0.5 * 100.0 * s.tangential_amplitude, h = h_of(s);
  EXPECT_NEAR(o.summary.dissipated_energy, exact,
              2 * 50.0 * s.tangential_amplitude * h * h / 2 + 4 * 50.0 * 50.0 / s.point.kt);
  EXPECT_NEAR(jenkins_loop_closed_form(s.point, s.tangential_amplitude).energy, exact, 1e-9 * exact);
}

TEST(ContactLoop, LoopIsOddSymmetricAtConstantNormalLoad) {
  const ContactLoopOutcome o = run_contact_loop(rig(7e-6));
  const Eigen::Index n = o.aft.t.size(), half = n / 2;
  for (Eigen::Index k = 0; k < n; ++k) {
    EXPECT_NEAR(o.aft.t[(k + half) % n], -o.aft.t[k], 1e-12 * 50.0) << k;
    EXPECT_NEAR(o.aft.u[(k + half) % n], -o.aft.u[k], 1e-18) << k;
  }
}

TEST(ContactLoop, OpenSamplesCarryNoForceAndTheOpenFractionMatchesTheArc) {
  for (double v_amp : {1.2e-6, 2e-6, 1e-5}) {
    for (double phase : {0.0, 37.0, 90.0}) {
      ContactLoopSpec s = rig(2e-5, v_amp);
      s.normal_phase_deg = phase;
      const ContactLoopOutcome o = run_contact_loop(s);
      int open = 0;
      for (size_t k = 0; k < o.aft.state.size(); ++k) {
        if (o.aft.state[k] != friction::ContactState::lift_off) continue;
        ++open;
        EXPECT_EQ(o.aft.t[static_cast<Eigen::Index>(k)], 0.0);
        EXPECT_EQ(o.aft.n[static_cast<Eigen::Index>(k)], 0.0);
      }
      EXPECT_GT(open, 0);
      EXPECT_EQ(o.summary.max_force_when_open, 0.0);
      // An arc of length L holds L / h samples within one.
      const double expected = std::acos(100.0 / (1e8 * v_amp)) / kPi;
      EXPECT_DOUBLE_EQ(lift_off_fraction_closed_form(s.point, v_amp), expected);
      EXPECT_NEAR(o.summary.lift_off_fraction, expected, 1.0 / s.samples) << v_amp << " " << phase;
      EXPECT_LE(o.summary.max_t_over_mu_n, 1.0 + 1e-12);
    }
  }
  EXPECT_EQ(lift_off_fraction_closed_form(rig(2e-5).point, 0.5e-6), 0.0);  // kn V < n0: never opens
}

TEST(ContactLoop, ClosedFormsAreNotClaimedForAVariableNormalLoad) {
  const ContactLoopOutcome o = run_contact_loop(rig(2e-5, 5e-7));
  const ResultTable& t = o.tables.at("loop_summary");
  EXPECT_TRUE(std::isnan(t.values(0, *t.column_index("closed_form_energy_j"))));
  EXPECT_TRUE(std::isnan(t.values(0, *t.column_index("closed_form_stiffness_n_per_m"))));
  const ResultTable& h = o.tables.at("hysteresis");
  for (const char* c : {"relative_tangential_m", "tangential_force_n", "normal_force_n", "slider_m"})
    EXPECT_TRUE(h.column_index(c)) << c;
  EXPECT_EQ(h.values.rows(), 256);
}

TEST(ContactLoop, VerificationCaseParsesIntoTheRigSpec) {
  const CaseSpec spec = parse_case_file(std::string(BB_SOURCE_DIR) + "/cases/verification/jenkins_loop_lift_off.toml");
  ASSERT_TRUE(std::holds_alternative<ContactLoopSpec>(spec.analysis));
  EXPECT_EQ(std::get<ContactLoopSpec>(spec.analysis).normal_amplitude, 2e-6);
  EXPECT_EQ(std::get<ContactLoopSpec>(spec.analysis).point.kt, 5e7);
  EXPECT_EQ(spec.model.mesh.kind, MeshSpec::Kind::none);
}

TEST(ContactLoop, ARunHoldsItsTablesOnceInTheResultsNotAgainInTheOutcome) {
  const ContactLoopSpec s = rig(3e-6);
  const ContactLoopOutcome alone = run_contact_loop(s);
  const AnalysisResults r = run_analysis(AnalysisSpec{s}, Model{});
  const auto& outcome = std::get<ContactLoopOutcome>(r.outcome);
  EXPECT_TRUE(outcome.tables.empty()) << "the outcome's tables were moved into the results";
  ASSERT_EQ(r.tables.size(), alone.tables.size());
  for (const auto& [name, table] : alone.tables) {
    ASSERT_TRUE(r.tables.count(name)) << name;
    EXPECT_EQ(r.tables.at(name).values, table.values) << name;
  }
}

}  // namespace
}  // namespace bb
