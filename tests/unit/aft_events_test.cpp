// Event-resolved AFT (friction/aft_events): the closed-form describing function to rounding at 16
// sample intervals, coefficients independent of the sample count where the sampled AFT converges
// as 1 / n, the energy of a loop with lift-off against a fine march, and the Jacobian and the law
// derivatives against central differences at every column: the map is smooth, so no column is
// skipped. Units: SI.
#include "friction/aft_events.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "common/constants.hpp"
#include "fourier_series.hpp"
#include "friction/jenkins.hpp"

namespace bb::friction {
namespace {

AftOptions events(int samples) {
  AftOptions o;
  o.samples = samples;
  o.resolve_events = true;
  return o;
}

// u and v out of phase with second harmonics: the contact opens for part of the cycle, slips under
// a varying limit and re-sticks (as aft_test.cpp's lift-off loop).
const PointParameters kLiftOff{.kn = 1e7, .kt = 1e6, .mu = 0.6, .n0 = 100.0};
Eigen::VectorXd lift_off_u() {
  Eigen::VectorXd u(5);
  u << 1e-5, 2e-4, 1e-4, 3e-5, -2e-5;
  return u;
}
Eigen::VectorXd lift_off_v() {
  Eigen::VectorXd v(5);
  v << 0.0, 5e-6, -1.2e-5, 2e-6, 1e-6;
  return v;
}

TEST(AftEvents, FirstHarmonicIsTheDescribingFunctionAtSixteenSamples) {
  const PointParameters p{.kn = 0.0, .kt = 1.0e6, .mu = 0.5, .n0 = 100.0};  // F = 50 N
  double worst = 0.0;
  for (double ratio : {0.5, 1.1, 2.0, 5.0, 50.0})
    for (double phase : {0.0, 0.7, 2.9}) {
      const double amplitude = ratio * 5.0e-5;
      Eigen::VectorXd u = Eigen::VectorXd::Zero(7);
      u[1] = amplitude * std::cos(phase);
      u[2] = amplitude * std::sin(phase);
      const AftResult r = aft_jenkins(p, u, Eigen::VectorXd::Zero(7), events(16));
      ASSERT_TRUE(r.closed);
      const Eigen::Vector2d d = describing_function(amplitude, p.kt, 50.0);
      const Eigen::Vector2d exact(d[0] * std::cos(phase) - d[1] * std::sin(phase),
                                  d[0] * std::sin(phase) + d[1] * std::cos(phase));
      const double error = (r.tangential.segment<2>(1) - exact).norm() / (p.kt * amplitude);
      worst = std::max(worst, error);
      EXPECT_LT(error, 1e-9) << "U / (mu N / kt) = " << ratio << ", phase " << phase;
    }
  std::printf("[ describing function ] events, n = 16: worst |T1 - T1_exact| / (kt U) = %.2e\n", worst);
}

TEST(AftEvents, CoefficientsDoNotDependOnTheSampleCount) {
  const Eigen::VectorXd u = lift_off_u(), v = lift_off_v();
  const AftResult fine = aft_jenkins(kLiftOff, u, v, events(16384));
  const double scale = fine.tangential.norm();
  for (int samples : {32, 64, 256}) {
    const AftResult r = aft_jenkins(kLiftOff, u, v, events(samples));
    const AftOptions plain{.samples = samples};
    const AftResult sampled = aft_jenkins(kLiftOff, u, v, plain);
    const double error = (r.tangential - fine.tangential).norm() / scale;
    const double sampled_error = (sampled.tangential - fine.tangential).norm() / scale;
    std::printf("[ samples ] n = %5d: events %.2e, sampled %.2e (relative to n = 16384 with events)\n", samples, error,
                sampled_error);
    EXPECT_LT(error, samples >= 64 ? 1e-6 : 1e-4);
    EXPECT_LT(error, sampled_error / 100.0);
  }
}

TEST(AftEvents, EnergyWithLiftOffIsTheIntegralOfTdu) {
  const Eigen::VectorXd u = lift_off_u(), v = lift_off_v();
  const AftResult r = aft_jenkins(kLiftOff, u, v, events(128));
  ASSERT_TRUE(r.closed);
  int open = 0;
  for (ContactState s : r.state) open += s == ContactState::lift_off;
  EXPECT_GT(open, 5);
  // Reference: the step law marched at 4e6 steps (error O(1e-7) of W).
  double slider = 0.0, work = 0.0, previous_t = 0.0, previous_u = 0.0;
  const int steps = 4000000;
  for (int k = 0; k <= 2 * steps; ++k) {
    const double theta = 2.0 * kPi * k / steps, uk = evaluate(u, theta);
    const JenkinsStep s = jenkins_step(kLiftOff, slider, uk, evaluate(v, theta));
    slider = s.slider;
    if (k > steps) work += 0.5 * (s.tangential + previous_t) * (uk - previous_u);
    previous_t = s.tangential;
    previous_u = uk;
  }
  const double w = cycle_work(r.tangential, u);
  std::printf("[ energy, lift-off ] events n = 128: %.9e J, march 4e6 steps: %.9e J, rel. diff %.2e\n", w, work,
              std::abs(w - work) / work);
  EXPECT_NEAR(w, work, 1e-6 * work);
}

struct EventRegime {
  const char* name;
  PointParameters p;
  double u_amplitude, v_amplitude, u_cos, v_cos;
};

const std::vector<EventRegime>& regimes() {
  static const std::vector<EventRegime> all = {
      {"stick", {.kn = 1e6, .kt = 1e6, .mu = 0.5, .n0 = 1000.0}, 1e-5, 1e-5, 0.0, 0.0},
      {"stick-slip", {.kn = 1e6, .kt = 1e6, .mu = 0.5, .n0 = 1000.0}, 1e-3, 1e-5, 2.5e-3, 0.0},
      {"partial lift-off", {.kn = 1e7, .kt = 1e6, .mu = 0.5, .n0 = 1000.0}, 1e-3, 1e-5, 2.5e-3, 2e-4}};
  return all;
}

TEST(AftEvents, JacobianMatchesCentralDifferencesAtEveryColumn) {
  std::mt19937 rng(2024);
  double worst = 0.0;
  int checked = 0;
  for (int harmonics : {1, 3})
    for (const EventRegime& regime : regimes())
      for (int trial = 0; trial < 4; ++trial) {
        const Eigen::Index m = harmonic_size(harmonics);
        Eigen::VectorXd u = random_coefficients(rng, harmonics, regime.u_amplitude);
        Eigen::VectorXd v = random_coefficients(rng, harmonics, regime.v_amplitude);
        u[1] += regime.u_cos;
        v[1] += regime.v_cos;
        const AftResult base = aft_jenkins(regime.p, u, v, events(64));
        ASSERT_TRUE(base.closed);
        const double t_scale = std::max(regime.p.kt, regime.p.mu * regime.p.kn), n_scale = regime.p.kn;
        for (Eigen::Index j = 0; j < 2 * m; ++j) {
          const bool tangential = j < m;
          const double step = 1e-6 * (tangential ? std::max(u.norm(), regime.p.mu * regime.p.n0 / regime.p.kt)
                                                 : std::max(v.norm(), regime.p.n0 / regime.p.kn));
          Eigen::VectorXd up = u, um = u, vp = v, vm = v;
          (tangential ? up[j] : vp[j - m]) += step;
          (tangential ? um[j] : vm[j - m]) -= step;
          const AftResult plus = aft_jenkins(regime.p, up, vp, events(64));
          const AftResult minus = aft_jenkins(regime.p, um, vm, events(64));
          const Eigen::VectorXd fd_t = (plus.tangential - minus.tangential) / (2.0 * step);
          const Eigen::VectorXd fd_n = (plus.normal - minus.normal) / (2.0 * step);
          const Eigen::VectorXd an_t = tangential ? base.dtangential_du.col(j) : base.dtangential_dv.col(j - m);
          const Eigen::VectorXd an_n =
              tangential ? Eigen::VectorXd(Eigen::VectorXd::Zero(m)) : Eigen::VectorXd(base.dnormal_dv.col(j - m));
          const double error =
              std::max((fd_t - an_t).cwiseAbs().maxCoeff() / t_scale, (fd_n - an_n).cwiseAbs().maxCoeff() / n_scale);
          worst = std::max(worst, error);
          ++checked;
          EXPECT_LT(error, 1e-5) << regime.name << ", H = " << harmonics << ", trial " << trial << ", column " << j;
        }
      }
  std::printf("[ Jacobian, events ] %d columns vs central differences, none skipped: worst error %.2e\n", checked,
              worst);
}

TEST(AftEvents, LawDerivativesMatchCentralDifferences) {
  std::mt19937 rng(7);
  double worst = 0.0;
  for (const EventRegime& regime : regimes())
    for (int trial = 0; trial < 3; ++trial) {
      Eigen::VectorXd u = random_coefficients(rng, 2, regime.u_amplitude);
      Eigen::VectorXd v = random_coefficients(rng, 2, regime.v_amplitude);
      u[1] += regime.u_cos;
      v[1] += regime.v_cos;
      AftOptions options = events(64);
      options.law_derivatives = true;
      const AftResult base = aft_jenkins(regime.p, u, v, options);
      const double force = std::max(base.tangential.cwiseAbs().maxCoeff(), regime.p.mu * regime.p.n0);
      for (Eigen::Index j = 0; j < 4; ++j) {
        PointParameters plus = regime.p, minus = regime.p;
        double* field[4] = {&plus.kn, &plus.kt, &plus.mu, &plus.n0};
        double* other[4] = {&minus.kn, &minus.kt, &minus.mu, &minus.n0};
        const double step = 1e-6 * *field[j];
        *field[j] += step;
        *other[j] -= step;
        const AftResult rp = aft_jenkins(plus, u, v, events(64)), rm = aft_jenkins(minus, u, v, events(64));
        const Eigen::VectorXd fd = (rp.tangential - rm.tangential) / (2.0 * step);
        const Eigen::VectorXd fd_n = (rp.normal - rm.normal) / (2.0 * step);
        // Relative to the force a unit relative change of the parameter makes.
        const double scale = force / std::abs(*field[j] - step);
        const double error = std::max((fd - base.dtangential_dlaw.col(j)).cwiseAbs().maxCoeff(),
                                      (fd_n - base.dnormal_dlaw.col(j)).cwiseAbs().maxCoeff()) /
                             scale;
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-5) << regime.name << ", trial " << trial << ", parameter " << j;
      }
    }
  std::printf("[ law derivatives, events ] worst error %.2e\n", worst);
}

// A contact that slips forgets where it started: from any starting slider the march closes on the
// same loop, coefficients and Jacobian alike (the periods after the first are copied from the
// period before once they reach its phase at a sample, so this also checks that copy).
TEST(AftEvents, EveryStartingSliderClosesOnTheSameLoop) {
  std::mt19937 rng(11);
  double worst = 0.0;
  for (const EventRegime& regime : regimes()) {
    if (std::string(regime.name) == "stick") continue;  // a loop that never slips keeps its start
    for (int trial = 0; trial < 3; ++trial) {
      Eigen::VectorXd u = random_coefficients(rng, 3, regime.u_amplitude);
      Eigen::VectorXd v = random_coefficients(rng, 3, regime.v_amplitude);
      u[1] += regime.u_cos;
      v[1] += regime.v_cos;
      const double reach = regime.p.mu * regime.p.n0 / regime.p.kt;
      const AftResult base = aft_jenkins(regime.p, u, v, events(64));
      ASSERT_TRUE(base.closed);
      const double t_scale = regime.p.kt * std::max(u.norm(), reach);
      for (double start : {-3.0, -1.0, -0.3, 0.4, 1.0, 2.5}) {
        AftOptions options = events(64);
        options.initial_slider = start * reach + u[0];
        const AftResult r = aft_jenkins(regime.p, u, v, options);
        ASSERT_TRUE(r.closed) << regime.name << ", start " << start;
        EXPECT_GE(r.periods, 1);
        const double error =
            std::max({(r.tangential - base.tangential).cwiseAbs().maxCoeff() / t_scale,
                      (r.dtangential_du - base.dtangential_du).cwiseAbs().maxCoeff() / regime.p.kt,
                      (r.dtangential_dv - base.dtangential_dv).cwiseAbs().maxCoeff() / (regime.p.mu * regime.p.kn)});
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-12) << regime.name << ", trial " << trial << ", start " << start;
        EXPECT_EQ(r.state, base.state) << regime.name << ", trial " << trial << ", start " << start;
      }
    }
  }
  std::printf("[ starting slider, events ] worst difference %.2e\n", worst);
}

}  // namespace
}  // namespace bb::friction
