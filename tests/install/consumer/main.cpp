// Uses the installed solvers as another project would: the harmonic balance of a friction
// oscillator driven far below its slip force, against the closed form of its stuck (linear) limit.
#include <bladebench/hbm/harmonic_balance.hpp>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

int main() {
  bb::friction::FrictionModel m;
  m.mass = Eigen::MatrixXd::Constant(1, 1, 1.0);
  m.damping = Eigen::MatrixXd::Constant(1, 1, 20.0);
  m.stiffness = Eigen::MatrixXd::Constant(1, 1, 1e6);
  m.contacts.push_back({.point = {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 30.0},
                        .tangential = Eigen::RowVectorXd::Ones(1),
                        .normal = Eigen::RowVectorXd::Zero(1)});
  m.harmonic_load = Eigen::VectorXcd::Constant(1, 0.01);
  const bb::hbm::HarmonicBalance system(m, {.harmonics = 3});
  const double omega = 2 * std::numbers::pi * 200.0;
  const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(system, omega);
  const double amplitude = std::hypot(s.x[1], s.x[2]);
  const double exact = 0.01 / std::abs(std::complex<double>(2e6 - omega * omega, 20.0 * omega));
  std::printf("consumer: converged %d, amplitude %.10e m, closed form %.10e m\n", s.converged ? 1 : 0, amplitude,
              exact);
  return s.converged && std::abs(amplitude / exact - 1) < 1e-9 ? 0 : 1;
}
