// Multi-DOF harmonic balance with friction contacts (hbm/harmonic_balance): linear limits of a
// frictionless and a stuck contact against direct solves, lift-off, energy balance per cycle, the
// 1-DOF friction oscillator's own balance, convergence in H, frequency continuation through folds, and a
// matrix of extreme parameters. Units: SI.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "../extremes/hbm_models.hpp"
#include "frf/receptance.hpp"
#include "friction/aft.hpp"
#include "friction_oscillator.hpp"
#include "hbm/harmonic_balance.hpp"

namespace bb::hbm {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXcd;
using Eigen::VectorXd;

Eigen::RowVectorXd unit_row(Eigen::Index n, Eigen::Index i, double value = 1.0) {
  Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(n);
  r[i] = value;
  return r;
}

using models::blade_on_ground;

// Harmonics of all DOFs of the linear model with the contact replaced by springs kn (a_n) and, if
// stuck, kt (a_t), preload N0 acting on the static term: columns (c0, a1, b1).
MatrixXd linear_reference(const friction::FrictionModel& m, double omega, bool stuck) {
  MatrixXd k = m.stiffness;
  VectorXd fs = m.static_load;
  for (const friction::ContactElement& c : m.contacts) {
    k += c.point.kn * c.normal.transpose() * c.normal;
    if (stuck) k += c.point.kt * c.tangential.transpose() * c.tangential;
    fs -= c.point.n0 * c.normal.transpose();
  }
  const VectorXd q0 = k.fullPivLu().solve(fs);
  const Eigen::VectorXcd q1 = direct_response(k, m.damping, m.mass, omega, m.harmonic_load);
  MatrixXd q(m.mass.rows(), 3);
  q.col(0) = q0;
  q.col(1) = q1.real();
  q.col(2) = -q1.imag();
  return q;
}

double relative_difference(const MatrixXd& a, const MatrixXd& b) { return (a - b).norm() / b.norm(); }

TEST(HbmMultiDof, FrictionlessContactIsTheLinearModelWithNormalSprings) {
  const friction::FrictionModel m = blade_on_ground({.kn = 3.0e5, .kt = 1.0e6, .mu = 0.0, .n0 = 50.0}, 10.0);
  const HarmonicBalance system(m, {.harmonics = 3});
  for (const double omega : {600.0, 1000.0, 1400.0, 2500.0}) {
    const HbmSolution s = solve_at_frequency(system, omega);
    ASSERT_TRUE(s.converged) << s.failure;
    EXPECT_GT(s.contacts[0].n.minCoeff(), 0.0) << "contact must stay closed for the linear limit";
    const MatrixXd q = system.recover(s.x, omega);
    const double e = relative_difference(q.leftCols(3), linear_reference(m, omega, false));
    std::printf("  mu = 0, omega %6.0f: |q - linear| / |linear| = %.2e, higher harmonics %.1e m\n", omega, e,
                q.rightCols(4).norm());
    EXPECT_LT(e, 1e-8);
    EXPECT_LT(q.rightCols(4).norm(), 1e-12 * q.norm());
  }
}

TEST(HbmMultiDof, StuckContactIsTheLinearModelWithNormalAndTangentialSprings) {
  const friction::FrictionModel m = blade_on_ground({.kn = 3.0e5, .kt = 1.0e6, .mu = 1.0e6, .n0 = 50.0}, 10.0);
  const HarmonicBalance system(m, {.harmonics = 3});
  for (const double omega : {600.0, 1200.0, 1800.0, 2500.0}) {
    const HbmSolution s = solve_at_frequency(system, omega);
    ASSERT_TRUE(s.converged) << s.failure;
    const MatrixXd q = system.recover(s.x, omega);
    const double e = relative_difference(q.leftCols(3), linear_reference(m, omega, true));
    std::printf("  stuck, omega %6.0f: |q - linear| / |linear| = %.2e\n", omega, e);
    EXPECT_LT(e, 1e-8);
  }
}

TEST(HbmMultiDof, StuckSliderRestsAtItsOffset) {
  // A static push along the tangential DOF with the slider at rest at u = d: stuck, the tangential
  // spring acts on u - d, so the static state is K q + kt a_t^T (a_t q - d) + kn ... = f (closed
  // form), and the stuck starting point of the solver is that same state.
  friction::FrictionModel m = blade_on_ground({.kn = 3.0e5, .kt = 1.0e6, .mu = 1.0e6, .n0 = 50.0}, 1.0);
  const double d = 2.0e-5;
  m.contacts[0].tangential_offset = d;
  m.static_load = Eigen::Vector3d(0.0, 15.0, 0.0);
  MatrixXd k = m.stiffness;
  VectorXd fs = m.static_load;
  const friction::ContactElement& c = m.contacts[0];
  k += c.point.kn * c.normal.transpose() * c.normal + c.point.kt * c.tangential.transpose() * c.tangential;
  fs += c.point.kt * d * c.tangential.transpose() - c.point.n0 * c.normal.transpose();
  const VectorXd q0 = k.fullPivLu().solve(fs);
  const HarmonicBalance system(m, {.harmonics = 1});
  const double omega = 900.0;
  const HbmSolution s = solve_at_frequency(system, omega);
  ASSERT_TRUE(s.converged) << s.failure;
  const VectorXd static_part = system.recover(s.x, omega).col(0);
  EXPECT_LT((static_part - q0).norm(), 1e-10 * q0.norm());
  const auto start = system.linearized(omega, true);
  ASSERT_TRUE(start.has_value());
  EXPECT_LT((*start - s.x).norm(), 1e-10 * s.x.norm());
  // The contact carries kt (u - d) statically, less than mu N: it does stick.
  EXPECT_NEAR(s.contacts[0].tangential[0], c.point.kt * (c.tangential.dot(q0) - d), 1e-8);
}

TEST(HbmMultiDof, OpeningContactLiftsOffWithoutNaN) {
  // N0 = 0 and no static load: the contact is closed for v > 0 only, i.e. open over part of the cycle.
  const friction::FrictionModel m = blade_on_ground({.kn = 5.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 0.0}, 20.0);
  const HarmonicBalance system(m, {.harmonics = 5});
  for (const double omega : {800.0, 1100.0, 1500.0}) {
    const HbmSolution s = solve_at_frequency(system, omega);
    ASSERT_TRUE(s.converged) << s.failure;
    ASSERT_TRUE(s.x.allFinite());
    const auto& n = s.contacts[0].n;
    const auto open =
        std::count(s.contacts[0].state.begin(), s.contacts[0].state.end(), friction::ContactState::lift_off);
    std::printf("  lift-off, omega %6.0f: %ld of %ld samples open, max N %.3g N\n", omega, static_cast<long>(open),
                static_cast<long>(n.size()), n.maxCoeff());
    EXPECT_GT(open, 0);
    EXPECT_LT(open, n.size());
    EXPECT_EQ(n.minCoeff(), 0.0);
    EXPECT_GT(n.maxCoeff(), 0.0);
  }
}

// Blade of three DOFs and a rigid damper (DOFs 3 tangential, 4 normal) held only by its two
// contacts: one against the platform, one against a fixed neighbour. K of the damper is zero; the
// centrifugal force on DOF 4 presses both contacts.
friction::FrictionModel blade_with_damper(double force, double mu) {
  friction::FrictionModel m;
  m.stiffness = MatrixXd::Zero(5, 5);
  m.stiffness.topLeftCorner(3, 3) << 2.0e6, -5.0e5, -2.0e5, -5.0e5, 1.5e6, 3.0e5, -2.0e5, 3.0e5, 1.0e6;
  m.mass = (VectorXd(5) << 1.0, 0.4, 0.3, 0.05, 0.05).finished().asDiagonal();
  m.damping = MatrixXd::Zero(5, 5);
  m.damping.topLeftCorner(3, 3) =
      modal_damping_matrix(m.stiffness.topLeftCorner(3, 3), m.mass.topLeftCorner(3, 3), 0.005);
  const friction::PointParameters law{.kn = 2.0e6, .kt = 1.0e6, .mu = mu, .n0 = 0.0};
  m.contacts.push_back({law, unit_row(5, 1) - unit_row(5, 3), unit_row(5, 4) - unit_row(5, 2)});
  m.contacts.push_back({law, unit_row(5, 3), unit_row(5, 4)});
  m.static_load = VectorXd::Zero(5);
  m.static_load[4] = 40.0;
  m.harmonic_load = VectorXcd::Zero(5);
  m.harmonic_load[1] = std::complex<double>(0.0, -force);  // force sin(omega t) on the platform
  return m;
}

// Relative error of the energy balance at s, printed; also returns friction / excitation.
std::pair<double, double> energy_balance(const HarmonicBalance& system, const HbmSolution& s, const char* label,
                                         double force) {
  const CycleEnergy e = cycle_energy(system, s);
  const double error = std::abs(e.excitation - (e.viscous + e.friction + e.normal)) / e.excitation;
  std::printf("  %s F %5.0f N, omega %5.0f: W_exc %.4e J, viscous %.3e, friction %.3e, normal %.1e, error %.1e\n",
              label, force, s.omega, e.excitation, e.viscous, e.friction, e.normal, error);
  EXPECT_GT(e.excitation, 0.0);
  EXPECT_GE(e.friction, -1e-12 * e.excitation);
  return {error, e.friction / e.excitation};
}

// solve_from is a continuation step: Newton from the given start alone. From the solution it takes
// no iteration; from a far start with a small budget it fails there, where solve_at_frequency
// goes on to the linear-limit starts.
TEST(HbmMultiDof, SolveFromIteratesFromTheGivenStartAlone) {
  const friction::FrictionModel model = blade_on_ground({.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 30.0}, 25.0, 0.005);
  const HarmonicBalance system(model, {.harmonics = 3, .tolerance = 1e-10});
  const HbmSolution solved = solve_at_frequency(system, 1000.0);
  ASSERT_TRUE(solved.converged) << solved.failure;
  const HbmSolution again = solve_from(system, 1000.0, solved.x);
  EXPECT_TRUE(again.converged);
  EXPECT_EQ(again.iterations, 0);
  EXPECT_EQ(again.x, solved.x);
  const HarmonicBalance short_budget(model, {.harmonics = 3, .max_iterations = 1, .tolerance = 1e-10});
  const VectorXd far = 50.0 * solved.x;
  const HbmSolution alone = solve_from(short_budget, 1000.0, far);
  EXPECT_FALSE(alone.converged);
  EXPECT_EQ(alone.start, HbmStart::initial);
  EXPECT_LE(alone.iterations, 2);
  const HbmSolution every_start = solve_at_frequency(short_budget, 1000.0, far);
  EXPECT_GT(every_start.iterations, alone.iterations);
}

TEST(HbmMultiDof, CycleEnergyOfExcitationEqualsViscousPlusContactDissipation) {
  double worst = 0.0, most_friction = 0.0;
  // Blade on the ground, variable normal load: every point must converge.
  for (const double force : {5.0, 25.0, 100.0}) {
    const HarmonicBalance system(blade_on_ground({.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 30.0}, force, 0.005),
                                 {.harmonics = 5, .tolerance = 1e-10});
    for (const double omega : {700.0, 1000.0, 1300.0, 1800.0}) {
      const HbmSolution s = solve_at_frequency(system, omega);
      ASSERT_TRUE(s.converged) << s.failure;
      const auto [error, friction] = energy_balance(system, s, "blade ", force);
      worst = std::max(worst, error);
      most_friction = std::max(most_friction, friction);
      EXPECT_LT(error, 1e-6);
    }
  }
  // Blade with a rigid damper held only by its contacts: the balance is checked on the converged
  // points; non-convergence (a known weakness there, see the report) is printed, not hidden.
  int damper_converged = 0;
  for (const double force : {2.0, 20.0, 100.0}) {
    const HarmonicBalance system(blade_with_damper(force, 0.4), {.harmonics = 5, .tolerance = 1e-10});
    for (const double omega : {700.0, 1000.0, 1300.0, 1800.0}) {
      const HbmSolution s = solve_at_frequency(system, omega);
      EXPECT_TRUE(s.x.allFinite());
      if (!s.converged) {
        std::printf("  damper F %5.0f N, omega %5.0f: not converged: %s\n", force, omega, s.failure.c_str());
        continue;
      }
      ++damper_converged;
      const auto [error, friction] = energy_balance(system, s, "damper", force);
      worst = std::max(worst, error);
      most_friction = std::max(most_friction, friction);
      EXPECT_LT(error, 1e-6);
    }
  }
  std::printf(
      "  worst relative energy-balance error %.2e, largest friction share %.2f, damper points converged %d/12\n", worst,
      most_friction, damper_converged);
  EXPECT_GT(most_friction, 0.2) << "the cases must exercise friction dissipation";
  EXPECT_GE(damper_converged, 6);
}

TEST(HbmMultiDof, SingleDofAgreesWithTheFrictionOscillator) {
  // The condensed multi-DOF balance on one DOF must be the friction oscillator's own balance,
  // written out here: R1(x) = A(w) x + T(x) - F e_a1, A = k for the static term and
  // [[k - m h^2 w^2, c h w], [-c h w, k - m h^2 w^2]] for harmonic h, T the AFT of the contact at
  // v = 0. The Newton correction of R1 at the solution, -(A + dT/du)^-1 R1, bounds (to first order)
  // the distance to that balance's exact solution.
  const test::FrictionOscillator o{.mass = 1.0,
                                   .damping = 20.0,
                                   .stiffness = 1.0e6,
                                   .force = 30.0,
                                   .contact = {.kn = 0.0, .kt = 5.0e5, .mu = 0.5, .n0 = 20.0}};
  const HarmonicBalance system(o.model(), {.harmonics = 5, .tolerance = 1e-12});
  const Eigen::Index m = friction::harmonic_size(5);
  double worst = 0.0;
  for (const double omega : {900.0, 1050.0, 1150.0, 1250.0, 1400.0}) {
    const HbmSolution s = solve_at_frequency(system, omega);
    ASSERT_TRUE(s.converged) << s.failure;
    MatrixXd a = MatrixXd::Zero(m, m);
    a(0, 0) = o.stiffness;
    for (int h = 1; h <= 5; ++h) {
      const Eigen::Index i = 2 * h - 1;
      a(i, i) = a(i + 1, i + 1) = o.stiffness - o.mass * h * h * omega * omega;
      a(i, i + 1) = o.damping * h * omega;
      a(i + 1, i) = -o.damping * h * omega;
    }
    const friction::AftResult t = friction::aft_jenkins(o.contact, s.x, VectorXd::Zero(m), system.aft_options());
    VectorXd r = a * s.x + t.tangential;
    r[1] -= o.force;
    const double e = (a + t.dtangential_du).fullPivLu().solve(r).norm() / s.x.norm();
    worst = std::max(worst, e);
    EXPECT_LT(e, 1e-8) << omega;
  }
  std::printf("  1-DOF vs the friction oscillator's balance: worst relative Newton correction %.2e\n", worst);
}

// Peak over time of q1(t) from its harmonics.
double peak_in_time(const VectorXd& coefficients) {
  const int harmonics = friction::harmonics_of(coefficients.size());
  const MatrixXd e = friction::synthesis_matrix(harmonics, 512);
  return (e * coefficients).cwiseAbs().maxCoeff();
}

TEST(HbmMultiDof, StickSlipPeakConvergesInHarmonics) {
  const friction::FrictionModel m = blade_on_ground({.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 30.0}, 25.0, 0.005);
  // The stick-slip resonance at H = 1 on a grid, then every H at that frequency.
  double peak_omega = 0.0, best = 0.0;
  {
    const HarmonicBalance h1(m, {.harmonics = 1});
    std::optional<VectorXd> warm;
    for (double omega = 700.0; omega <= 1500.0; omega += 10.0) {
      const HbmSolution s = solve_at_frequency(h1, omega, warm);
      ASSERT_TRUE(s.converged) << s.failure;
      warm = s.x;
      const double a = std::hypot(s.x[2], s.x[4]);
      if (a > best) best = a, peak_omega = omega;
    }
  }
  std::vector<double> peaks;
  for (const int harmonics : {1, 3, 5, 7}) {
    const HarmonicBalance system(m, {.harmonics = harmonics, .aft = {.samples = 1024}});
    const HbmSolution s = solve_at_frequency(system, peak_omega);
    ASSERT_TRUE(s.converged) << s.failure;
    const MatrixXd q = system.recover(s.x, peak_omega);
    peaks.push_back(peak_in_time(q.row(1).transpose()));
    std::printf("  H = %d at omega %.0f rad/s: peak |q1| = %.8e m\n", harmonics, peak_omega, peaks.back());
  }
  const double d1 = std::abs(peaks[1] - peaks[0]), d2 = std::abs(peaks[2] - peaks[1]),
               d3 = std::abs(peaks[3] - peaks[2]);
  std::printf("  differences: |3-1| %.2e, |5-3| %.2e, |7-5| %.2e\n", d1, d2, d3);
  EXPECT_GT(d1, d2);
  EXPECT_GT(d2, d3);
}

// Two masses grounded by springs, one contact between them (v = q0 - q1 presses) with N0 = 0 and a
// static load opening a gap of 2e-5 m: small motion is linear, large motion impacts the stiff
// normal spring. A hardening (impact) resonance whose response curve folds twice.
friction::FrictionModel impact_pair() {
  friction::FrictionModel m;
  m.mass = MatrixXd::Identity(2, 2);
  m.stiffness = 1.0e6 * MatrixXd::Identity(2, 2);
  m.damping = 20.0 * MatrixXd::Identity(2, 2);
  m.contacts.push_back({{.kn = 1.0e6, .kt = 1.0, .mu = 0.0, .n0 = 0.0},
                        Eigen::RowVectorXd::Zero(2),
                        (Eigen::RowVectorXd(2) << 1.0, -1.0).finished()});
  m.static_load = Eigen::Vector2d(-10.0, 10.0);
  m.harmonic_load = Eigen::Vector2cd(2.0, 0.0);
  return m;
}

TEST(HbmContinuation, ImpactResonanceIsFollowedThroughItsFolds) {
  const HarmonicBalance system(impact_pair(), {.harmonics = 5});
  int calls = 0;
  const auto start = std::chrono::steady_clock::now();
  const ContinuationResult r = continue_in_frequency(
      system, {.omega_start = 800.0, .omega_end = 1600.0, .progress = [&](const ContinuationProgress&) { ++calls; }});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r.converged) << r.failure;
  double max_step = 0.0, max_amplitude = 0.0;
  for (size_t i = 0; i < r.points.size(); ++i) {
    const ContinuationPoint& p = r.points[i];
    EXPECT_TRUE(p.x.allFinite());
    EXPECT_LE(p.residual, system.options().tolerance * system.force_scale());
    // Independent check of the stored point with a fresh evaluation of R.
    const auto linear = system.condense(p.omega);
    ASSERT_TRUE(linear);
    const double residual = (linear->operator_ * p.x + system.contact_forces(p.x).force - linear->load).norm();
    EXPECT_LE(residual, 1.0001 * system.options().tolerance * system.force_scale());
    max_amplitude = std::max(max_amplitude, std::hypot(p.x[2], p.x[4]));
    if (i > 0 && (p.tangent_omega > 0.0) != (r.points[i - 1].tangent_omega > 0.0))
      std::printf("  turning point near omega %.2f rad/s, |q0| %.3e m\n", p.omega, std::hypot(p.x[2], p.x[4]));
    if (i > 0) {
      // Continuity: consecutive points are no further apart (scaled) than the step that joined them, plus the
      // corrector.
      const ContinuationPoint& q = r.points[i - 1];
      const double distance = std::hypot((p.x - q.x).norm() / r.amplitude_scale, (p.omega - q.omega) / 800.0);
      max_step = std::max(max_step, distance / p.step);
      EXPECT_LT(distance, 3.0 * p.step);
    }
  }
  std::printf(
      "  continuation: %zu points, %d turning points, %d corrector iterations, %d rejected steps, %d jumps, %.2f s, "
      "max |q0| %.3e m, max distance/step %.2f\n",
      r.points.size(), r.turning_points, r.corrector_iterations, r.rejected_steps, r.jumps, seconds, max_amplitude,
      max_step);
  EXPECT_EQ(calls, static_cast<int>(r.points.size()));
  EXPECT_GE(r.turning_points, 2);
  // Past the folds the path has returned to the small-amplitude linear branch.
  EXPECT_GT(r.points.back().omega, 1600.0);
}

