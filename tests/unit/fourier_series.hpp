// Truncated Fourier series in the harmonic balance's layout [c0, a1, b1, a2, b2, ...] and the
// Jenkins element's describing function, shared by the AFT tests.
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <random>

#include "friction/aft.hpp"

namespace bb::friction {

// The series c at the phase angle theta.
inline double evaluate(const Eigen::VectorXd& c, double theta) {
  double x = c[0];
  for (int h = 1; h <= harmonics_of(c.size()); ++h)
    x += c[2 * h - 1] * std::cos(h * theta) + c[2 * h] * std::sin(h * theta);
  return x;
}

// Random coefficient vector: c0 within mean +- amplitude / 2, harmonic h within +-amplitude / h.
inline Eigen::VectorXd random_coefficients(std::mt19937& rng, int harmonics, double amplitude, double mean = 0.0) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd c(harmonic_size(harmonics));
  c[0] = mean + 0.5 * amplitude * unit(rng);
  for (int h = 1; h <= harmonics; ++h) {
    c[2 * h - 1] = amplitude * unit(rng) / h;
    c[2 * h] = amplitude * unit(rng) / h;
  }
  return c;
}

// Describing function of the Jenkins element (Griffin, "Friction damping of resonant stresses in gas
// turbine engine airfoils", J. Eng. Power 102, 1980, whose equivalent stiffness and damping of the
// elastic-Coulomb damper are these coefficients divided by U): integrating the parallelogram loop
// under u = U cos(theta) at slip force F against cos and sin over a period,
//   a1 = (kt U / pi) (beta - sin(2 beta) / 2),   b1 = -(kt U / pi) sin^2(beta)   (U > F / kt),
//   a1 = kt U, b1 = 0 (stuck), with cos beta = 1 - 2 F / (kt U).
// Then W = -pi b1 U = kt U^2 sin^2 beta = 4 F (U - F / kt), the parallelogram's area.
inline Eigen::Vector2d describing_function(double amplitude, double kt, double slip_force) {
  if (kt * amplitude <= slip_force) return {kt * amplitude, 0.0};
  const double beta = std::acos(1.0 - 2.0 * slip_force / (kt * amplitude));
  return {kt * amplitude / std::numbers::pi * (beta - 0.5 * std::sin(2.0 * beta)),
          -kt * amplitude / std::numbers::pi * std::pow(std::sin(beta), 2)};
}

}  // namespace bb::friction
