// What timeint/steady_state says of a motion that does not repeat every forcing period: a
// subharmonic motion found with its period multiple, a quasi-periodic one with the range of its
// first harmonic, a periodic one with an envelope of zero width. Linear oscillators started from
// rest (no contact): the free vibration at the natural frequency rides on the forced one.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "timeint/steady_state.hpp"

namespace bb::timeint {
namespace {

// m x'' + c x' + k x = F cos(omega t), omega = 100 rad/s.
constexpr double kOmega = 100.0, kForce = 2.0, kMass = 1.0;

friction::FrictionModel oscillator(double natural, double zeta) {
  friction::FrictionModel m;
  m.mass = Eigen::MatrixXd::Constant(1, 1, kMass);
  m.stiffness = Eigen::MatrixXd::Constant(1, 1, kMass * natural * natural);
  m.damping = Eigen::MatrixXd::Constant(1, 1, 2.0 * zeta * kMass * natural);
  m.harmonic_load = Eigen::VectorXcd::Constant(1, kForce);
  return m;
}

double forced_amplitude(double natural, double zeta = 0.0) {
  return kForce / std::abs(std::complex<double>(kMass * (natural * natural - kOmega * kOmega),
                                                2.0 * zeta * kMass * natural * kOmega));
}

SteadyStateOptions options(double tolerance, int max_cycles) {
  return {.dofs = {0}, .steps_per_period = 512, .harmonics = 1, .tolerance = tolerance, .max_cycles = max_cycles};
}

// Undamped, natural frequency omega / 2: the free vibration repeats every second forcing period.
TEST(SteadyStateEnvelope, AMotionThatRepeatsEverySecondPeriodIsFoundAsSubharmonic) {
  const SteadyState s = steady_state(oscillator(kOmega / 2, 0.0), kOmega, options(1e-4, 20));
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.period_multiple, 2);
  EXPECT_NE(s.failure.find("repeats every 2 periods"), std::string::npos) << s.failure;
  // Over two periods the free vibration at omega / 2 has no first harmonic: the forced one is left.
  EXPECT_NEAR(s.amplitude(0, 1) / forced_amplitude(kOmega / 2), 1.0, 1e-3);
  // One period alone sees part of the free vibration, its sign alternating from period to period.
  const Eigen::Index last = s.period_harmonics.rows() - 1;
  ASSERT_GE(last, 2);
  const double x = forced_amplitude(kOmega / 2);
  EXPECT_GT(std::abs(s.period_harmonics(last, 0) - s.period_harmonics(last - 1, 0)), 0.1 * x);
  EXPECT_LT(std::abs(s.period_harmonics(last, 0) - s.period_harmonics(last - 2, 0)), 1e-3 * x);
}

// Undamped, natural frequency omega / sqrt(2): no whole number of periods repeats.
TEST(SteadyStateEnvelope, AMotionThatRepeatsWithinNoPeriodsIsReportedWithItsEnvelope) {
  const double natural = kOmega / std::numbers::sqrt2;
  const SteadyState s = steady_state(oscillator(natural, 0.0), kOmega, options(1e-4, 150));
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.period_multiple, 0);
  EXPECT_NE(s.failure.find("no repetition within 8 periods"), std::string::npos) << s.failure;
  ASSERT_EQ(s.period_harmonics.rows(), 100);  // the last envelope_periods
  EXPECT_DOUBLE_EQ(s.envelope(0, 0), s.period_harmonics.col(0).cwiseAbs().minCoeff());
  EXPECT_DOUBLE_EQ(s.envelope(0, 1), s.period_harmonics.col(0).cwiseAbs().maxCoeff());
  // The free vibration's share of a period's first harmonic swings with its phase: the envelope
  // brackets the forced amplitude.
  EXPECT_LT(s.envelope(0, 0), forced_amplitude(natural));
  EXPECT_GT(s.envelope(0, 1), forced_amplitude(natural));
}

// Damped: the free vibration dies out, the motion repeats every period.
TEST(SteadyStateEnvelope, APeriodicMotionHasPeriodMultipleOneAndAnEnvelopeOfNoWidth) {
  const SteadyState s = steady_state(oscillator(kOmega / 2, 0.2), kOmega, options(1e-9, 2000));
  ASSERT_TRUE(s.converged) << s.failure;
  EXPECT_EQ(s.period_multiple, 1);
  EXPECT_TRUE(s.failure.empty());
  ASSERT_EQ(s.period_harmonics.rows(), 1);  // the transient before it is not the motion's envelope
  EXPECT_EQ(s.envelope(0, 0), s.envelope(0, 1));
  EXPECT_NEAR(s.envelope(0, 0), s.amplitude(0, 1), 1e-12 * s.amplitude(0, 1));
  EXPECT_NEAR(s.amplitude(0, 1) / forced_amplitude(kOmega / 2, 0.2), 1.0, 1e-3);
}

TEST(SteadyStateEnvelope, NoRepetitionOrEnvelopeWindowBelowOneIsRefused) {
  SteadyStateOptions o = options(1e-6, 10);
  o.max_period_multiple = 0;
  EXPECT_THROW((void)steady_state(oscillator(kOmega / 2, 0.1), kOmega, o), std::invalid_argument);
  o = options(1e-6, 10);
  o.envelope_periods = 0;
  EXPECT_THROW((void)steady_state(oscillator(kOmega / 2, 0.1), kOmega, o), std::invalid_argument);
}

}  // namespace
}  // namespace bb::timeint
