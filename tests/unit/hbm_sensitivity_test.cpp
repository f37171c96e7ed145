// Implicit-function-theorem sensitivities of harmonic-balance solutions (hbm/sensitivity) and the
// AFT law derivatives behind them (friction/aft, law_derivatives), against central differences of
// full re-solves and of the AFT. Units: SI.
//
// Every parameter is a relative scale s (p -> s p, derivative at s = 1, i.e. p d/dp), for kn, kt,
// mu, N0, the damping (C -> s C: zeta d/dzeta for modal damping) and the harmonic load. The
// difference step is 1e-6 relative. Its error budget, relative to the sensitivity: the solves stop
// at ||R|| <= 1e-12 of the force scale, which after the division by 2e-6 leaves up to ~1e-6 of the
// force scale in dR, hence the 1e-5 bound on the solves (tighter than the budget would be luck);
// truncation is O(1e-12) (smooth on one piece of the piecewise-smooth map) and rounding ~1e-10.
// Measured: <= 1e-8 everywhere (Newton ends far below its tolerance), while a dropped term of the
// chain rule or of the condensation shows up at O(1). The AFT alone is a march to machine
// precision, bilinear in the parameters on one piece: its bound is 1e-7 (measured <= 5e-9). Where a difference
// would straddle a switch (some sample sticks at s = 1 + h and slips at 1 - h) it measures the jump
// of the map, not its derivative: every comparison first asserts that no sample of the +h and -h
// solutions changed state, and the points below are chosen away from switches.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "../extremes/hbm_models.hpp"
#include "common/errors.hpp"
#include "frf/receptance.hpp"
#include "friction/aft.hpp"
#include "hbm/harmonic_balance.hpp"
#include "hbm/sensitivity.hpp"

