// Time integration with friction contacts (timeint/contact_step, newmark, static_state, steady_state):
// the transitions of thesis Table XII from references/thesis/table12.csv, the friction oscillator's
// steady state against harmonic balance, the energy balance of a cycle, the shapes of stuck,
// slipping and separated hysteresis loops, a stiff contact at a step set by accuracy, the static
// initial state of eq 3.49 against the damper pre-solve, and a 31-DOF blades + damper run. Units: SI.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "common/csv_reader.hpp"
#include "damper/rigid_damper.hpp"
#include "damper_support.hpp"
#include "frf/receptance.hpp"
#include "hbm/harmonic_balance.hpp"
#include "timeint/contact_step.hpp"
#include "timeint/newmark.hpp"
#include "timeint/static_state.hpp"
#include "timeint/steady_state.hpp"

namespace bb::timeint {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using friction::ContactState;

ContactState state_from_table(const std::string& name) {
  if (name == "stick") return ContactState::stick;
  if (name == "positive_slip") return ContactState::slip_positive;
  if (name == "negative_slip") return ContactState::slip_negative;
  if (name == "separation") return ContactState::lift_off;
  ADD_FAILURE() << "unknown state " << name;
  return ContactState::stick;
}

TEST(TimeContact, TableXiiTransitionsOfThePredictorCorrectorSlider) {
  // Bodies 1 and 2 at the contact point, DOFs q = (t1, t2, n1, n2): u = t1 - t2 (eq 3.44's s* is
  // the slider relative to body 2), v = n1 - n2 (eq 3.45).
  friction::ContactElement c{.point = {.kn = 1e6, .kt = 2e6, .mu = 0.5, .n0 = 0.0},
                             .tangential = Eigen::RowVector4d(1.0, -1.0, 0.0, 0.0),
                             .normal = Eigen::RowVector4d(0.0, 0.0, 1.0, -1.0)};
  const std::filesystem::path file = std::filesystem::path(BB_SOURCE_DIR) / "references" / "thesis" / "table12.csv";
  CsvReader<12> in(file.string());
  in.read_header(io::ignore_extra_column, "transition", "state_before", "s_before", "t2_before", "t1", "t2", "n1", "n2",
                 "state_after", "s_after", "T", "N");
  std::string name, before, after;
  double s0, t20, t1, t2, n1, n2, s1, t, n;
  int rows = 0;
  std::vector<ContactState> reached;
  while (in.read_row(name, before, s0, t20, t1, t2, n1, n2, after, s1, t, n)) {
    ++rows;
    (void)state_from_table(before);
    const ContactSample r = contact_step(c, s0 - t20, Eigen::Vector4d(t1, t2, n1, n2));
    const double scale = 1e-12;
    EXPECT_EQ(r.state, state_from_table(after)) << name;
    EXPECT_NEAR(r.slider + t2, s1, 1e-18) << name << ": Table XII slider s(1) = s*(1) + t2(1)";
    EXPECT_NEAR(r.tangential, t, scale * 10.0) << name;
    EXPECT_NEAR(r.normal, n, scale * 10.0) << name;
    // The Table's own formula for T in every state: kt (t1 - s) when stuck, +-mu N when slipping.
    if (r.state == ContactState::stick) {
      EXPECT_NEAR(r.tangential, c.point.kt * (t1 - s1), 1e-9) << name;
    }
    if (r.state == ContactState::lift_off) {
      EXPECT_EQ(r.slider + t2, t1) << name;
    }
    reached.push_back(r.state);
  }
  EXPECT_EQ(rows, 13);
  for (const ContactState s :
       {ContactState::stick, ContactState::slip_positive, ContactState::slip_negative, ContactState::lift_off})
    EXPECT_NE(std::find(reached.begin(), reached.end(), s), reached.end()) << state_name(s);
}

TEST(TimeContact, ConsistentTangentIsTheDerivativeOfTheSlider) {
  const friction::ContactElement c{.point = {.kn = 3e5, .kt = 1e6, .mu = 0.4, .n0 = 20.0},
                                   .tangential = Eigen::RowVector2d(1.0, 0.0),
                                   .normal = Eigen::RowVector2d(0.0, 1.0)};
  for (const Eigen::Vector2d& q : {Eigen::Vector2d(2e-6, 1e-5), Eigen::Vector2d(3e-5, 1e-5),
                                   Eigen::Vector2d(-3e-5, -2e-5), Eigen::Vector2d(1e-5, -1e-4)}) {
    const ContactSample s = contact_step(c, 0.0, q);
    const ContactTangent& d = s.tangent;
    const double h = 1e-12;
    const ContactSample su = contact_step(c, 0.0, Eigen::Vector2d(q + Eigen::Vector2d(h, 0.0)));
    const ContactSample sv = contact_step(c, 0.0, Eigen::Vector2d(q + Eigen::Vector2d(0.0, h)));
    EXPECT_NEAR((su.tangential - s.tangential) / h, d.dt_du, 1e-6 * c.point.kt) << state_name(s.state);
    EXPECT_NEAR((sv.tangential - s.tangential) / h, d.dt_dv, 1e-6 * c.point.kt) << state_name(s.state);
    EXPECT_NEAR((sv.normal - s.normal) / h, d.dn_dv, 1e-6 * c.point.kt) << state_name(s.state);
  }
}

// m x'' + c x' + k x + T = F cos(w t), ground contact u = x at constant N0 (a_n = 0).
struct Oscillator {
  double m = 1.0, k = 1.0e4, zeta = 0.02, force = 3.0;
  friction::PointParameters point{.kn = 0.0, .kt = 2.0e4, .mu = 0.5, .n0 = 2.0};
  double c() const { return 2.0 * zeta * std::sqrt(k * m); }
  friction::FrictionModel model() const {
    friction::FrictionModel mo;
    mo.mass = MatrixXd::Constant(1, 1, m);
    mo.damping = MatrixXd::Constant(1, 1, c());
    mo.stiffness = MatrixXd::Constant(1, 1, k);
    mo.contacts.push_back(
        {.point = point, .tangential = Eigen::RowVectorXd::Ones(1), .normal = Eigen::RowVectorXd::Zero(1)});
    mo.harmonic_load = Eigen::VectorXcd::Constant(1, force);
    return mo;
  }
  double hbm_amplitude(double omega, int harmonics = 7) const {
    const hbm::HbmSolution s = hbm::solve_at_frequency(hbm::HarmonicBalance(model(), {.harmonics = harmonics}), omega);
    EXPECT_TRUE(s.converged) << s.failure;
    return std::hypot(s.x[1], s.x[2]);  // one contact DOF: x holds its harmonics
  }
};

SteadyState oscillator_steady_state(const Oscillator& o, double omega, int steps_per_period = 512) {
  SteadyStateOptions opt{.dofs = {0}, .steps_per_period = steps_per_period, .harmonics = 7, .tolerance = 1e-8};
  const SteadyState s = steady_state(o.model(), omega, opt);
  EXPECT_TRUE(s.converged) << s.failure;
  return s;
}

double loop_area(const std::vector<ContactSample>& loop) {
  double area = 0.0;
  for (size_t i = 1; i < loop.size(); ++i)
    area += 0.5 * (loop[i].tangential + loop[i - 1].tangential) * (loop[i].u - loop[i - 1].u);
  return area;
}

TEST(TimeContact, FrictionOscillatorSteadyStateMatchesHarmonicBalanceAndBalancesEnergy) {
  const Oscillator o;
  for (const double omega : {90.0, 110.0, 140.0, 175.0}) {
    const SteadyState s = oscillator_steady_state(o, omega);
    const double hbm = o.hbm_amplitude(omega);
    const double a = s.amplitude(0, 1);
    const double area = loop_area(s.contacts[0]);
    const double balance = s.cycle_work.excitation - s.cycle_work.viscous;
    std::printf(
        "  omega %5.1f: A1 time %.6e m, HBM(H=7) %.6e m, diff %+.2e; %d periods, max %d Newton it.; "
        "loop area %.6e J, W_ext - W_visc %.6e J (rel %.1e), A3/A1 %.3f\n",
        omega, a, hbm, a / hbm - 1.0, s.cycles, s.max_iterations, area, balance, std::abs(area - balance) / area,
        s.amplitude(0, 3) / a);
    EXPECT_NEAR(a, hbm, 0.01 * hbm);
    EXPECT_NEAR(s.cycle_work.friction, area, 1e-12 * area);
    EXPECT_GT(area, 0.0);
    EXPECT_NEAR(area, balance, 1e-3 * area);
    EXPECT_LE(s.max_iterations, 5);
  }
}

TEST(TimeContact, FrictionOscillatorAmplitudeConvergesWithStepsPerPeriod) {
  // Observed order of the first-harmonic amplitude in dt (printed; the stick-slip kinks are resolved
  // to first order within a step, so between 1 and 2 is expected), and the sweep warm start.
  const Oscillator o;
  const double omega = 110.0;
  const double reference = oscillator_steady_state(o, omega, 4096).amplitude(0, 1);
  double previous = 0.0;
  for (const int n : {64, 128, 256, 512}) {
    const double e = std::abs(oscillator_steady_state(o, omega, n).amplitude(0, 1) - reference);
    if (previous > 0.0)
      std::printf("  %4d steps/period: |A1 - A1(4096)| = %.3e m, order %.2f\n", n, e, std::log2(previous / e));
    previous = e;
  }
  EXPECT_LT(previous, 1e-3 * reference);
  // The next frequency of a sweep starts from the previous final state: fewer periods than from rest.
  SteadyStateOptions opt{.dofs = {0}, .steps_per_period = 256, .harmonics = 3, .tolerance = 1e-8};
  const SteadyState first = steady_state(o.model(), omega, opt);
  const SteadyState warm = steady_state(o.model(), omega * 1.01, opt, first.final_state);
  const SteadyState cold = steady_state(o.model(), omega * 1.01, opt);
  ASSERT_TRUE(warm.converged && cold.converged);
  std::printf("  sweep step 1%%: %d periods from the previous state, %d from rest\n", warm.cycles, cold.cycles);
  EXPECT_LT(warm.cycles, cold.cycles);
  EXPECT_NEAR(warm.amplitude(0, 1), cold.amplitude(0, 1), 1e-6 * cold.amplitude(0, 1));
}

TEST(TimeContact, StuckLoopIsALineOfSlopeKt) {
  Oscillator o;
  o.force = 0.05;  // kt |x| stays well below mu N0 = 1 N
  const SteadyState s = oscillator_steady_state(o, 150.0);
  const auto& loop = s.contacts[0];
  double umin = 1e9, umax = -1e9, tmin = 1e9, tmax = -1e9, off_line = 0.0;
  for (const ContactSample& p : loop) {
    EXPECT_EQ(p.state, ContactState::stick);
    EXPECT_EQ(p.slider, loop.front().slider);
    off_line = std::max(off_line, std::abs(p.tangential - o.point.kt * (p.u - p.slider)));
    if (p.u < umin) {
      umin = p.u;
      tmin = p.tangential;
    }
    if (p.u > umax) {
      umax = p.u;
      tmax = p.tangential;
    }
  }
  EXPECT_NEAR((tmax - tmin) / (umax - umin), o.point.kt, 1e-9 * o.point.kt);
  EXPECT_LT(off_line, 1e-12);
  // No hysteresis: what remains is the end-point mismatch of a loop closed to the steady-state tolerance.
  EXPECT_NEAR(loop_area(loop), 0.0, 1e-6 * (tmax - tmin) * (umax - umin));
  EXPECT_LT(std::abs(tmax), o.point.mu * o.point.n0);
}

TEST(TimeContact, SlippingLoopHasPlateausAtPlusMinusMuN) {
  const Oscillator o;
  const SteadyState s = oscillator_steady_state(o, 110.0);
  const double limit = o.point.mu * o.point.n0;
  int positive = 0, negative = 0, stuck = 0;
  double tmax = -1e9, tmin = 1e9;
  for (const ContactSample& p : s.contacts[0]) {
    tmax = std::max(tmax, p.tangential);
    tmin = std::min(tmin, p.tangential);
    if (p.state == ContactState::slip_positive) {
      ++positive;
      EXPECT_EQ(p.tangential, limit);
    } else if (p.state == ContactState::slip_negative) {
      ++negative;
      EXPECT_EQ(p.tangential, -limit);
    } else {
      ++stuck;
      EXPECT_LT(std::abs(p.tangential), limit);
    }
  }
  std::printf("  samples: %d slip+, %d slip-, %d stick\n", positive, negative, stuck);
  EXPECT_GT(positive, 10);
  EXPECT_GT(negative, 10);
  EXPECT_GT(stuck, 10);  // the reversals stick before slipping back
  EXPECT_EQ(tmax, limit);
  EXPECT_EQ(tmin, -limit);
}

Eigen::RowVectorXd unit_row(Eigen::Index n, Eigen::Index i) {
  Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(n);
  r[i] = 1.0;
  return r;
}

// The 3-DOF blade of tests/unit/hbm_harmonic_balance_test.cpp: DOF 0 excited, the platform
// (DOF 1 tangential, DOF 2 normal) on the ground; the normal load varies with q2.
friction::FrictionModel blade_on_ground(double force) {
  friction::FrictionModel m;
  m.stiffness.resize(3, 3);
  m.stiffness << 2.0e6, -5.0e5, -2.0e5, -5.0e5, 1.5e6, 3.0e5, -2.0e5, 3.0e5, 1.0e6;
  m.mass = Eigen::Vector3d(1.0, 0.4, 0.3).asDiagonal();
  m.damping = modal_damping_matrix(m.stiffness, m.mass, 0.02);
  m.contacts.push_back({.point = {.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 30.0},
                        .tangential = unit_row(3, 1),
                        .normal = unit_row(3, 2)});
  m.static_load = Eigen::Vector3d::Zero();
  m.harmonic_load = Eigen::VectorXcd::Zero(3);
  m.harmonic_load[0] = force;
  return m;
}

TEST(TimeContact, MultiDofVariableNormalLoadMatchesHarmonicBalance) {
  // First harmonics of every DOF against hbm::solve_at_frequency (H = 7), the normal load varying
  // with the motion (the slip tangent's mu kn coupling at work), stick-slip and micro-slip.
  for (const double force : {25.0, 100.0}) {
    const friction::FrictionModel m = blade_on_ground(force);
    const hbm::HarmonicBalance system(m, {.harmonics = 7, .tolerance = 1e-10});
    for (const double omega : {1000.0, 1300.0, 1800.0}) {
      const hbm::HbmSolution h = hbm::solve_at_frequency(system, omega);
      ASSERT_TRUE(h.converged) << h.failure;
      const MatrixXd q = system.recover(h.x, omega);
      const SteadyState s =
          steady_state(m, omega, {.dofs = {0, 1, 2}, .steps_per_period = 512, .harmonics = 7, .tolerance = 1e-8});
      ASSERT_TRUE(s.converged) << s.failure;
      const double e = (s.coefficients.middleCols(1, 2) - q.middleCols(1, 2)).norm() / q.middleCols(1, 2).norm();
      int slipping = 0;
      for (const ContactSample& p : s.contacts[0])
        slipping += p.state == ContactState::slip_positive || p.state == ContactState::slip_negative;
      std::printf(
          "  F %5.1f N, omega %6.0f: |first harmonics time - HBM| / |HBM| = %.2e, %d of %zu samples slip, "
          "%d periods, max %d Newton it.\n",
          force, omega, e, slipping, s.contacts[0].size(), s.cycles, s.max_iterations);
      EXPECT_LT(e, 0.01);
      EXPECT_NEAR(s.cycle_work.excitation - s.cycle_work.viscous, s.cycle_work.friction + s.cycle_work.normal,
                  1e-6 * s.cycle_work.excitation);
    }
  }
}

// The blade + rigid damper of tests/unit/hbm_harmonic_balance_test.cpp (zeta 0.01 here): damper DOFs 3 (tangential)
// and 4 (normal) held only by two contacts (platform and a fixed neighbour), pressed by 40 N.
friction::FrictionModel blade_with_damper(double force) {
  friction::FrictionModel m;
  m.stiffness = MatrixXd::Zero(5, 5);
  m.stiffness.topLeftCorner(3, 3) << 2.0e6, -5.0e5, -2.0e5, -5.0e5, 1.5e6, 3.0e5, -2.0e5, 3.0e5, 1.0e6;
  m.mass = (VectorXd(5) << 1.0, 0.4, 0.3, 0.05, 0.05).finished().asDiagonal();
  m.damping = MatrixXd::Zero(5, 5);
  m.damping.topLeftCorner(3, 3) =
      modal_damping_matrix(m.stiffness.topLeftCorner(3, 3), m.mass.topLeftCorner(3, 3), 0.01);
  // Unlike the HBM test, the damper gets a little damping of its own (1% of critical on its contact
  // springs): undamped damper modes make the transient from rest last thousands of periods.
  m.damping(3, 3) = m.damping(4, 4) = 2.0 * 0.01 * std::sqrt(2.0e6 * 0.05);
  const friction::PointParameters law{.kn = 2.0e6, .kt = 1.0e6, .mu = 0.4, .n0 = 0.0};
  m.contacts.push_back(
      {.point = law, .tangential = unit_row(5, 1) - unit_row(5, 3), .normal = unit_row(5, 4) - unit_row(5, 2)});
  m.contacts.push_back({.point = law, .tangential = unit_row(5, 3), .normal = unit_row(5, 4)});
  m.static_load = VectorXd::Zero(5);
  m.static_load[4] = 40.0;
  m.harmonic_load = Eigen::VectorXcd::Zero(5);
  m.harmonic_load[1] = std::complex<double>(0.0, -force);  // force sin(omega t) on the platform
  return m;
}

TEST(TimeContact, DamperHeldOnlyByFrictionMatchesHarmonicBalance) {
  // Compared wherever both domains find a periodic response; where either does not, the reason is
  // printed (the time domain shows why: the damper walks, see the next test).
  // K is singular without the contacts' tangential springs: the static state needs the contacts
  // stuck at their offsets (StaticFriction::stuck_at_offset); the free-slip one must say so.
  const friction::FrictionModel m0 = blade_with_damper(20.0);
  const StaticState free = static_initial_state(m0);
  EXPECT_FALSE(free.converged);
  EXPECT_NE(free.failure.find("stuck_at_offset"), std::string::npos) << free.failure;
  int compared = 0;
  for (const double force : {2.0, 20.0, 100.0}) {
    const friction::FrictionModel m = blade_with_damper(force);
    const hbm::HarmonicBalance system(m, {.harmonics = 7, .tolerance = 1e-10});
    for (const double omega : {700.0, 1000.0, 1300.0, 1800.0}) {
      SteadyStateOptions opt{.dofs = {0, 1, 2, 3, 4},
                             .steps_per_period = 256,
                             .harmonics = 7,
                             .tolerance = 1e-8,
                             .ignore_drift = true,
                             .max_cycles = 400};
      opt.initial.friction = StaticFriction::stuck_at_offset;
      const SteadyState s = steady_state(m, omega, opt);
      ASSERT_TRUE(s.final_state.displacement.allFinite());
      if (!s.converged) {  // printed, not hidden: no periodic response within the cap
        std::printf("  damper F %5.1f N, omega %6.0f: time domain: %s\n", force, omega, s.failure.c_str());
        continue;
      }
      const hbm::HbmSolution h = hbm::solve_at_frequency(system, omega);
      if (!h.converged) {
        std::printf(
            "  damper F %5.1f N, omega %6.0f: HBM not converged (%s); time A1(q1) %.4e m, damper drift %.2e "
            "m/period\n",
            force, omega, h.failure.c_str(), s.amplitude(1, 1), s.drift[3]);
        continue;
      }
      const MatrixXd q = system.recover(h.x, omega);
      const double e = (s.coefficients.middleCols(1, 2) - q.middleCols(1, 2)).norm() / q.middleCols(1, 2).norm();
      std::printf(
          "  damper F %5.1f N, omega %6.0f: |first harmonics time - HBM| / |HBM| = %.2e, %d periods, max %d "
          "Newton it., damper drift %.2e m/period\n",
          force, omega, e, s.cycles, s.max_iterations, s.drift[3]);
      ++compared;
      EXPECT_LT(e, 0.01);
    }
  }
  EXPECT_GE(compared, 6);  // measured: the six points of F = 2 and 20 N where neither walks
}

TEST(TimeContact, WalkingDamperIsReportedAsDriftNotAsASteadyState) {
  // F = 20 N at 1300 rad/s: the oscillation becomes periodic while the damper's mean position moves
  // by the same amount every period (ratcheting). Without ignore_drift the run must say so.
  const friction::FrictionModel m = blade_with_damper(20.0);
  SteadyStateOptions opt{.dofs = {0, 1, 2, 3, 4},
                         .steps_per_period = 256,
                         .harmonics = 3,
                         .tolerance = 1e-8,
                         .min_cycles = 2,
                         .max_cycles = 300};
  opt.initial.friction = StaticFriction::stuck_at_offset;
  const SteadyState walking = steady_state(m, 1300.0, opt);
  EXPECT_FALSE(walking.converged);
  EXPECT_NE(walking.failure.find("drift"), std::string::npos) << walking.failure;
  opt.ignore_drift = true;
  const SteadyState periodic = steady_state(m, 1300.0, opt);
  ASSERT_TRUE(periodic.converged) << periodic.failure;
  std::printf("  walking damper: drift %.3e m per period (blade DOFs %.1e), oscillation A1(q3) %.3e m\n",
              periodic.drift[3], periodic.drift.head(3).cwiseAbs().maxCoeff(), periodic.amplitude(3, 1));
  EXPECT_GT(std::abs(periodic.drift[3]), 1e-3 * periodic.amplitude(3, 1));
  EXPECT_LT(periodic.drift.head(3).cwiseAbs().maxCoeff(), 1e-6 * std::abs(periodic.drift[3]));
}

// DOF 0 tangential (platform), DOF 1 normal; contact u = q0, v = q1, N = max(N0 + kn q1, 0).
friction::FrictionModel platform(double static_normal, double normal_force) {
  friction::FrictionModel m;
  m.mass = Eigen::Vector2d(0.5, 0.5).asDiagonal();
  m.stiffness = Eigen::Vector2d(1e4, 1e4).asDiagonal();
  m.damping = 2.0 * 0.02 * std::sqrt(1e4 * 0.5) * MatrixXd::Identity(2, 2);
  m.contacts.push_back({.point = {.kn = 1e5, .kt = 1e4, .mu = 0.5, .n0 = 2.0},
                        .tangential = Eigen::RowVector2d(1.0, 0.0),
                        .normal = Eigen::RowVector2d(0.0, 1.0)});
  m.static_load = Eigen::Vector2d(0.0, static_normal);
  m.harmonic_load = Eigen::Vector2cd(1.0, normal_force);
  return m;
}

TEST(TimeContact, SeparatedContactCarriesNoForce) {
  // Pulled away: N0 + kn v < 0 all the time.
  const SteadyStateOptions opt{.dofs = {0, 1}, .steps_per_period = 256, .harmonics = 3, .tolerance = 1e-8};
  const SteadyState open = steady_state(platform(-10.0, 1.0), 120.0, opt);
  ASSERT_TRUE(open.converged) << open.failure;
  for (const ContactSample& p : open.contacts[0]) {
    EXPECT_EQ(p.state, ContactState::lift_off);
    EXPECT_EQ(p.tangential, 0.0);
    EXPECT_EQ(p.normal, 0.0);
  }
  EXPECT_EQ(open.cycle_work.friction, 0.0);
  // Opening and closing within each period: the force vanishes exactly while open.
  const SteadyState partial = steady_state(platform(0.0, 6.0), 120.0, opt);
  ASSERT_TRUE(partial.converged) << partial.failure;
  int opened = 0, closed = 0;
  for (const ContactSample& p : partial.contacts[0]) {
    const bool gap = 2.0 + 1e5 * p.v <= 0.0;
    EXPECT_EQ(p.state == ContactState::lift_off, gap);
    if (gap) {
      ++opened;
      EXPECT_EQ(p.tangential, 0.0);
      EXPECT_EQ(p.normal, 0.0);
      EXPECT_EQ(p.slider, p.u);  // follows the surface: re-closes with zero tangential force
    } else {
      ++closed;
    }
  }
  std::printf(
      "  partial separation: %d samples open, %d closed, %d periods, loop area %.3e J, "
      "W_ext - W_visc - W_normal %.3e J\n",
      opened, closed, partial.cycles, loop_area(partial.contacts[0]),
      partial.cycle_work.excitation - partial.cycle_work.viscous - partial.cycle_work.normal);
  EXPECT_GT(opened, 5);
  EXPECT_GT(closed, 5);
}

TEST(TimeContact, StiffContactNeedsNoSmallerStepThanAccuracyAsks) {
  // kt = 1e9 N/m on a 1e4 N/m oscillator: the stuck contact's own period is 200 times shorter than
  // the time step at 64 steps per excitation period. The implicit step and the consistent tangent
  // keep Newton bounded; HHT alpha = -0.1 damps the unresolved contact frequency.
  Oscillator o;
  o.point.kt = 1e9;
  for (const double alpha : {0.0, -0.1}) {
    SteadyStateOptions opt{.dofs = {0}, .steps_per_period = 64, .harmonics = 7, .tolerance = 1e-7};
    opt.newmark.alpha = alpha;
    const SteadyState s = steady_state(o.model(), 110.0, opt);
    ASSERT_TRUE(s.converged) << s.failure;
    const double hbm = o.hbm_amplitude(110.0, 7);
    std::printf(
        "  kt 1e9, alpha %+.1f, 64 steps/period: A1 %.5e (HBM %.5e, %+.2e), %d periods, %ld Newton "
        "iterations, max %d per step\n",
        alpha, s.amplitude(0, 1), hbm, s.amplitude(0, 1) / hbm - 1.0, s.cycles, s.total_iterations, s.max_iterations);
    EXPECT_LE(s.max_iterations, 10);
    EXPECT_NEAR(s.amplitude(0, 1), hbm, 0.02 * hbm);
  }
}

TEST(TimeContact, FailedStepStopsTheRunWithTimeAndResidual) {
  Oscillator o;
  friction::FrictionModel m = o.model();
  const NewmarkIntegrator integrator(m, {.time_step = 1e-3, .max_iterations = 1, .tolerance = 1e-300});
  const Excitation f = harmonic_excitation(m.harmonic_load, 100.0);
  const TimeHistory h = integrate(integrator, integrator.initial_state(VectorXd::Zero(1), VectorXd::Zero(1), 0.0, f), f,
                                  100, {.dofs = {0}});
  EXPECT_FALSE(h.converged);
  EXPECT_NE(h.failure.find("t = "), std::string::npos) << h.failure;
  EXPECT_NE(h.failure.find("|R| = "), std::string::npos) << h.failure;
  EXPECT_TRUE(h.final_state.displacement.allFinite());
}

// 28 blade DOFs (a random well-conditioned SPD pair, ~1 kHz) plus the rigid damper of
// damper_support.hpp pressed by CF = 300 N: the size of the thesis's 31-DOF model (eq 3.43).
struct BladesAndDamper {
  friction::FrictionModel model;
  damper::RigidDamper damper;
  MatrixXd blade_stiffness;
};

BladesAndDamper blades_and_damper() {
  const int nb = 28;
  std::srand(7);
  const MatrixXd a = MatrixXd::Random(nb, nb);
  BladesAndDamper out;
  out.blade_stiffness = 1e6 * (a * a.transpose() / nb + MatrixXd::Identity(nb, nb));
  const MatrixXd blade_mass = 0.02 * MatrixXd::Identity(nb, nb);
  damper::AsymmetricDamperGeometry g = damper::test::asymmetric_geometry();
  g.l1_x = 0, g.l1_y = 1, g.l2_x = 2, g.l2_y = 3, g.r_x = 4, g.r_y = 5;
  out.damper = damper::asymmetric_damper(g);
  const damper::CoupledSystem sys = damper::assemble_coupled_system(blade_mass, out.blade_stiffness, out.damper);
  const damper::ContactKinematics kin = damper::contact_kinematics(out.damper, nb);
  friction::FrictionModel& m = out.model;
  m.mass = sys.mass;
  m.stiffness = sys.stiffness;
  m.damping = 1e-5 * sys.stiffness;
  for (Eigen::Index c = 0; c < kin.tangential.rows(); ++c)
    m.contacts.push_back({.point = {.kn = 2e7, .kt = 2e7, .mu = 0.3, .n0 = 0.0},
                          .tangential = kin.tangential.row(c),
                          .normal = kin.normal.row(c)});
  m.static_load = damper::centrifugal_load(nb, 300.0);
  m.harmonic_load = Eigen::VectorXcd::Zero(nb + 3);
  m.harmonic_load[0] = 200.0;  // on the platform point under L1
  return out;
}

TEST(TimeContact, StaticInitialStateWithoutFrictionEqualsTheDamperPreSolve) {
  const BladesAndDamper b = blades_and_damper();
  const StaticState s = static_initial_state(b.model);
  ASSERT_TRUE(s.converged) << s.failure;
  const damper::DamperStaticState d =
      damper::solve_damper_static(b.blade_stiffness, b.damper, b.model.static_load, {.kn = 2e7});
  ASSERT_TRUE(d.converged) << d.failure;
  EXPECT_LT((s.q - d.q).norm(), 1e-9 * d.q.norm());
  for (size_t c = 0; c < s.contacts.size(); ++c) {
    EXPECT_NEAR(s.contacts[c].normal, d.normal_preload[static_cast<Eigen::Index>(c)], 1e-8 * 300.0);
    EXPECT_EQ(s.contacts[c].tangential, 0.0);  // closed with zero tangential force
  }
}

TEST(TimeContact, ThirtyOneDofBladesAndDamperRunReportsIterationsAndCost) {
  const BladesAndDamper b = blades_and_damper();
  const StaticState s0 = static_initial_state(b.model);
  ASSERT_TRUE(s0.converged) << s0.failure;
  const double omega = 2.0 * std::numbers::pi * 1000.0;
  const NewmarkIntegrator integrator(b.model, {.time_step = 2.0 * std::numbers::pi / omega / 128});
  const Excitation f = harmonic_excitation(b.model.harmonic_load, omega);
  const DynamicState start = integrator.initial_state(s0.q, VectorXd::Zero(31), 0.0, f, s0.sliders);
  const int steps = 128 * 40;
  const auto t0 = std::chrono::steady_clock::now();
  const TimeHistory h = integrate(integrator, start, f, steps, {.dofs = {0, 28, 29, 30}});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(h.converged) << h.failure;
  int slipping = 0;
  for (const auto& history : h.contacts)
    for (const ContactSample& p : history)
      slipping += p.state == ContactState::slip_positive || p.state == ContactState::slip_negative;
  std::printf(
      "  31 DOF, %zu contact DOFs, %d steps: %ld Newton iterations (max %d per step), %d contact-samples "
      "slipping, %.2f us per step\n",
      integrator.contact_dofs().size(), h.steps, h.total_iterations, h.max_iterations, slipping,
      1e6 * seconds / h.steps);
  EXPECT_EQ(h.steps, steps);
  EXPECT_GT(slipping, 0);
  EXPECT_LE(h.max_iterations, 15);
  // Energy bookkeeping of the average-acceleration rule: exact to round-off, contacts included
  // (their elastic energy is recovered from the slider: 1/2 T^2 / kt + 1/2 N^2 / kn is path-free
  // only in stick, so compare the ledger with the mechanical energy change plus the contact work).
  const DynamicState& e = h.final_state;
  const double lhs = integrator.mechanical_energy(e) - integrator.mechanical_energy(start);
  const double rhs = e.work.excitation - e.work.viscous - e.work.friction - e.work.normal;
  EXPECT_NEAR(lhs, rhs, 1e-9 * std::max(std::abs(e.work.excitation), 1e-12));
}

}  // namespace
}  // namespace bb::timeint
