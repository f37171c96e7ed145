// Nonlinear modes by the extended periodic motion concept (hbm/nonlinear_modes.hpp) on the one-DOF
// Jenkins oscillator, whose single-harmonic mode has a closed form (the describing function of the
// elastic-perfectly-plastic slider), and on two coupled oscillators (symmetry, stuck limit). Units: SI.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/constants.hpp"
#include "hbm/nonlinear_modes.hpp"

namespace bb::hbm {
namespace {

// m = 1 kg on k = 1e6 N/m, c = 20 N s/m; a contact to the ground with kt = 5e5 N/m and a constant
// normal load of 20 N, mu = 0.5: it lets go after x_s = mu N / kt = 2e-5 m.
friction::FrictionModel oscillator() {
  friction::FrictionModel m;
  m.mass = Eigen::MatrixXd::Constant(1, 1, 1.0);
  m.stiffness = Eigen::MatrixXd::Constant(1, 1, 1.0e6);
  m.damping = Eigen::MatrixXd::Constant(1, 1, 20.0);
  friction::ContactElement c;
  c.point = {.kn = 0.0, .kt = 5.0e5, .mu = 0.5, .n0 = 20.0};
  c.tangential = Eigen::RowVectorXd::Constant(1, 1.0);
  c.normal = Eigen::RowVectorXd::Zero(1);
  m.contacts.push_back(c);
  return m;
}

// The single-harmonic mode at amplitude A (Griffin's describing function of the Jenkins element):
// in-phase force a1 = kt A (beta - sin 2 beta / 2) / pi, dissipation 4 mu N (A - x_s) per cycle,
// beta = acos(1 - 2 x_s / A); omega^2 = (k + a1 / A) / m and kappa m omega A^2 pi = c omega A^2 pi + dissipation.
struct ClosedForm {
  double omega, kappa;
};
ClosedForm closed_form(double amplitude) {
  const double m = 1.0, k = 1.0e6, c = 20.0, kt = 5.0e5, slip = 10.0, xs = slip / kt;
  if (amplitude <= xs) return {std::sqrt((k + kt) / m), c / m};
  const double beta = std::acos(1.0 - 2.0 * xs / amplitude);
  const double a1 = kt * amplitude * (beta - std::sin(2.0 * beta) / 2.0) / kPi;
  const double omega = std::sqrt((k + a1 / amplitude) / m);
  const double dissipated = 4.0 * slip * (amplitude - xs);
  return {omega, c / m + dissipated / (kPi * m * omega * amplitude * amplitude)};
}

TEST(NonlinearModes, SingleHarmonicModeOfTheJenkinsOscillatorIsItsDescribingFunction) {
  NonlinearModeOptions options;
  options.aft.samples = 2048;
  const std::vector<double> amplitudes = {1e-6, 1.5e-5, 2.5e-5, 5e-5, 1e-4, 1e-3, 1e-2};
  const NonlinearModeBranch b = trace_nonlinear_mode(oscillator(), 1, amplitudes, {}, options);
  ASSERT_TRUE(b.converged) << b.failure;
  ASSERT_EQ(b.points.size(), amplitudes.size());
  EXPECT_NEAR(b.linear_omega, std::sqrt(1.5e6), 1e-9 * std::sqrt(1.5e6));
  for (const NonlinearModePoint& p : b.points) {
    const ClosedForm exact = closed_form(p.modal_amplitude);
    EXPECT_NEAR(p.omega, exact.omega, 2e-4 * exact.omega) << "A = " << p.modal_amplitude;
    EXPECT_NEAR(p.kappa, exact.kappa, 2e-3 * exact.kappa) << "A = " << p.modal_amplitude;
    EXPECT_NEAR(p.damping_ratio(), p.kappa / (2 * p.omega), 1e-15);
  }
  // Stuck: the linear mode with the contact as a spring, its viscous damping only.
  EXPECT_NEAR(b.points[0].damping_ratio(), 20.0 / (2 * std::sqrt(1.5e6)), 1e-9);
  // Gross slip: the frequency falls to the free one and the friction damping fades as 1 / A.
  EXPECT_LT(b.points.back().omega, 1.001e3);
  const double peak_damping = closed_form(3 * 2e-5).kappa;  // friction damping peaks at A ~ 2-3 x_s
  EXPECT_GT(peak_damping, 5 * b.points.back().kappa);
}

// Two equal oscillators coupled by the contact: the in-phase mode does not load it (its frequency
// and damping stay those of one oscillator at every amplitude), the out-of-phase mode softens and
// gains friction damping.
TEST(NonlinearModes, InPhaseModeOfSymmetricBladesNeverLoadsTheirContact) {
  friction::FrictionModel m;
  m.mass = Eigen::Matrix2d::Identity();
  m.stiffness = (Eigen::Matrix2d() << 1.1e6, -1e5, -1e5, 1.1e6).finished();
  m.damping = 20.0 * Eigen::Matrix2d::Identity();
  friction::ContactElement c;
  c.point = {.kn = 1.0e6, .kt = 2.0e5, .mu = 0.3, .n0 = 20.0};
  c.tangential = Eigen::RowVector2d(1.0, -1.0);
  c.normal = Eigen::RowVector2d::Zero();
  m.contacts.push_back(c);
  NonlinearModeOptions options;
  options.aft.samples = 512;
  const std::vector<double> amplitudes = {1e-6, 1e-5, 1e-4, 1e-3};
  const NonlinearModeBranch ip = trace_nonlinear_mode(m, 1, amplitudes, {}, options);
  const NonlinearModeBranch oop = trace_nonlinear_mode(m, 2, amplitudes, {}, options);
  ASSERT_TRUE(ip.converged) << ip.failure;
  ASSERT_TRUE(oop.converged) << oop.failure;
  for (const NonlinearModePoint& p : ip.points) {
    EXPECT_NEAR(p.omega, 1000.0, 1e-9 * 1000.0);
    EXPECT_NEAR(p.damping_ratio(), 0.01, 1e-9);
    EXPECT_NEAR(p.coefficients(0, 1), p.coefficients(1, 1), 1e-9 * p.modal_amplitude);
  }
  const double stuck = std::sqrt(1.2e6 + 2 * 2e5);  // k + 2 kc + 2 kt on q_A - q_B
  EXPECT_NEAR(oop.points.front().omega, stuck, 1e-9 * stuck);
  EXPECT_LT(oop.points.back().omega, 0.9 * stuck);
  EXPECT_GT(oop.points[2].damping_ratio(), 2 * oop.points.front().damping_ratio());
}

TEST(NonlinearModes, RefusesAModeIndexOutsideTheModelAndAmplitudesThatDoNotIncrease) {
  EXPECT_THROW(trace_nonlinear_mode(oscillator(), 2, {1e-5}, {}, {}), std::invalid_argument);
  EXPECT_THROW(trace_nonlinear_mode(oscillator(), 1, {1e-5, 1e-6}, {}, {}), std::invalid_argument);
  EXPECT_THROW(trace_nonlinear_mode(oscillator(), 1, {0.0}, {}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace bb::hbm
