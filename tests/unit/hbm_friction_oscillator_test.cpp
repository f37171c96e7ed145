// The general harmonic balance (hbm/harmonic_balance.hpp) on the one-DOF friction oscillator
// (friction_oscillator.hpp) against brute-force time integration run to steady state, the energy
// balance of the converged harmonics, and the damped Newton's robustness to poor starts. Units: SI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "common/constants.hpp"
#include "friction/aft.hpp"
#include "friction/jenkins.hpp"
#include "friction_oscillator.hpp"
#include "hbm/harmonic_balance.hpp"

namespace bb::hbm {
namespace {

using friction::ContactState;
using test::first_harmonic_amplitude;
using test::FrictionOscillator;

// m = 1 kg, k = 1e6 N/m (1000 rad/s free of the contact), 1 % viscous damping; the stuck contact
// adds kt = 5e5 N/m (1225 rad/s), and lets go at mu N0 = 10 N, i.e. after 2e-5 m.
FrictionOscillator oscillator(double force) {
  return {.mass = 1.0,
          .damping = 20.0,
          .stiffness = 1.0e6,
          .force = force,
          .contact = {.kn = 0.0, .kt = 5.0e5, .mu = 0.5, .n0 = 20.0}};
}

// Classical RK4 on (x, x'), the contact force at each stage from the committed slider through
// jenkins_step (the exact Jenkins force for a monotone path from the committed state), the slider
// committed at the end of each step. Runs `periods` periods from rest and returns the first
// harmonic (a1, b1) of x over the last `averaged` of them (rectangle rule on whole periods, exact
// for the harmonics of a sampled periodic signal).
Eigen::Vector2d time_integration_first_harmonic(const FrictionOscillator& o, double omega, int periods, int averaged,
                                                int steps_per_period) {
  const double dt = 2.0 * kPi / (omega * steps_per_period);
  const auto acceleration = [&](double t, double x, double v, double slider) {
    const double contact = friction::jenkins_step(o.contact, slider, x, 0.0).tangential;
    return (o.force * std::cos(omega * t) - o.damping * v - o.stiffness * x - contact) / o.mass;
  };
  double x = 0.0, v = 0.0, slider = 0.0;
  Eigen::Vector2d harmonic = Eigen::Vector2d::Zero();
  const long total = static_cast<long>(periods) * steps_per_period;
  const long first_averaged = static_cast<long>(periods - averaged) * steps_per_period;
  for (long n = 0; n < total; ++n) {
    const double t = static_cast<double>(n) * dt;
    if (n >= first_averaged) harmonic += x * Eigen::Vector2d(std::cos(omega * t), std::sin(omega * t));
    const double k1x = v, k1v = acceleration(t, x, v, slider);
    const double k2x = v + 0.5 * dt * k1v,
                 k2v = acceleration(t + 0.5 * dt, x + 0.5 * dt * k1x, v + 0.5 * dt * k1v, slider);
    const double k3x = v + 0.5 * dt * k2v,
                 k3v = acceleration(t + 0.5 * dt, x + 0.5 * dt * k2x, v + 0.5 * dt * k2v, slider);
    const double k4x = v + dt * k3v, k4v = acceleration(t + dt, x + dt * k3x, v + dt * k3v, slider);
    x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    slider = friction::jenkins_step(o.contact, slider, x, 0.0).slider;
  }
  return harmonic * (2.0 / (static_cast<double>(averaged) * steps_per_period));
}

TEST(HbmFrictionOscillator, FirstHarmonicMatchesTimeIntegrationAndImprovesWithHarmonics) {
  // F = 20 N: stuck, the linear resonance would reach 8e-4 m, 40 times the elastic range, so the
  // sweep crosses from near-stick (U ~ 2 mu N0 / kt at 0.9 wn) to gross slip (U ~ 20 mu N0 / kt at wn).
  const FrictionOscillator o = oscillator(20.0);
  double worst_h1 = 0.0, worst_h5 = 0.0, ti_step_error = 0.0;
  for (double ratio : {0.9, 0.95, 1.0, 1.03, 1.06, 1.1, 1.15, 1.2}) {
    const double omega = ratio * 1000.0;
    const double amplitude = time_integration_first_harmonic(o, omega, 600, 20, 2000).norm();
    if (ratio == 1.0)  // the reference's own error: halve the step once
      ti_step_error = std::abs(time_integration_first_harmonic(o, omega, 600, 20, 4000).norm() - amplitude) / amplitude;
    std::vector<double> errors;
    for (int harmonics : {1, 3, 5}) {
      const HbmSolution s = solve_at_frequency(HarmonicBalance(o.model(), {.harmonics = harmonics}), omega);
      ASSERT_TRUE(s.converged) << "w / wn = " << ratio << ", H = " << harmonics << ": " << s.failure;
      ASSERT_TRUE(std::any_of(s.contacts[0].state.begin(), s.contacts[0].state.end(),
                              [](ContactState c) { return c == ContactState::slip_positive; }))
          << "w / wn = " << ratio << ": the point of the test is a slipping contact";
      errors.push_back(std::abs(first_harmonic_amplitude(s) - amplitude) / amplitude);
      std::printf("[ HBM vs TI ] w/wn %.2f H %d: HBM %.6e m (%d Newton it), TI %.6e m, rel. diff %.1e\n", ratio,
                  harmonics, first_harmonic_amplitude(s), s.iterations, amplitude, errors.back());
    }
    EXPECT_LT(errors[0], 0.01) << "H = 1, w / wn = " << ratio;
    EXPECT_LT(errors[2], 5e-4) << "H = 5, w / wn = " << ratio;
    EXPECT_LT(errors[2], errors[0]) << "w / wn = " << ratio;
    worst_h1 = std::max(worst_h1, errors[0]);
    worst_h5 = std::max(worst_h5, errors[2]);
  }
  std::printf("[ HBM vs TI ] worst rel. diff H = 1: %.1e, H = 5: %.1e (TI step halving changes it by %.1e)\n", worst_h1,
              worst_h5, ti_step_error);
  EXPECT_LT(ti_step_error, 1e-5);
}

TEST(HbmFrictionOscillator, ConvergedHarmonicsBalanceInputAndDissipatedEnergy) {
  // Over a period the excitation's work equals what viscous damping and friction dissipate:
  // pi F b1 = pi c w sum h^2 (a_h^2 + b_h^2) + integral of T dx. It follows from R = 0 only if the
  // signs of every term of R are right, and friction must dissipate (W > 0).
  const FrictionOscillator o = oscillator(20.0);
  const double omega = 1030.0;
  const HbmSolution s = solve_at_frequency(HarmonicBalance(o.model(), {.harmonics = 5}), omega);
  ASSERT_TRUE(s.converged) << s.failure;
  Eigen::VectorXd excitation = Eigen::VectorXd::Zero(s.x.size());
  excitation[1] = o.force;
  const double input = friction::cycle_work(excitation, s.x),
               friction = friction::cycle_work(s.contacts[0].tangential, s.x);
  double viscous = 0.0;
  for (int h = 1; h <= 5; ++h)
    viscous += kPi * o.damping * omega * h * h * (s.x[2 * h - 1] * s.x[2 * h - 1] + s.x[2 * h] * s.x[2 * h]);
  EXPECT_GT(friction, 0.0);
  EXPECT_GT(input, 0.0);
  EXPECT_NEAR(input, viscous + friction, 1e-8 * input);
}

TEST(HbmFrictionOscillator, LineSearchReachesTheSameSolutionFromPoorStarts) {
  const FrictionOscillator o = oscillator(20.0);
  const double omega = 1060.0;
  const HarmonicBalance system(o.model(), {.harmonics = 3});
  const HbmSolution reference = solve_at_frequency(system, omega);
  ASSERT_TRUE(reference.converged);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(7);
  Eigen::VectorXd far = 30.0 * reference.x;  // deep in gross slip, 30 times too large
  far[0] = 1e-3;                             // and offset
  for (const Eigen::VectorXd& start : {zero, far}) {
    const HbmSolution s = solve_at_frequency(system, omega, start);
    ASSERT_TRUE(s.converged) << s.failure;
    EXPECT_EQ(s.start, HbmStart::initial) << "converged only from a fallback start";
    EXPECT_LT((s.x - reference.x).norm(), 1e-6 * reference.x.norm());
  }
}

TEST(HbmFrictionOscillator, NonConvergenceIsReportedNotThrown) {
  const FrictionOscillator o = oscillator(20.0);
  Eigen::VectorXd far = Eigen::VectorXd::Zero(3);
  far[1] = 1e-2;
  HbmOptions options{.harmonics = 1};
  options.max_iterations = 1;
  const HarmonicBalance system(o.model(), options);
  const HbmSolution s = solve_at_frequency(system, 1060.0, far);
  EXPECT_FALSE(s.converged);
  EXPECT_FALSE(s.failure.empty());
  EXPECT_GT(s.residual, 0.0);
  EXPECT_THROW((void)solve_at_frequency(system, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace bb::hbm