namespace bb::hbm {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kStep = 1e-6;        // relative central-difference step
constexpr double kSolveBound = 1e-5;  // see the header
constexpr double kAftBound = 1e-7;
constexpr double kSolverTolerance = 1e-12;

enum Parameter { p_kn, p_kt, p_mu, p_n0, p_zeta, p_load, parameter_count };
constexpr std::array<const char*, parameter_count> kNames{"kn", "kt", "mu", "n0", "zeta", "load"};

friction::FrictionModel scaled(friction::FrictionModel m, int which, double s) {
  for (friction::ContactElement& c : m.contacts) {
    if (which == p_kn) c.point.kn *= s;
    if (which == p_kt) c.point.kt *= s;
    if (which == p_mu) c.point.mu *= s;
    if (which == p_n0) c.point.n0 *= s;
  }
  if (which == p_zeta) m.damping *= s;
  if (which == p_load) friction::scale_excitation(m, s);
  return m;
}

// d/ds of scaled(m, which, s) at s = 1.
ModelDerivative scale_derivative(const friction::FrictionModel& m, int which) {
  if (which == p_zeta) return damping_scale_derivative(m);
  if (which == p_load) return excitation_scale_derivative(m);
  ModelDerivative d = law_derivative(m, static_cast<friction::LawParameter>(which));
  for (size_t k = 0; k < m.contacts.size(); ++k) {
    const friction::PointParameters& law = m.contacts[k].point;
    d.laws[k].kn *= law.kn, d.laws[k].kt *= law.kt, d.laws[k].mu *= law.mu, d.laws[k].n0 *= law.n0;
  }
  return d;
}

struct StateCount {
  int stick = 0, slip = 0, open = 0;
};

StateCount count_states(const HbmSolution& s) {
  StateCount c;
  for (const friction::AftResult& r : s.contacts)
    for (const friction::ContactState state : r.state) {
      if (state == friction::ContactState::stick)
        ++c.stick;
      else if (state == friction::ContactState::lift_off)
        ++c.open;
      else
        ++c.slip;
    }
  return c;
}

bool same_states(const HbmSolution& a, const HbmSolution& b) {
  for (size_t k = 0; k < a.contacts.size(); ++k)
    if (a.contacts[k].state != b.contacts[k].state) return false;
  return true;
}

enum class Regime { stuck, stick_slip, gross_slip, lift_off };

const char* regime_name(Regime r) {
  switch (r) {
    case Regime::stuck:
      return "stuck";
    case Regime::stick_slip:
      return "stick-slip";
    case Regime::gross_slip:
      return "gross slip";
    case Regime::lift_off:
      return "lift-off";
  }
  return "?";
}

// The regime is asserted, not assumed: a model change that moves the point into another regime
// must fail here rather than silently test something else.
void expect_regime(const HbmSolution& s, Regime regime) {
  const StateCount c = count_states(s);
  const double total = c.stick + c.slip + c.open, slip = c.slip / total;
  switch (regime) {
    case Regime::stuck:
      EXPECT_EQ(c.stick, total);
      break;
    case Regime::stick_slip:
      EXPECT_EQ(c.open, 0);
      EXPECT_GT(slip, 0.1);
      EXPECT_LT(slip, 0.75);
      break;
    case Regime::gross_slip:
      EXPECT_EQ(c.open, 0);
      EXPECT_GE(slip, 0.75);
      break;
    case Regime::lift_off:
      EXPECT_GT(c.open, 0);
      EXPECT_GT(c.stick + c.slip, 0);
      break;
  }
}

struct Comparison {
  double worst = 0.0;  // max over parameters of the relative difference
  std::array<double, parameter_count> error{};
};

// Relative difference of an analytic sensitivity to its central difference. Below 1e-6 of the
// solution norm a sensitivity is compared in absolute terms at that level (the difference noise).
double relative(const MatrixXd& analytic, const MatrixXd& fd, double scale) {
  return (analytic - fd).norm() / std::max(fd.norm(), 1e-6 * scale);
}

HbmOptions tight(int harmonics) { return {.harmonics = harmonics, .tolerance = kSolverTolerance}; }

// Analytic vs central differences of warm-started re-solves for every parameter, at omega.
Comparison compare(const friction::FrictionModel& model, int harmonics, double omega, Regime regime,
                   const char* label) {
  const HarmonicBalance system(model, tight(harmonics));
  const HbmSolution base = solve_at_frequency(system, omega);
  EXPECT_TRUE(base.converged) << base.failure;
  if (!base.converged) return {1.0, {}};
  expect_regime(base, regime);
  std::vector<ModelDerivative> derivatives;
  for (int p = 0; p < parameter_count; ++p) derivatives.push_back(scale_derivative(model, p));
  const MatrixXd dx = solution_sensitivity(system, base, derivatives);
  const std::vector<MatrixXd> dq = response_sensitivity(system, base, derivatives);
  const MatrixXd q = system.recover(base.x, omega);

  Comparison out;
  const StateCount c = count_states(base);
  std::printf("  %-12s %-10s (stick %d, slip %d, open %d):", label, regime_name(regime), c.stick, c.slip, c.open);
  for (int p = 0; p < parameter_count; ++p) {
    std::array<HbmSolution, 2> s;
    std::array<MatrixXd, 2> qs;
    for (int side = 0; side < 2; ++side) {
      const HarmonicBalance perturbed(scaled(model, p, side == 0 ? 1.0 + kStep : 1.0 - kStep), tight(harmonics));
      s[side] = solve_at_frequency(perturbed, omega, base.x);
      EXPECT_TRUE(s[side].converged) << kNames[p] << ": " << s[side].failure;
      EXPECT_TRUE(same_states(base, s[side])) << kNames[p] << ": a sample changed state within the step";
      qs[side] = perturbed.recover(s[side].x, omega);
    }
    const MatrixXd fd_x = (s[0].x - s[1].x) / (2.0 * kStep);
    const MatrixXd fd_q = (qs[0] - qs[1]) / (2.0 * kStep);
    const double e = std::max(relative(dx.col(p), fd_x, base.x.norm()), relative(dq[p], fd_q, q.norm()));
    // The solution vector and the recovered harmonics must agree with each other exactly.
    const Eigen::Index nc = static_cast<Eigen::Index>(system.contact_dofs().size());
    for (Eigen::Index i = 0; i < nc; ++i)
      for (Eigen::Index j = 0; j < q.cols(); ++j)
        EXPECT_EQ(dq[p](system.contact_dofs()[static_cast<size_t>(i)], j), dx(j * nc + i, p));
    out.error[p] = e;
    out.worst = std::max(out.worst, e);
    std::printf(" %s %.1e", kNames[p], e);
    EXPECT_LT(e, kSolveBound) << label << ", " << regime_name(regime) << ", d/d" << kNames[p] << ": analytic "
                              << dx.col(p).transpose() << "\n  differences " << fd_x.transpose();
  }
  std::printf("\n");
  return out;
}

// One DOF against the ground: m x'' + c x' + k x + T = F cos(omega t), k = 1e6 N/m, m = 1 kg
// (omega_0 = 1000 rad/s), 1 % damping. a_n = 0: N = N0 throughout; a_n = 0.5 (inclined contact):
// v = x / 2 varies and opens the contact for x < -2 N0 / kn.
friction::FrictionModel oscillator(const friction::PointParameters& law, double force, double inclination) {
  friction::FrictionModel m;
  m.mass = MatrixXd::Constant(1, 1, 1.0);
  m.stiffness = MatrixXd::Constant(1, 1, 1.0e6);
  m.damping = modal_damping_matrix(m.stiffness, m.mass, 0.01);
  m.contacts.push_back({law, Eigen::RowVectorXd::Constant(1, 1.0), Eigen::RowVectorXd::Constant(1, inclination)});
  m.harmonic_load = Eigen::VectorXcd::Constant(1, force);
  return m;
}

TEST(HbmSensitivity, OneDofOscillatorMatchesCentralDifferencesInEveryRegime) {
  const friction::PointParameters law{.kn = 2.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 100.0};  // mu N0 = 30 N
  compare(oscillator(law, 5.0, 0.0), 3, 1300.0, Regime::stuck, "1-DOF");
  compare(oscillator(law, 20.0, 0.0), 3, 1300.0, Regime::stick_slip, "1-DOF");
  compare(oscillator(law, 200.0, 0.0), 3, 900.0, Regime::gross_slip, "1-DOF");
  compare(oscillator({.kn = 2.0e6, .kt = 1.0e6, .mu = 0.3, .n0 = 10.0}, 30.0, 0.5), 3, 1200.0, Regime::lift_off,
          "1-DOF");
}

TEST(HbmSensitivity, LoadOfSeveralHarmonicsMatchesCentralDifferences) {
  // A distorted excitation (a shaker's third harmonic): every derivative carries it.
  const friction::PointParameters law{.kn = 2.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 100.0};
  friction::FrictionModel m = oscillator(law, 20.0, 0.0);
  m.higher_loads = {Eigen::VectorXcd(), Eigen::VectorXcd::Constant(1, std::complex<double>(3.0, 2.0))};
  compare(m, 5, 1300.0, Regime::stick_slip, "1-DOF h1+h3");
}

TEST(HbmSensitivity, BladeOnGroundMatchesCentralDifferencesInEveryRegime) {
  const friction::PointParameters law{.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 50.0};
  const double omega = 0.9 * models::stuck_resonance(models::blade_on_ground(law, 1.0), 0);
  compare(models::blade_on_ground(law, 2.0), 3, omega, Regime::stuck, "blade");
  compare(models::blade_on_ground(law, 30.0), 3, omega, Regime::stick_slip, "blade");
  compare(models::blade_on_ground(law, 150.0), 3, omega, Regime::gross_slip, "blade");
  compare(models::blade_on_ground({.kn = 5.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 5.0}, 80.0), 5, 1100.0, Regime::lift_off,
          "blade");
}

TEST(HbmSensitivity, PlanarDamperMatchesCentralDifferences) {
  // Three contacts, every DOF a contact DOF, K_cc singular (the damper is held by its contacts).
  // The sliders rest at the frictionless static seat (as hbm_analysis does): from zero offsets the
  // first period would slip into the seat and leave a sample exactly on the Coulomb limit, a kink
  // whose state flips under any perturbation.
  const friction::PointParameters law{.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 0.0};
  for (const auto& [force, below, regime] :
       {std::tuple{2.0, 0.98, Regime::stuck}, std::tuple{200.0, 0.9, Regime::stick_slip}}) {
    friction::FrictionModel model = models::planar_blades_with_damper(law, force, 1e-2);
    MatrixXd k = model.stiffness;
    for (const friction::ContactElement& c : model.contacts) k += c.point.kn * c.normal.transpose() * c.normal;
    const VectorXd seat = k.fullPivLu().solve(model.static_load);
    for (friction::ContactElement& c : model.contacts) c.tangential_offset = c.tangential.dot(seat);
    compare(model, 1, below * models::stuck_resonance(model, 0), regime, "damper");
  }
}

TEST(HbmSensitivity, StuckContactHasExactlyZeroFrictionSensitivity) {
  // A contact stuck throughout never reaches mu N: the solution cannot depend on mu at all.
  const friction::PointParameters law{.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 50.0};
  const friction::FrictionModel model = models::blade_on_ground(law, 2.0);
  const HarmonicBalance system(model, tight(3));
  const HbmSolution s = solve_at_frequency(system, 0.9 * models::stuck_resonance(model, 0));
  ASSERT_TRUE(s.converged) << s.failure;
  expect_regime(s, Regime::stuck);
  const MatrixXd dx = solution_sensitivity(system, s, {law_derivative(model, friction::law_mu)});
  EXPECT_EQ(dx.norm(), 0.0);
  EXPECT_GT(solution_sensitivity(system, s, {law_derivative(model, friction::law_kt)}).norm(), 0.0);
}

TEST(HbmSensitivity, FrictionlessContactHasExactlyZeroTangentialStiffnessSensitivity) {
  // mu = 0: the contact slips with T = 0 at every sample, whatever kt; N still depends on kn.
  const friction::PointParameters law{.kn = 3.0e5, .kt = 1.0e6, .mu = 0.0, .n0 = 50.0};
  const friction::FrictionModel model = models::blade_on_ground(law, 10.0);
  const HarmonicBalance system(model, tight(3));
  const HbmSolution s = solve_at_frequency(system, 1000.0);
  ASSERT_TRUE(s.converged) << s.failure;
  const MatrixXd dx = solution_sensitivity(
      system, s, {law_derivative(model, friction::law_kt), law_derivative(model, friction::law_kn)});
  EXPECT_EQ(dx.col(0).norm(), 0.0);
  EXPECT_GT(dx.col(1).norm(), 0.0);
}

TEST(HbmSensitivity, AmplitudeSensitivityIsTheDerivativeOfTheFirstHarmonicModulus) {
  const friction::PointParameters law{.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 50.0};
  const friction::FrictionModel model = models::blade_on_ground(law, 30.0);
  const double omega = 0.9 * models::stuck_resonance(model, 0);
  const HarmonicBalance system(model, tight(3));
  const HbmSolution s = solve_at_frequency(system, omega);
  ASSERT_TRUE(s.converged) << s.failure;
  expect_regime(s, Regime::stick_slip);
  const std::vector<ModelDerivative> d{scale_derivative(model, p_mu), scale_derivative(model, p_zeta)};
  for (const Eigen::Index dof : {0, 1}) {  // the condensed root and a contact DOF
    const VectorXd analytic = amplitude_sensitivity(system, s, d, dof);
    for (size_t j = 0; j < d.size(); ++j) {
      std::array<double, 2> amplitude{};
      for (int side = 0; side < 2; ++side) {
        const HarmonicBalance p(scaled(model, j == 0 ? p_mu : p_zeta, side == 0 ? 1.0 + kStep : 1.0 - kStep), tight(3));
        const HbmSolution ps = solve_at_frequency(p, omega, s.x);
        ASSERT_TRUE(ps.converged && same_states(s, ps));
        const MatrixXd q = p.recover(ps.x, omega);
        amplitude[static_cast<size_t>(side)] = std::hypot(q(dof, 1), q(dof, 2));
      }
      const double fd = (amplitude[0] - amplitude[1]) / (2.0 * kStep);
      EXPECT_NEAR(analytic[static_cast<Eigen::Index>(j)], fd, kSolveBound * std::abs(fd)) << "DOF " << dof;
    }
  }
  EXPECT_THROW((void)amplitude_sensitivity(system, s, d, 3), std::invalid_argument);
}

TEST(HbmSensitivity, RefusesAnUnconvergedSolutionAndMismatchedDerivatives) {
  const friction::PointParameters law{.kn = 3.0e5, .kt = 1.0e6, .mu = 0.3, .n0 = 50.0};
  const friction::FrictionModel model = models::blade_on_ground(law, 15.0);
  const HarmonicBalance system(model, tight(1));
  HbmSolution s = solve_at_frequency(system, 1000.0);
  ASSERT_TRUE(s.converged) << s.failure;
  ModelDerivative wrong;
  wrong.stiffness = MatrixXd::Identity(2, 2);
  EXPECT_THROW((void)solution_sensitivity(system, s, {wrong}), std::invalid_argument);
  s.converged = false;
  EXPECT_THROW((void)solution_sensitivity(system, s, {damping_scale_derivative(model)}), SolverError);
}

// ---- The AFT law derivatives on their own: exact for the discrete march, so only rounding. ----

struct AftCase {
  const char* name;
  friction::PointParameters point;
  double u1, v0, v1;  // u = u1 cos + small 3rd harmonic; v = v0 + v1 sin
};

TEST(AftLawDerivatives, MatchCentralDifferencesOfTheMarch) {
  const std::vector<AftCase> cases{
      {"stuck", {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 100.0}, 1e-5, 0.0, 1e-5},
      {"stick-slip, constant N", {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 100.0}, 1e-4, 0.0, 0.0},
      {"stick-slip, varying N", {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 100.0}, 1e-4, 1e-5, 5e-5},
      {"gross slip", {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 100.0}, 2e-3, 0.0, 2e-5},
      {"lift-off", {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 10.0}, 1e-4, 0.0, 3e-5},
  };
  const friction::AftOptions plain{.samples = 112};  // H = 3 below, the default 16 (2H + 1)
  friction::AftOptions with = plain;
  with.law_derivatives = true;
  for (const AftCase& c : cases) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(friction::harmonic_size(3)),
                    v = Eigen::VectorXd::Zero(friction::harmonic_size(3));
    u[1] = c.u1, u[5] = 0.1 * c.u1, v[0] = c.v0, v[2] = c.v1;
    const friction::AftResult r = friction::aft_jenkins(c.point, u, v, with);
    ASSERT_EQ(r.dtangential_dlaw.rows(), 7);
    ASSERT_EQ(r.dtangential_dlaw.cols(), 4);
    // The flag adds outputs only.
    const friction::AftResult reference = friction::aft_jenkins(c.point, u, v, plain);
    EXPECT_EQ(reference.dtangential_dlaw.size(), 0);
    EXPECT_EQ((reference.tangential - r.tangential).norm(), 0.0);
    EXPECT_EQ((reference.dtangential_du - r.dtangential_du).norm(), 0.0);
    std::printf("  AFT %-24s", c.name);
    for (int p = 0; p < 4; ++p) {
      std::array<friction::AftResult, 2> side;
      double value = 0.0;
      for (int k = 0; k < 2; ++k) {
        friction::PointParameters law = c.point;
        double* field = p == 0 ? &law.kn : p == 1 ? &law.kt : p == 2 ? &law.mu : &law.n0;
        value = *field;
        *field *= k == 0 ? 1.0 + kStep : 1.0 - kStep;
        side[static_cast<size_t>(k)] = friction::aft_jenkins(law, u, v, plain);
        ASSERT_EQ(side[static_cast<size_t>(k)].state, r.state) << c.name << ": a sample switched within the step";
      }
      const Eigen::VectorXd fd_t = (side[0].tangential - side[1].tangential) / (2.0 * kStep * value);
      const Eigen::VectorXd fd_n = (side[0].normal - side[1].normal) / (2.0 * kStep * value);
      // Compared per unit relative change of the parameter, against the force scale mu N0 + kn |v|.
      const double scale = c.point.mu * c.point.n0 + c.point.kn * v.norm();
      const double e_t =
          (r.dtangential_dlaw.col(p) - fd_t).norm() * value / std::max(fd_t.norm() * value, 1e-6 * scale);
      const double e_n = (r.dnormal_dlaw.col(p) - fd_n).norm() * value / std::max(fd_n.norm() * value, 1e-6 * scale);
      std::printf(" %s %.1e/%.1e", kNames[static_cast<size_t>(p)], e_t, e_n);
      EXPECT_LT(e_t, kAftBound) << c.name << ", dT/d" << kNames[static_cast<size_t>(p)];
      EXPECT_LT(e_n, kAftBound) << c.name << ", dN/d" << kNames[static_cast<size_t>(p)];
    }
    std::printf("\n");
  }
}

TEST(AftLawDerivatives, StuckLoopIgnoresFrictionAndFrictionlessLoopIgnoresTangentialStiffness) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
  u[1] = 1e-5, v[2] = 1e-5;
  const friction::AftOptions options{.samples = 64, .law_derivatives = true};
  const friction::AftResult stuck =
      friction::aft_jenkins({.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 100.0}, u, v, options);
  EXPECT_EQ(stuck.dtangential_dlaw.col(friction::law_mu).norm(), 0.0);
  EXPECT_EQ(stuck.dtangential_dlaw.col(friction::law_kn).norm(), 0.0);
  // T = kt u exactly: dT/dkt = u.
  EXPECT_LT((stuck.dtangential_dlaw.col(friction::law_kt) - u).norm(), 1e-13 * u.norm());  // P E = I to rounding
  const friction::AftResult free = friction::aft_jenkins({.kn = 1e6, .kt = 1e6, .mu = 0.0, .n0 = 100.0}, u, v, options);
  EXPECT_EQ(free.dtangential_dlaw.col(friction::law_kt).norm(), 0.0);
  EXPECT_GT(free.dtangential_dlaw.col(friction::law_mu).norm(), 0.0);
}

}  // namespace
}  // namespace bb::hbm
