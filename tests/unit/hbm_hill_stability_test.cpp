// Stability of harmonic-balance solutions by Hill's method (hbm/hill_stability): the Floquet
// exponents of a linear oscillator against its closed form, growth detected with negative damping,
// and the middle branch of a hardening (impact) resonance between its two folds found unstable while
// the outer branches are stable. Units: SI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "friction_oscillator.hpp"
#include "hbm/harmonic_balance.hpp"
#include "hbm/hill_stability.hpp"

namespace bb::hbm {
namespace {

// A friction oscillator driven far below its slip force is the linear oscillator m, c, k + kt:
// exponents -c / 2m +- i w_d (Krack & Gross 2019, eq. for a linear system).
TEST(HillStability, StuckOscillatorHasTheExponentsOfItsLinearSpring) {
  const test::FrictionOscillator o{.mass = 1.0,
                                   .damping = 20.0,
                                   .stiffness = 1e6,
                                   .force = 1e-3,
                                   .contact = {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 30.0}};
  for (int h : {1, 3}) {
    const HarmonicBalance system(o.model(), {.harmonics = h});
    const double omega = 2 * std::numbers::pi * 150.0;
    const HbmSolution s = solve_at_frequency(system, omega);
    ASSERT_TRUE(s.converged) << s.failure;
    const HillStability st = hill_stability(system, s.x, omega);
    ASSERT_TRUE(st.ok) << st.failure;
    ASSERT_EQ(st.exponents.size(), 2);
    const double wn = std::sqrt(2e6), zeta = 20.0 / (2 * wn);
    const double wd = wn * std::sqrt(1 - zeta * zeta);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(st.exponents[i].real(), -10.0, 1e-6) << "H = " << h;
      // Im is +w_d or -w_d shifted by a multiple of omega (the exponents are defined modulo i omega).
      const double im = st.exponents[i].imag();
      const double shifted =
          std::min(std::abs(std::remainder(im - wd, omega)), std::abs(std::remainder(im + wd, omega)));
      EXPECT_NEAR(shifted, 0.0, 1e-6 * wd) << "H = " << h;
    }
    EXPECT_TRUE(st.stable);
  }
}

TEST(HillStability, NegativeDampingIsUnstableWithTheRightGrowthRate) {
  test::FrictionOscillator o{.mass = 1.0,
                             .damping = -20.0,
                             .stiffness = 1e6,
                             .force = 1e-3,
                             .contact = {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 30.0}};
  const HarmonicBalance system(o.model(), {.harmonics = 1});
  const double omega = 2 * std::numbers::pi * 150.0;
  const HbmSolution s = solve_at_frequency(system, omega);
  ASSERT_TRUE(s.converged) << s.failure;
  const HillStability st = hill_stability(system, s.x, omega);
  ASSERT_TRUE(st.ok);
  EXPECT_FALSE(st.stable);
  EXPECT_NEAR(st.max_real, 10.0, 1e-6);
}

// Two masses whose relative motion closes a unilateral contact (impact_pair of
// hbm_harmonic_balance_test.cpp): a hardening resonance with two folds. Between the folds the path
// runs backwards in frequency; that branch is a saddle (a real exponent crossed zero at the fold).
TEST(HillStability, BranchBetweenTheFoldsOfAHardeningResonanceIsUnstable) {
  friction::FrictionModel m;
  m.mass = Eigen::MatrixXd::Identity(2, 2);
  m.stiffness = 1.0e6 * Eigen::MatrixXd::Identity(2, 2);
  m.damping = 20.0 * Eigen::MatrixXd::Identity(2, 2);
  m.contacts.push_back({{.kn = 1.0e6, .kt = 1.0, .mu = 0.0, .n0 = 0.0},
                        Eigen::RowVectorXd::Zero(2),
                        (Eigen::RowVectorXd(2) << 1.0, -1.0).finished()});
  m.static_load = Eigen::Vector2d(-10.0, 10.0);
  m.harmonic_load = Eigen::Vector2cd(2.0, 0.0);
  const HarmonicBalance system(m, {.harmonics = 5});
  ContinuationOptions options;
  options.omega_start = 800.0;
  options.omega_end = 1600.0;
  const ContinuationResult r = continue_in_frequency(system, options);
  ASSERT_TRUE(r.converged) << r.failure;
  ASSERT_GE(r.turning_points, 2);
  int forward = 0, forward_stable = 0, backward = 0, backward_unstable = 0;
  for (const ContinuationPoint& p : r.points) {
    const HillStability st = hill_stability(system, p.x, p.omega);
    ASSERT_TRUE(st.ok) << st.failure;
    if (p.tangent_omega > 0) {
      ++forward;
      forward_stable += st.stable ? 1 : 0;
    } else {
      ++backward;
      backward_unstable += st.stable ? 0 : 1;
    }
  }
  std::printf("  forward points %d (stable %d), backward points %d (unstable %d)\n", forward, forward_stable, backward,
              backward_unstable);
  ASSERT_GT(backward, 3);
  // Points right at a fold are marginal either way: allow one on each side.
  EXPECT_GE(backward_unstable, backward - 2);
  EXPECT_GE(forward_stable, forward - 2);
}

// An oscillator at 16 kHz driven at 150 Hz with H = 1: every copy of its exponent lies beyond the
// band one harmonic resolves. Its growth (negative damping) is reported as unknown, never as a
// resolved verdict; its decay leaves nothing to report.
TEST(HillStability, GrowthBeyondTheResolvedBandIsUnknownNotUnstable) {
  const double omega = 2 * std::numbers::pi * 150.0;
  for (const double damping : {-20.0, 20.0}) {
    const test::FrictionOscillator o{.mass = 1.0,
                                     .damping = damping,
                                     .stiffness = 1e10,
                                     .force = 1e-3,
                                     .contact = {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 30.0}};
    const HarmonicBalance system(o.model(), {.harmonics = 1});
    const HbmSolution s = solve_at_frequency(system, omega);
    ASSERT_TRUE(s.converged) << s.failure;
    const HillStability st = hill_stability(system, s.x, omega);
    ASSERT_TRUE(st.ok) << st.failure;
    if (damping < 0) {
      EXPECT_TRUE(std::isnan(st.verdict()));
      EXPECT_NE(st.unresolved.find("beyond the band"), std::string::npos) << st.unresolved;
    } else {
      EXPECT_EQ(st.verdict(), 1.0);
    }
  }
}

TEST(HillStability, RefusesASingularMassWithAReason) {
  test::FrictionOscillator o{.mass = 1.0,
                             .damping = 20.0,
                             .stiffness = 1e6,
                             .force = 1.0,
                             .contact = {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 30.0}};
  friction::FrictionModel m = o.model();
  m.mass(0, 0) = 0.0;
  const HarmonicBalance system(m, {.harmonics = 1});
  const HillStability st = hill_stability(system, Eigen::VectorXd::Zero(3), 900.0);
  EXPECT_FALSE(st.ok);
  EXPECT_NE(st.failure.find("mass"), std::string::npos);
}

}  // namespace
}  // namespace bb::hbm
