// Implicit Newmark / HHT-alpha integration of linear models (timeint/newmark): second-order
// convergence against the exact forced response of a 1-DOF oscillator, the period elongation of
// the average-acceleration rule, energy conservation (alpha = 0) and dissipation (alpha < 0), and
// the condensation onto contact DOFs agreeing with the uncondensed solve. Units: SI.
#include "timeint/newmark.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "common/constants.hpp"
#include "timeint/static_state.hpp"

namespace bb::timeint {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

friction::FrictionModel one_dof(double m, double c, double k) {
  friction::FrictionModel model;
  model.mass = MatrixXd::Constant(1, 1, m);
  model.damping = MatrixXd::Constant(1, 1, c);
  model.stiffness = MatrixXd::Constant(1, 1, k);
  return model;
}

// m u'' + c u' + k u = F cos(w t), u(0) = u'(0) = 0: particular Re(X e^{iwt}) plus the free
// response that cancels its initial values.
double exact_forced(double m, double c, double k, double force, double w, double t) {
  const std::complex<double> x = force / std::complex<double>(k - m * w * w, c * w);
  const double wn = std::sqrt(k / m), zeta = c / (2.0 * std::sqrt(k * m)), wd = wn * std::sqrt(1.0 - zeta * zeta);
  const double up0 = x.real(), vp0 = -w * x.imag();  // d/dt Re(X e^{iwt}) at 0 = Re(i w X)
  const double a = -up0, b = (-vp0 + zeta * wn * a) / wd;
  return (x * std::exp(std::complex<double>(0.0, w * t))).real() +
         std::exp(-zeta * wn * t) * (a * std::cos(wd * t) + b * std::sin(wd * t));
}

double max_error(double zeta, double alpha, double dt) {
  const double m = 2.0, k = m * 4.0 * kPi * kPi, c = 2.0 * zeta * std::sqrt(k * m), force = 3.0, w = 0.6 * 2.0 * kPi;
  friction::FrictionModel model = one_dof(m, c, k);
  const NewmarkIntegrator integrator(model, {.time_step = dt, .alpha = alpha});
  const Excitation f = harmonic_excitation(Eigen::VectorXcd::Constant(1, force), w);
  const int steps = static_cast<int>(std::lround(5.0 / dt));
  const TimeHistory h = integrate(integrator, integrator.initial_state(VectorXd::Zero(1), VectorXd::Zero(1), 0.0, f), f,
                                  steps, {.dofs = {0}, .contacts = false});
  EXPECT_TRUE(h.converged) << h.failure;
  double e = 0.0;
  for (int i = 0; i <= h.steps; ++i)
    e = std::max(e, std::abs(h.displacement(i, 0) - exact_forced(m, c, k, force, w, h.time[static_cast<size_t>(i)])));
  return e;
}

TEST(Newmark, ForcedOscillatorConvergesAtSecondOrderInTheTimeStep) {
  for (const double zeta : {0.0, 0.05}) {
    for (const double alpha : {0.0, -0.1, -1.0 / 3.0}) {
      double previous = 0.0;
      for (const double dt : {1.0 / 40, 1.0 / 80, 1.0 / 160, 1.0 / 320}) {
        const double e = max_error(zeta, alpha, dt);
        if (previous > 0.0) {
          const double order = std::log2(previous / e);
          std::printf("  zeta %.2f alpha %+.3f dt 1/%3.0f: max error %.3e m, observed order %.3f\n", zeta, alpha,
                      1.0 / dt, e, order);
          EXPECT_GE(order, 1.8);
          EXPECT_LE(order, 2.2);
        }
        previous = e;
      }
    }
  }
}

TEST(Newmark, AverageAccelerationPeriodElongationIsOmegaOverTwoArctanHalfOmega) {
  // Free vibration with omega = 1: the discrete solution obeys u_n+1 + u_n-1 = 2 cos(phi) u_n exactly,
  // phi = omega_bar dt, so T_num / T = Omega / phi (Omega = omega dt) to round-off.
  for (const double big_omega : {0.05, 0.3, 1.0, 2.0, 4.0}) {
    const friction::FrictionModel model = one_dof(1.0, 0.0, 1.0);
    const NewmarkIntegrator integrator(model, {.time_step = big_omega});
    const Excitation f = no_excitation(1);
    const TimeHistory h = integrate(integrator, integrator.initial_state(VectorXd::Ones(1), VectorXd::Zero(1), 0.0, f),
                                    f, 40, {.dofs = {0}, .contacts = false});
    ASSERT_TRUE(h.converged);
    Eigen::Index best = 1;
    for (Eigen::Index i = 1; i < h.steps; ++i)
      if (std::abs(h.displacement(i, 0)) > std::abs(h.displacement(best, 0))) best = i;
    const double cos_phi =
        (h.displacement(best + 1, 0) + h.displacement(best - 1, 0)) / (2.0 * h.displacement(best, 0));
    const double measured = big_omega / std::acos(cos_phi);
    const double formula = big_omega / (2.0 * std::atan(big_omega / 2.0));
    std::printf("  Omega %.2f: T_num / T = %.12f (formula %.12f)\n", big_omega, measured, formula);
    EXPECT_NEAR(measured, formula, 1e-9 * formula);
  }
}

// Three-mass chain, fixed at one end, undamped: frequencies ~ 0.45 to 1.8 rad/s per unit.
friction::FrictionModel chain() {
  friction::FrictionModel model;
  model.mass = Eigen::Vector3d(1.0, 2.0, 0.5).asDiagonal();
  model.stiffness.resize(3, 3);
  model.stiffness << 2.0, -1.0, 0.0, -1.0, 2.0, -1.0, 0.0, -1.0, 1.0;
  return model;
}

TEST(Newmark, AverageAccelerationConservesEnergyAndHhtDissipatesIt) {
  const friction::FrictionModel model = chain();
  const Excitation f = no_excitation(3);
  const VectorXd q0 = Eigen::Vector3d(0.3, -0.7, 1.1), v0 = Eigen::Vector3d(0.2, 0.0, -0.4);
  for (const double alpha : {0.0, -0.05, -0.3}) {
    const NewmarkIntegrator integrator(model, {.time_step = 0.8, .alpha = alpha});
    DynamicState s = integrator.initial_state(q0, v0, 0.0, f);
    const double e0 = integrator.mechanical_energy(s);
    double drift = 0.0;
    for (int i = 0; i < 2000; ++i) {
      ASSERT_TRUE(integrator.step(s, f).converged);
      drift = std::max(drift, std::abs(integrator.mechanical_energy(s) - e0) / e0);
    }
    const double e_end = integrator.mechanical_energy(s);
    std::printf("  alpha %+.2f: E_end / E0 = %.15f, max |E - E0| / E0 = %.2e\n", alpha, e_end / e0, drift);
    if (alpha == 0.0) {
      EXPECT_LT(drift, 1e-12);
    } else {
      EXPECT_LT(e_end, (1.0 - 1e-3) * e0);
    }
  }
}

TEST(Newmark, CondensationOntoContactDofsMatchesTheFullSolveOfALinearModel) {
  // A frictionless, always-closed contact is a normal spring kn on a_n: the condensed Newton step must
  // give the same history as the plain linear model with that spring added.
  friction::FrictionModel with_contact = chain();
  with_contact.damping = 0.01 * with_contact.stiffness;
  const Eigen::RowVectorXd a_n = Eigen::RowVector3d(0.0, 1.0, -1.0);
  with_contact.contacts.push_back({.point = {.kn = 3.0, .kt = 1.0, .mu = 0.0, .n0 = 100.0},
                                   .tangential = Eigen::RowVector3d(0.0, 1.0, 0.0),
                                   .normal = a_n});
  friction::FrictionModel linear = chain();
  linear.damping = with_contact.damping;
  linear.stiffness += 3.0 * a_n.transpose() * a_n;
  linear.static_load = -100.0 * a_n.transpose();
  const Eigen::VectorXcd force = Eigen::Vector3cd(1.0, 0.0, 0.0);
  const Excitation f = harmonic_excitation(force, 0.9);
  const NewmarkIntegrator a(with_contact, {.time_step = 0.1}), b(linear, {.time_step = 0.1});
  // Both start from their static state (eq 3.49), so the contact stays closed (N0 = 100 N).
  const StaticState s = static_initial_state(with_contact);
  ASSERT_TRUE(s.converged) << s.failure;
  const VectorXd q_linear = linear.stiffness.lu().solve(linear.static_load);
  EXPECT_LT((s.q - q_linear).norm(), 1e-12 * q_linear.norm());
  const VectorXd zero = VectorXd::Zero(3);
  const TimeHistory ha = integrate(a, a.initial_state(s.q, zero, 0.0, f, s.sliders), f, 500, {.dofs = {0, 1, 2}});
  const TimeHistory hb = integrate(b, b.initial_state(q_linear, zero, 0.0, f), f, 500, {.dofs = {0, 1, 2}});
  ASSERT_TRUE(ha.converged && hb.converged);
  for (const ContactSample& p : ha.contacts[0]) ASSERT_GT(p.normal, 0.0);
  EXPECT_LT((ha.displacement - hb.displacement).cwiseAbs().maxCoeff(), 1e-10 * hb.displacement.cwiseAbs().maxCoeff());
  EXPECT_EQ(a.contact_dofs().size(), 2u);  // DOF 0 (excited) is condensed
  EXPECT_LE(ha.max_iterations, 1);         // linear law: one Newton step is exact
}

TEST(Newmark, InvalidOptionsAreRejectedWithAMessage) {
  const friction::FrictionModel model = chain();
  EXPECT_THROW(NewmarkIntegrator(model, {.time_step = 0.0}), std::invalid_argument);
  EXPECT_THROW(NewmarkIntegrator(model, {.time_step = 0.1, .alpha = -0.5}), std::invalid_argument);
  EXPECT_THROW(NewmarkIntegrator(model, {.time_step = 0.1, .alpha = 0.1}), std::invalid_argument);
}

}  // namespace
}  // namespace bb::timeint
