// Jenkins point contact (friction/jenkins): the states and transitions of thesis Table X,
// eqs 3.28-3.29, lift-off and re-stick, the Coulomb bound, frictionless, very stiff and unloaded
// contacts, and the 2D contact of two sliders sharing N. Units: SI.
#include "friction/jenkins.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace bb::friction {
namespace {

// kt = 1e6 N/m, mu N0 = 50 N: the slider lets go after 5e-5 m of tangential travel.
constexpr PointParameters kContact{.kn = 1.0e7, .kt = 1.0e6, .mu = 0.5, .n0 = 100.0};

TEST(JenkinsContact, StickThenPositiveSlipThenStickOnReversalThenNegativeSlip) {
  const auto& p = kContact;
  JenkinsStep s = jenkins_step(p, 0.0, 2.0e-5, 0.0);  // within the elastic range
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_DOUBLE_EQ(s.tangential, 20.0);
  EXPECT_DOUBLE_EQ(s.normal, 100.0);
  EXPECT_EQ(s.slider, 0.0);

  s = jenkins_step(p, s.slider, 8.0e-5, 0.0);  // T* = 80 N > mu N = 50 N
  EXPECT_EQ(s.state, ContactState::slip_positive);
  EXPECT_DOUBLE_EQ(s.tangential, 50.0);
  EXPECT_DOUBLE_EQ(s.slider, 3.0e-5);  // kt (u - w) = mu N again

  s = jenkins_step(p, s.slider, 6.0e-5, 0.0);  // reversal: the spring unloads elastically
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_NEAR(s.tangential, 30.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.slider, 3.0e-5);

  s = jenkins_step(p, s.slider, -3.0e-5, 0.0);  // T* = -60 N: slips the other way
  EXPECT_EQ(s.state, ContactState::slip_negative);
  EXPECT_DOUBLE_EQ(s.tangential, -50.0);
  EXPECT_NEAR(s.slider, 2.0e-5, 1e-18);

  s = jenkins_step(p, s.slider, 0.0, 0.0);  // second reversal, stuck again
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_NEAR(s.tangential, -20.0, 1e-9);
}

TEST(JenkinsContact, UnloadingTheNormalForceMakesAStuckContactSlip) {
  // A stuck contact carrying 40 N slips when N falls below 80 N (mu = 0.5) without tangential
  // motion: the Coulomb limit, not the tangential displacement, drives the transition.
  const auto& p = kContact;
  JenkinsStep s = jenkins_step(p, 0.0, 4.0e-5, 0.0);
  ASSERT_EQ(s.state, ContactState::stick);
  s = jenkins_step(p, s.slider, 4.0e-5, -4.0e-6);  // N = 60 N, limit 30 N
  EXPECT_EQ(s.state, ContactState::slip_positive);
  EXPECT_DOUBLE_EQ(s.normal, 60.0);
  EXPECT_DOUBLE_EQ(s.tangential, 30.0);
  s = jenkins_step(p, s.slider, 4.0e-5, 5.0e-6);  // reloading does not bring the force back
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_NEAR(s.tangential, 30.0, 1e-9);
}

TEST(JenkinsContact, LiftOffCarriesNoForceAndReSticksWithZeroTangentialForce) {
  const auto& p = kContact;
  JenkinsStep s = jenkins_step(p, 0.0, 3.0e-5, 0.0);
  ASSERT_EQ(s.state, ContactState::stick);
  ASSERT_GT(s.tangential, 0.0);

  s = jenkins_step(p, s.slider, 3.5e-5, -1.0e-5 - 1e-9);  // N0 + kn v < 0: open
  EXPECT_EQ(s.state, ContactState::lift_off);
  EXPECT_EQ(s.normal, 0.0);
  EXPECT_EQ(s.tangential, 0.0);
  EXPECT_EQ(s.slider, 3.5e-5);

  s = jenkins_step(p, s.slider, -7.0e-5, -2.0e-5);  // sliding freely while open
  EXPECT_EQ(s.state, ContactState::lift_off);
  EXPECT_EQ(s.tangential, 0.0);

  s = jenkins_step(p, s.slider, -7.0e-5, 0.0);  // closes where it is: no tangential force
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_DOUBLE_EQ(s.normal, 100.0);
  EXPECT_EQ(s.tangential, 0.0);

  s = jenkins_step(p, s.slider, -6.0e-5, 0.0);  // and the spring starts from there
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_NEAR(s.tangential, 10.0, 1e-9);
}

TEST(JenkinsContact, ExactlyZeroNormalLoadIsLiftOff) {
  // N0 = 0: v = 0 is touching without load, which carries no friction.
  PointParameters p = kContact;
  p.n0 = 0.0;
  JenkinsStep s = jenkins_step(p, 0.0, 1.0e-6, 0.0);
  EXPECT_EQ(s.state, ContactState::lift_off);
  EXPECT_EQ(s.tangential, 0.0);
  s = jenkins_step(p, s.slider, 2.0e-6, 1.0e-6);  // N = 10 N, limit 5 N; T* = 1 N
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_DOUBLE_EQ(s.normal, 10.0);
  EXPECT_NEAR(s.tangential, 1.0, 1e-12);
}

TEST(JenkinsContact, FrictionlessContactCarriesNoTangentialForce) {
  PointParameters p = kContact;
  p.mu = 0.0;
  double slider = 0.0;
  for (double u : {0.0, 1e-6, 1e-3, -1e-2, 5e-4}) {
    const JenkinsStep s = jenkins_step(p, slider, u, 1e-6);
    slider = s.slider;
    EXPECT_EQ(s.tangential, 0.0) << "u = " << u;
    EXPECT_DOUBLE_EQ(s.normal, 110.0);
    EXPECT_EQ(slider, u);
  }
}

TEST(JenkinsContact, VeryStiffTangentialSpringIsARigidCoulombContact) {
  // kt = 1e12 N/m: the elastic range mu N / kt is 5e-11 m, so any visible motion slips at
  // exactly +-mu N and a reversal of more than 1e-10 m flips the force.
  PointParameters p = kContact;
  p.kt = 1.0e12;
  JenkinsStep s = jenkins_step(p, 0.0, 1.0e-3, 0.0);
  EXPECT_EQ(s.state, ContactState::slip_positive);
  EXPECT_DOUBLE_EQ(s.tangential, 50.0);
  s = jenkins_step(p, s.slider, 1.0e-3 - 2.0e-11, 0.0);
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_NEAR(s.tangential, 30.0, 1e-3);  // 2e-11 m of unloading at 1e12 N/m, within rounding of u
  s = jenkins_step(p, s.slider, 1.0e-3 - 2.0e-10, 0.0);
  EXPECT_EQ(s.state, ContactState::slip_negative);
  EXPECT_DOUBLE_EQ(s.tangential, -50.0);
}

TEST(JenkinsContact, ForceNeverExceedsTheCoulombLimitAndNormalLoadIsNeverNegative) {
  // Random walks in (u, v) through every state, for soft, stiff, frictionless and unloaded contacts;
  // the force must obey the law of the state it reports.
  std::mt19937 rng(7);
  std::normal_distribution<double> step(0.0, 1.0);
  const std::vector<PointParameters> contacts = {kContact,
                                                 {.kn = 1e3, .kt = 1e12, .mu = 2.0, .n0 = 0.0},
                                                 {.kn = 1e12, .kt = 1e3, .mu = 0.1, .n0 = 1.0},
                                                 {.kn = 1e6, .kt = 1e6, .mu = 0.0, .n0 = 10.0}};
  std::vector<int> seen(4, 0);
  for (const auto& p : contacts) {
    const double du = 3.0 * (p.mu * p.n0 + 1.0) / p.kt, dv = 0.5 * (p.n0 + 1.0) / p.kn;
    double u = 0.0, v = 0.0, slider = 0.0;
    for (int i = 0; i < 20000; ++i) {
      u += du * step(rng);
      v = 0.9 * v + dv * step(rng);
      const JenkinsStep s = jenkins_step(p, slider, u, v);
      seen[static_cast<size_t>(s.state)]++;
      ASSERT_GE(s.normal, 0.0);
      ASSERT_EQ(s.normal, std::max(p.n0 + p.kn * v, 0.0));
      ASSERT_LE(std::abs(s.tangential), p.mu * s.normal) << "step " << i;
      switch (s.state) {
        case ContactState::stick:
          ASSERT_EQ(s.slider, slider);
          ASSERT_EQ(s.tangential, p.kt * (u - slider));
          break;
        case ContactState::slip_positive:
        case ContactState::slip_negative:
          ASSERT_EQ(std::abs(s.tangential), p.mu * s.normal);
          if (p.mu > 0.0) {
            ASSERT_EQ(s.tangential > 0.0, s.state == ContactState::slip_positive);
          }
          // The slider moved in the direction of the slip and the spring sits at the limit.
          ASSERT_EQ(s.slider > slider, s.state == ContactState::slip_positive);
          ASSERT_NEAR(p.kt * (u - s.slider), s.tangential, 1e-9 * (p.mu * s.normal + p.kt * std::abs(u)));
          break;
        case ContactState::lift_off:
          ASSERT_EQ(s.tangential, 0.0);
          ASSERT_EQ(s.normal, 0.0);
          ASSERT_EQ(s.slider, u);
          break;
      }
      slider = s.slider;
    }
  }
  for (int i = 0; i < 4; ++i) EXPECT_GT(seen[static_cast<size_t>(i)], 100) << state_name(static_cast<ContactState>(i));
}

TEST(JenkinsContact, TwoDimensionalContactSharesTheNormalLoadAndSlipsPerDirection) {
  const auto& p = kContact;
  // Direction 1 goes past the 5e-5 m elastic range, direction 2 stays inside it.
  JenkinsStep2D s = jenkins_step_2d(p, Eigen::Vector2d::Zero(), Eigen::Vector2d(8e-5, -3e-5), 2e-6);
  EXPECT_DOUBLE_EQ(s.normal, 120.0);
  EXPECT_EQ(s.state[0], ContactState::slip_positive);
  EXPECT_EQ(s.state[1], ContactState::stick);
  EXPECT_DOUBLE_EQ(s.tangential[0], 60.0);
  EXPECT_NEAR(s.tangential[1], -30.0, 1e-9);
  // Uncoupled: each direction is the 1D law with the shared N.
  const JenkinsStep second = jenkins_step(p, 0.0, -3e-5, 2e-6);
  EXPECT_EQ(s.tangential[1], second.tangential);
  // Both open together.
  s = jenkins_step_2d(p, s.slider, Eigen::Vector2d(1e-4, 1e-4), -2e-5);
  EXPECT_EQ(s.state[0], ContactState::lift_off);
  EXPECT_EQ(s.state[1], ContactState::lift_off);
  EXPECT_EQ(s.tangential, Eigen::Vector2d::Zero());
}

TEST(JenkinsContact, InvalidParametersAreRejected) {
  EXPECT_NO_THROW(validate(kContact));
  EXPECT_NO_THROW(validate({.kn = 0.0, .kt = 1.0, .mu = 0.0, .n0 = 0.0}));
  EXPECT_THROW(validate({.kn = 1.0, .kt = 0.0, .mu = 0.1, .n0 = 1.0}), std::invalid_argument);
  EXPECT_THROW(validate({.kn = -1.0, .kt = 1.0, .mu = 0.1, .n0 = 1.0}), std::invalid_argument);
  EXPECT_THROW(validate({.kn = 1.0, .kt = 1.0, .mu = -0.1, .n0 = 1.0}), std::invalid_argument);
  EXPECT_THROW(validate({.kn = 1.0, .kt = 1.0, .mu = 0.1, .n0 = -1.0}), std::invalid_argument);
  EXPECT_THROW(validate({.kn = 1.0, .kt = std::nan(""), .mu = 0.1, .n0 = 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace bb::friction