// A cap one below the turning points of the same path stops it at its last one, saying why, with
// every point before it kept.
TEST(HbmContinuation, APathTurningMoreOftenThanAllowedStopsAndSaysSo) {
  const HarmonicBalance system(impact_pair(), {.harmonics = 5});
  ContinuationOptions options;
  options.omega_start = 800.0;
  options.omega_end = 1600.0;
  const ContinuationResult free = continue_in_frequency(system, options);
  ASSERT_TRUE(free.converged) << free.failure;
  ASSERT_GE(free.turning_points, 2);
  const int cap = free.turning_points - 1;
  options.max_turning_points = cap;
  const ContinuationResult capped = continue_in_frequency(system, options);
  EXPECT_FALSE(capped.converged);
  EXPECT_EQ(capped.turning_points, cap + 1);
  EXPECT_NE(capped.failure.find(fmt::format("turned back and forth {} times", cap + 1)), std::string::npos)
      << capped.failure;
  ASSERT_GE(capped.points.size(), 2u);
  EXPECT_LT(capped.points.size(), free.points.size());
  for (size_t i = 0; i < capped.points.size(); ++i) EXPECT_EQ(capped.points[i].omega, free.points[i].omega);
}

TEST(HbmContinuation, StoppedPathReportsFrequencyAndResidualWithoutNaN) {
  const HarmonicBalance system(impact_pair(), {.harmonics = 3});
  const ContinuationResult r =
      continue_in_frequency(system, {.omega_start = 800.0, .omega_end = 1600.0, .max_points = 5, .progress = {}});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.points.size(), 5u);
  EXPECT_NE(r.failure.find("omega ="), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("|R| ="), std::string::npos) << r.failure;
  for (const ContinuationPoint& p : r.points) EXPECT_TRUE(p.x.allFinite() && std::isfinite(p.omega));
}

