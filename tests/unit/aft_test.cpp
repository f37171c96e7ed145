// Alternating frequency-time evaluation of a Jenkins contact (friction/aft): the steady hysteresis
// loop against the closed-form parallelogram and describing function, the energy it dissipates,
// the clipped normal load against its closed-form harmonics, the exact Jacobian against central
// differences, convergence with the number of time samples, and finite, closed loops over extreme
// parameters. Units: SI.
#include "friction/aft.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "common/constants.hpp"
#include "fourier_series.hpp"
#include "friction/jenkins.hpp"

namespace bb::friction {
namespace {

Eigen::VectorXd cosine(int harmonics, double amplitude, double phase = 0.0) {
  // amplitude cos(theta - phase) in the layout [c0, a1, b1, ...].
  Eigen::VectorXd c = Eigen::VectorXd::Zero(harmonic_size(harmonics));
  c[1] = amplitude * std::cos(phase);
  c[2] = amplitude * std::sin(phase);
  return c;
}

// Steady force of a Jenkins element under u = U cos(theta) at a constant slip force F = mu N: the
// parallelogram loop. From u = U (theta = 0, just slipped positively) the spring unloads,
// T = F - kt U (1 - cos theta), until T = -F at theta = beta, cos beta = 1 - 2 F / (kt U); it then
// slips at -F up to theta = pi; the second half is the mirror image, T(theta + pi) = -T(theta).
double parallelogram(double theta, double amplitude, double kt, double slip_force) {
  if (kt * amplitude <= slip_force) return kt * amplitude * std::cos(theta);
  theta = std::fmod(theta, 2.0 * kPi);
  if (theta < 0.0) theta += 2.0 * kPi;
  const double sign = theta < kPi ? 1.0 : -1.0;
  if (theta >= kPi) theta -= kPi;
  const double beta = std::acos(1.0 - 2.0 * slip_force / (kt * amplitude));
  return sign * (theta < beta ? slip_force - kt * amplitude * (1.0 - std::cos(theta)) : -slip_force);
}

// First harmonic of the response to U cos(theta - phase): the loop above delayed by `phase`.
Eigen::Vector2d shifted_describing_function(double amplitude, double phase, double kt, double slip_force) {
  const Eigen::Vector2d d = describing_function(amplitude, kt, slip_force);
  return {d[0] * std::cos(phase) - d[1] * std::sin(phase), d[0] * std::sin(phase) + d[1] * std::cos(phase)};
}

constexpr PointParameters kConstantLoad{.kn = 0.0, .kt = 1.0e6, .mu = 0.5, .n0 = 100.0};  // F = 50 N
constexpr double kSlipForce = 50.0, kSlipDistance = 5.0e-5;

TEST(AftJenkins, AnalysisInvertsSynthesis) {
  for (int harmonics : {0, 1, 3, 7})
    for (int samples : {2 * harmonics + 1, 2 * harmonics + 2, 64}) {
      const Eigen::MatrixXd product = analysis_matrix(harmonics, samples) * synthesis_matrix(harmonics, samples);
      EXPECT_LT((product - Eigen::MatrixXd::Identity(product.rows(), product.cols())).norm(), 1e-13)
          << harmonics << " harmonics, " << samples << " samples";
    }
  EXPECT_THROW(synthesis_matrix(3, 6), std::invalid_argument);
}

TEST(AftJenkins, ConstantNormalLoadLoopIsTheJenkinsParallelogram) {
  // With the extremes of u on the grid, the sampled steady loop is the continuous one exactly.
  const double amplitude = 4.0 * kSlipDistance;
  const int samples = 64;
  const AftResult r = aft_jenkins(kConstantLoad, cosine(3, amplitude), Eigen::VectorXd::Zero(7), {.samples = samples});
  ASSERT_TRUE(r.closed);
  EXPECT_EQ(r.periods, 2);
  int slips = 0;
  for (int k = 0; k < samples; ++k) {
    const double theta = 2.0 * kPi * k / samples;
    EXPECT_NEAR(r.t[k], parallelogram(theta, amplitude, kConstantLoad.kt, kSlipForce), 1e-9 * kSlipForce)
        << "k = " << k;
    EXPECT_LE(std::abs(r.t[k]), kSlipForce * (1.0 + 1e-15));
    EXPECT_EQ(r.n[k], 100.0);
    slips += r.state[static_cast<size_t>(k)] != ContactState::stick;
  }
  // Slip on [beta, pi] and [pi + beta, 2 pi], beta = acos(1 - 2 / 4) = 60 degrees: 2/3 of the period.
  EXPECT_NEAR(slips, 2 * samples / 3, 2);
  // Half-wave symmetry: no static term and no even harmonics.
  EXPECT_NEAR(r.tangential[0], 0.0, 1e-9 * kSlipForce);
  EXPECT_NEAR(r.tangential[3], 0.0, 1e-9 * kSlipForce);
  EXPECT_NEAR(r.tangential[4], 0.0, 1e-9 * kSlipForce);
}

TEST(AftJenkins, DissipatedEnergyIsTheParallelogramArea) {
  // W = 4 mu N (U - mu N / kt) for U > mu N / kt, else 0.
  double worst = 0.0;
  for (double ratio : {0.5, 0.999, 1.001, 1.2, 1.5, 3.0, 10.0, 100.0}) {
    const double amplitude = ratio * kSlipDistance;
    const AftResult r =
        aft_jenkins(kConstantLoad, cosine(1, amplitude, 0.4), Eigen::VectorXd::Zero(3), {.samples = 256});
    const double exact = ratio > 1.0 ? 4.0 * kSlipForce * (amplitude - kSlipDistance) : 0.0;
    const double work = cycle_work(r.tangential, cosine(1, amplitude, 0.4));
    const double error = std::abs(work - exact) / (4.0 * kSlipForce * amplitude);
    worst = std::max(worst, error);
    EXPECT_LT(error, 2e-4) << "U / (mu N / kt) = " << ratio << ": W = " << work << " J, exact " << exact << " J";
    if (ratio >= 1.5) {
      EXPECT_NEAR(work, exact, 1e-3 * exact) << "U / (mu N / kt) = " << ratio;
    }
    if (ratio < 1.0) {
      EXPECT_NEAR(work, 0.0, 1e-12 * kSlipForce * amplitude);
    }
  }
  std::printf("[ energy ] parallelogram area at n_t = 256: worst |W - 4 mu N (U - mu N / kt)| / (4 mu N U) = %.2e\n",
              worst);
}

TEST(AftJenkins, FirstHarmonicMatchesTheDescribingFunction) {
  double worst = 0.0;
  for (double ratio : {0.5, 1.1, 2.0, 5.0, 50.0})
    for (double phase : {0.0, 0.7, 2.9}) {
      const double amplitude = ratio * kSlipDistance;
      const AftResult r =
          aft_jenkins(kConstantLoad, cosine(3, amplitude, phase), Eigen::VectorXd::Zero(7), {.samples = 512});
      const Eigen::Vector2d exact = shifted_describing_function(amplitude, phase, kConstantLoad.kt, kSlipForce);
      const double error = (r.tangential.segment<2>(1) - exact).norm() / (kConstantLoad.kt * amplitude);
      worst = std::max(worst, error);
      EXPECT_LT(error, 1e-4) << "U / (mu N / kt) = " << ratio << ", phase " << phase;
    }
  std::printf("[ describing function ] n_t = 512: worst |T1 - T1_exact| / (kt U) = %.2e\n", worst);
}

TEST(AftJenkins, HarmonicsConvergeAsTheInverseSquareOfTheSampleCount) {
  // Stick-slip loop (U = 3 mu N / kt) with the extremes of u off the grid: both the quadrature of a
  // force with kinks and the slider positions set at the sampled extremes err by O(1 / n_t^2).
  const double amplitude = 3.0 * kSlipDistance, phase = 0.3;
  const Eigen::Vector2d exact = shifted_describing_function(amplitude, phase, kConstantLoad.kt, kSlipForce);
  std::vector<double> errors;
  for (int samples : {16, 64, 256}) {
    const AftResult r =
        aft_jenkins(kConstantLoad, cosine(1, amplitude, phase), Eigen::VectorXd::Zero(3), {.samples = samples});
    errors.push_back((r.tangential.segment<2>(1) - exact).norm() / exact.norm());
    std::printf("[ n_t convergence ] n_t = %3d: |T1 - T1_exact| / |T1_exact| = %.2e\n", samples, errors.back());
  }
  EXPECT_LT(errors[0], 0.05);
  EXPECT_LT(errors[1], errors[0] / 6.0);  // 16x per 4x samples expected; kinks landing near samples add noise
  EXPECT_LT(errors[2], errors[1] / 6.0);
  EXPECT_LT(errors[2], 1e-3);
}

TEST(AftJenkins, StuckContactIsALinearSpringAndFrictionlessOneCarriesNothing) {
  const PointParameters stuck{.kn = 1e7, .kt = 1e6, .mu = 0.5, .n0 = 1e4};  // elastic range 5e-3 m
  Eigen::VectorXd u(5), v(5);
  u << 1e-4, 2e-4, -1e-4, 5e-5, 3e-5;
  v << 1e-5, -3e-5, 2e-5, 0.0, 1e-5;
  AftResult r = aft_jenkins(stuck, u, v, {.samples = 32, .initial_slider = 2e-5});
  ASSERT_TRUE(r.closed);
  Eigen::VectorXd expected = stuck.kt * u;
  expected[0] -= stuck.kt * 2e-5;  // the slider stays where the contact closed
  EXPECT_LT((r.tangential - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT((r.dtangential_du - stuck.kt * Eigen::MatrixXd::Identity(5, 5)).norm(), 1e-9 * stuck.kt);
  EXPECT_LT(r.dtangential_dv.norm(), 1e-9 * stuck.kt);
  EXPECT_LT((r.normal - (stuck.kn * v + Eigen::VectorXd::Unit(5, 0) * stuck.n0)).norm(), 1e-9 * stuck.n0);

  PointParameters frictionless = stuck;
  frictionless.mu = 0.0;
  r = aft_jenkins(frictionless, u, v, {.samples = 32});
  EXPECT_EQ(r.tangential.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(r.dtangential_du.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(r.dtangential_dv.cwiseAbs().maxCoeff(), 0.0);
}

// Fourier coefficients of N = max(c + A cos theta, 0) (the normal load of eq 3.28 under
// v = v0 + V cos theta, c = N0 + kn v0, A = kn V), in contact for |theta| < alpha, cos alpha = -c / A:
//   N0 = (c alpha + A sin alpha) / pi,
//   N_h = [2 c sin(h alpha) / h + A (sin((h-1) alpha) / (h-1) + sin((h+1) alpha) / (h+1))] / pi,
// with sin(0 alpha) / 0 read as alpha; the sine coefficients vanish by symmetry.
Eigen::VectorXd clipped_cosine(int harmonics, double c, double a) {
  const double alpha = std::acos(std::clamp(-c / a, -1.0, 1.0));
  const auto sinc = [alpha](int g) { return g == 0 ? alpha : std::sin(g * alpha) / g; };
  Eigen::VectorXd n = Eigen::VectorXd::Zero(harmonic_size(harmonics));
  n[0] = (c * alpha + a * std::sin(alpha)) / kPi;
  for (int h = 1; h <= harmonics; ++h) n[2 * h - 1] = (2.0 * c * sinc(h) + a * (sinc(h - 1) + sinc(h + 1))) / kPi;
  return n;
}

TEST(AftJenkins, OpeningContactNormalLoadMatchesTheClippedCosine) {
  const PointParameters p{.kn = 1e7, .kt = 1e6, .mu = 0.5, .n0 = 100.0};
  const int harmonics = 5;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(harmonic_size(harmonics));
  v[0] = 2e-6;  // c = 120 N
  v[1] = 3e-5;  // A = 300 N: open for |theta| > acos(-0.4), 37 % of the period
  const Eigen::VectorXd exact = clipped_cosine(harmonics, p.n0 + p.kn * v[0], p.kn * v[1]);
  for (int samples : {64, 1024}) {
    const AftResult r = aft_jenkins(p, cosine(harmonics, 1e-4), v, {.samples = samples});
    for (int k = 0; k < samples; ++k)  // eq 3.28 at every sample
      ASSERT_EQ(r.n[k], std::max(p.n0 + p.kn * r.v[k], 0.0));
    const double error = (r.normal - exact).cwiseAbs().maxCoeff() / (p.kn * v[1]);
    std::printf("[ normal load ] n_t = %4d: max |N_h - N_h,exact| / (kn V) = %.2e\n", samples, error);
    EXPECT_LT(error, samples == 64 ? 2e-3 : 1e-5);
  }
}

// Work of T on u over the second of two periods marched by jenkins_step on a fine grid, trapezoidal
// in u: an independent time-domain evaluation of the loop area.
double fine_march_work(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v, int steps) {
  double slider = 0.0, work = 0.0, previous_t = 0.0, previous_u = 0.0;
  for (int k = 0; k <= 2 * steps; ++k) {
    const double theta = 2.0 * kPi * k / steps, uk = evaluate(u, theta);
    const JenkinsStep s = jenkins_step(p, slider, uk, evaluate(v, theta));
    slider = s.slider;
    if (k > steps) work += 0.5 * (s.tangential + previous_t) * (uk - previous_u);
    previous_t = s.tangential;
    previous_u = uk;
  }
  return work;
}

TEST(AftJenkins, EnergyWithVariableNormalLoadAndLiftOffIsTheIntegralOfTdu) {
  // u and v out of phase and with a second harmonic: the contact opens for part of the cycle,
  // slips under a varying limit and re-sticks; |T| <= mu N at every sample.
  const PointParameters p{.kn = 1e7, .kt = 1e6, .mu = 0.6, .n0 = 100.0};
  Eigen::VectorXd u(5), v(5);
  u << 1e-5, 2e-4, 1e-4, 3e-5, -2e-5;
  v << 0.0, 5e-6, -1.2e-5, 2e-6, 1e-6;
  const AftResult r = aft_jenkins(p, u, v, {.samples = 512});
  ASSERT_TRUE(r.closed);
  int open = 0, slipping = 0;
  for (int k = 0; k < 512; ++k) {
    EXPECT_LE(std::abs(r.t[k]), p.mu * r.n[k] * (1.0 + 1e-14));
    open += r.state[static_cast<size_t>(k)] == ContactState::lift_off;
    slipping += r.state[static_cast<size_t>(k)] == ContactState::slip_positive ||
                r.state[static_cast<size_t>(k)] == ContactState::slip_negative;
  }
  EXPECT_GT(open, 20);
  EXPECT_GT(slipping, 20);
  const double work = cycle_work(r.tangential, u), reference = fine_march_work(p, u, v, 200000);
  std::printf(
      "[ energy, lift-off ] W from AFT harmonics (n_t = 512) = %.6e J, integral of T du (2e5 steps) = %.6e J,"
      " rel. diff %.2e\n",
      work, reference, std::abs(work - reference) / reference);
  EXPECT_GT(reference, 0.0);
  EXPECT_NEAR(work, reference, 1e-3 * reference);
}

TEST(AftJenkins, JacobianMatchesCentralDifferences) {
  struct Regime {
    const char* name;
    PointParameters p;
    double u_amplitude, v_amplitude;  // of the random coefficients
    double u_cos, v_cos;              // added to a1 to force the regime
    ContactState expected;            // a state that must appear in the loop
  };
  // Elastic range mu N0 / kt = 5e-4 m. Stick-slip: u swings 4e-3 m or more; lift-off: kn v swings
  // 2000 N +- 300 N about N0 = 1000 N, so the contact opens and closes in every trial.
  const std::vector<Regime> regimes = {
      {"stick", {.kn = 1e6, .kt = 1e6, .mu = 0.5, .n0 = 1000.0}, 1e-5, 1e-5, 0.0, 0.0, ContactState::stick},
      {"stick-slip",
       {.kn = 1e6, .kt = 1e6, .mu = 0.5, .n0 = 1000.0},
       1e-3,
       1e-5,
       2.5e-3,
       0.0,
       ContactState::slip_positive},
      {"partial lift-off",
       {.kn = 1e7, .kt = 1e6, .mu = 0.5, .n0 = 1000.0},
       1e-3,
       1e-5,
       2.5e-3,
       2e-4,
       ContactState::lift_off}};
  std::mt19937 rng(2024);
  double worst = 0.0;
  int checked = 0, skipped = 0;
  for (int harmonics : {1, 3})
    for (const auto& regime : regimes)
      for (int trial = 0; trial < 4; ++trial) {
        const Eigen::Index m = harmonic_size(harmonics);
        const AftOptions options{.samples = 128};
        Eigen::VectorXd u = random_coefficients(rng, harmonics, regime.u_amplitude);
        Eigen::VectorXd v = random_coefficients(rng, harmonics, regime.v_amplitude);
        u[1] += regime.u_cos;
        v[1] += regime.v_cos;
        const AftResult base = aft_jenkins(regime.p, u, v, options);
        ASSERT_TRUE(base.closed);
        ASSERT_NE(std::find(base.state.begin(), base.state.end(), regime.expected), base.state.end()) << regime.name;
        // Each force relative to the largest stiffness it can show, so a zero block (dT/dv in stick)
        // is judged against kt rather than against itself.
        const double t_scale = std::max(regime.p.kt, regime.p.mu * regime.p.kn), n_scale = regime.p.kn;
        for (Eigen::Index j = 0; j < 2 * m; ++j) {
          const bool tangential = j < m;
          // The map is piecewise linear, so the step only has to beat rounding of the forces it
          // changes (N carries N0, T up to mu N) while leaving every sample in its state.
          const double step = 1e-6 * (tangential ? std::max(u.norm(), regime.p.mu * regime.p.n0 / regime.p.kt)
                                                 : std::max(v.norm(), regime.p.n0 / regime.p.kn));
          Eigen::VectorXd up = u, um = u, vp = v, vm = v;
          if (tangential) {
            up[j] += step;
            um[j] -= step;
          } else {
            vp[j - m] += step;
            vm[j - m] -= step;
          }
          const AftResult plus = aft_jenkins(regime.p, up, vp, options), minus = aft_jenkins(regime.p, um, vm, options);
          if (plus.state != base.state || minus.state != base.state) {
            ++skipped;  // a sample changed state: the map has a kink here, no derivative to compare
            continue;
          }
          ++checked;
          const Eigen::VectorXd fd_t = (plus.tangential - minus.tangential) / (2.0 * step);
          const Eigen::VectorXd fd_n = (plus.normal - minus.normal) / (2.0 * step);
          const Eigen::VectorXd an_t = tangential ? base.dtangential_du.col(j) : base.dtangential_dv.col(j - m);
          const Eigen::VectorXd an_n =
              tangential ? Eigen::VectorXd(Eigen::VectorXd::Zero(m)) : Eigen::VectorXd(base.dnormal_dv.col(j - m));
          const double error =
              std::max((fd_t - an_t).cwiseAbs().maxCoeff() / t_scale, (fd_n - an_n).cwiseAbs().maxCoeff() / n_scale);
          worst = std::max(worst, error);
          EXPECT_LT(error, 1e-6) << regime.name << ", H = " << harmonics << ", trial " << trial << ", column " << j;
        }
      }
  std::printf("[ Jacobian ] %d columns vs central differences, %d skipped (state change): worst error %.2e\n", checked,
              skipped, worst);
  EXPECT_GT(checked, 10 * skipped);
}

TEST(AftJenkins, ExtremeParametersGiveFiniteForcesAndLoopsThatClose) {
  // kn, kt log-uniform in [1e3, 1e12] N/m, mu in [0, 2], N0 in {0, 1e-3, 300, 1e5} N, amplitudes
  // log-uniform in [1e-9, 1e-2] m. Every composition of Jenkins steps over a period is a clamp of
  // the slider onto an interval (or a point), which is idempotent: the loop must close by the
  // second period, so `closed` is expected everywhere, not just tolerated.
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
  const double preloads[] = {0.0, 1e-3, 300.0, 1e5};
  int runs = 0, lift_offs = 0;
  for (int i = 0; i < 400; ++i) {
    const PointParameters p{
        .kn = log_uniform(1e3, 1e12), .kt = log_uniform(1e3, 1e12), .mu = 2.0 * unit(rng), .n0 = preloads[i % 4]};
    const int harmonics = 1 + i % 3;
    const Eigen::VectorXd u = random_coefficients(rng, harmonics, log_uniform(1e-9, 1e-2));
    const Eigen::VectorXd v = random_coefficients(rng, harmonics, log_uniform(1e-9, 1e-2));
    const AftResult r = aft_jenkins(p, u, v, {.samples = 16 * (2 * harmonics + 1)});
    ++runs;
    lift_offs += std::find(r.state.begin(), r.state.end(), ContactState::lift_off) != r.state.end();
    ASSERT_TRUE(r.tangential.allFinite() && r.normal.allFinite()) << "run " << i;
    ASSERT_TRUE(r.dtangential_du.allFinite() && r.dtangential_dv.allFinite() && r.dnormal_dv.allFinite())
        << "run " << i;
    ASSERT_TRUE(r.closed) << "run " << i << ": mismatch " << r.closure_mismatch << " m after " << r.periods
                          << " periods";
    EXPECT_EQ(r.periods, 2) << "run " << i;
    for (Eigen::Index k = 0; k < r.t.size(); ++k) {
      ASSERT_GE(r.n[k], 0.0);
      ASSERT_LE(std::abs(r.t[k]), p.mu * r.n[k] * (1.0 + 1e-14)) << "run " << i;
    }
  }
  EXPECT_GT(lift_offs, 20);
  EXPECT_LT(lift_offs, runs - 20);
}

TEST(AftJenkins, RejectsMalformedInput) {
  const Eigen::VectorXd u = cosine(2, 1e-4), v = Eigen::VectorXd::Zero(5);
  EXPECT_THROW((void)aft_jenkins(kConstantLoad, u, v, {.samples = 4}), std::invalid_argument);
  EXPECT_THROW((void)aft_jenkins(kConstantLoad, u, Eigen::VectorXd::Zero(3), {.samples = 32}), std::invalid_argument);
  EXPECT_THROW((void)aft_jenkins(kConstantLoad, Eigen::VectorXd::Zero(4), Eigen::VectorXd::Zero(4), {.samples = 32}),
               std::invalid_argument);
  Eigen::VectorXd bad = u;
  bad[1] = std::nan("");
  EXPECT_THROW((void)aft_jenkins(kConstantLoad, bad, v, {.samples = 32}), std::invalid_argument);
  EXPECT_THROW((void)aft_jenkins(kConstantLoad, u, v, {.samples = 32, .max_periods = 1}), std::invalid_argument);
  EXPECT_THROW((void)aft_jenkins({.kn = 1.0, .kt = 0.0, .mu = 0.1, .n0 = 1.0}, u, v, {.samples = 32}),
               std::invalid_argument);
}

}  // namespace
}  // namespace bb::friction
