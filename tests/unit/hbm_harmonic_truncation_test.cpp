// The truncation estimate of the harmonic balance (hbm/harmonic_truncation): nothing above H for a
// linear contact, only odd harmonics for friction under a constant normal load (half-wave
// symmetry), a one-step estimate of the third harmonic that agrees with the H = 3 solution, and
// shares that fall as H grows. Units: SI.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "../extremes/hbm_models.hpp"
#include "hbm/harmonic_balance.hpp"
#include "hbm/harmonic_truncation.hpp"

namespace bb::hbm {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// m = 1 kg on k = 1e6 N/m, zeta 1 %, a Jenkins contact to the ground with the constant normal load
// N0 = 30 N (no normal DOF), F cos(omega t) on the mass.
friction::FrictionModel friction_oscillator(double kt, double mu, double force) {
  friction::FrictionModel m;
  m.mass = MatrixXd::Identity(1, 1);
  m.stiffness = MatrixXd::Constant(1, 1, 1.0e6);
  m.damping = MatrixXd::Constant(1, 1, 20.0);
  m.contacts.push_back(
      {{.kn = 1.0e6, .kt = kt, .mu = mu, .n0 = 30.0}, Eigen::RowVectorXd::Ones(1), Eigen::RowVectorXd::Zero(1)});
  m.harmonic_load = Eigen::VectorXcd::Constant(1, force);
  return m;
}

HbmSolution solve(const HarmonicBalance& system, double omega) {
  HbmSolution s = solve_at_frequency(system, omega);
  EXPECT_TRUE(s.converged) << s.failure;
  return s;
}

TEST(HarmonicTruncation, LinearContactExcitesNothingAboveH) {
  // mu = 0: the contact is the normal spring alone, a linear force.
  const HarmonicBalance system(models::blade_on_ground({.kn = 3.0e5, .kt = 1.0e6, .mu = 0.0, .n0 = 30.0}, 5.0),
                               {.harmonics = 2, .aft = {.samples = 64}});
  const HbmSolution s = solve(system, 900.0);
  const HarmonicTruncation t = harmonic_truncation(system, s.x, s.omega);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.probe_harmonics, 6);
  ASSERT_EQ(t.share.size(), 4u);
  EXPECT_LT(t.largest(), 1e-12);
  EXPECT_EQ(t.needed(1e-9), 2);
}

TEST(HarmonicTruncation, FrictionUnderConstantLoadExcitesOddHarmonicsOnly) {
  const HarmonicBalance system(friction_oscillator(1.0e6, 0.3, 10.0), {.harmonics = 1, .aft = {.samples = 1024}});
  const HbmSolution s = solve(system, 2 * std::numbers::pi * 170.0);  // stick-slip near the resonance
  const HarmonicTruncation t = harmonic_truncation(system, s.x, s.omega);
  ASSERT_TRUE(t.ok);
  ASSERT_EQ(t.share.size(), 2u);  // harmonics 2 and 3
  std::printf("  H = 1: share of harmonic 2 %.2e, of harmonic 3 %.2e\n", t.share[0], t.share[1]);
  EXPECT_LT(t.share[0], 1e-12);
  EXPECT_GT(t.share[1], 1e-3);
  EXPECT_EQ(t.needed(1e-4), 3);
  EXPECT_EQ(t.needed(0.5), 1);
}

// The estimate is one Newton step on the harmonics above H with the lower ones held: it should give
// the third harmonic of the H = 3 solution to first order (the third harmonic feeds back on the
// first only through the slip phases it shifts).
TEST(HarmonicTruncation, OneStepEstimateMatchesTheThirdHarmonicOfTheLargerBalance) {
  const friction::FrictionModel model = friction_oscillator(1.0e6, 0.3, 10.0);
  const double omega = 2 * std::numbers::pi * 170.0;
  const HarmonicBalance h1(model, {.harmonics = 1, .aft = {.samples = 1024}});
  const HarmonicBalance h3(model, {.harmonics = 3, .aft = {.samples = 1024}});
  const HbmSolution s1 = solve(h1, omega), s3 = solve(h3, omega);
  const double estimated = harmonic_truncation(h1, s1.x, omega).share[1];
  const double actual = std::hypot(s3.x[5], s3.x[6]) / s3.x.segment(1, 6).norm();
  std::printf("  third harmonic: estimated share %.4e, H = 3 solution %.4e\n", estimated, actual);
  EXPECT_NEAR(estimated, actual, 0.2 * actual);
}

TEST(HarmonicTruncation, SharesFallAsHarmonicsAreAdded) {
  // Coulomb-like (stiff stick) in gross slip: F = 30 N against a slip force of 9 N. (Near F = mu N0
  // the stuck and sliding branches coexist and each H may land on another one.)
  const friction::FrictionModel model = friction_oscillator(1.0e8, 0.3, 30.0);
  const double omega = 2 * std::numbers::pi * 200.0;  // above the resonance: the motion never sticks long
  double previous = 1.0;
  VectorXd warm;  // the previous H's solution, its higher coefficients zero
  for (const int h : {1, 3, 5, 9}) {
    const HarmonicBalance system(model, {.harmonics = h, .aft = {.samples = 4096}});
    if (warm.size() > 0) warm.conservativeResizeLike(VectorXd::Zero(system.unknowns()));
    HbmSolution s = solve_at_frequency(system, omega, warm.size() > 0 ? std::optional<VectorXd>(warm) : std::nullopt);
    ASSERT_TRUE(s.converged) << s.failure;
    warm = s.x;
    const double share = harmonic_truncation(system, s.x, omega).largest();
    std::printf("  H = %d: largest share above H %.3e\n", h, share);
    EXPECT_LT(share, previous);
    previous = share;
  }
}

}  // namespace
}  // namespace bb::hbm