TEST(HbmMultiDof, ExtremeParametersConvergeOrReportFailureWithoutNaN) {
  int converged = 0, failed = 0, worst_iterations = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const double kn : {1.0e3, 1.0e12})
    for (const double kt : {1.0e3, 1.0e12})
      for (const double mu : {0.0, 2.0})
        for (const double force : {0.01, 3000.0}) {
          const friction::FrictionModel m = blade_on_ground({.kn = kn, .kt = kt, .mu = mu, .n0 = 10.0}, force, 1e-5);
          const HarmonicBalance system(m, {.harmonics = 3});
          for (const double omega : {900.0, 1300.0}) {
            const HbmSolution s = solve_at_frequency(system, omega);
            EXPECT_TRUE(s.x.allFinite());
            EXPECT_TRUE(std::isfinite(s.residual));
            EXPECT_LE(s.iterations, 3 * (system.options().max_iterations + 1));
            worst_iterations = std::max(worst_iterations, s.iterations);
            if (s.converged)
              ++converged;
            else {
              ++failed;
              EXPECT_FALSE(s.failure.empty());
              std::printf("  kn %.0e kt %.0e mu %.0f F %.2g omega %.0f: %s\n", kn, kt, mu, force, omega,
                          s.failure.c_str());
            }
          }
        }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("  extremes: %d converged, %d reported failure, worst %d iterations, %.2f s\n", converged, failed,
              worst_iterations, seconds);
}

TEST(HbmMultiDof, RigidNonContactPartIsRejectedWithAClearMessage) {
  friction::FrictionModel m = blade_on_ground({.kn = 1.0e5, .kt = 1.0e5, .mu = 0.3, .n0 = 10.0}, 1.0);
  m.stiffness.row(0).setZero();
  m.stiffness.col(0).setZero();  // the root DOF is now free when the contact DOFs are clamped
  try {
    const HarmonicBalance system(m, {});
    FAIL() << "a singular K_oo must be rejected";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rigid-body mode"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb::hbm
