// Harmonic balance of a one-DOF friction oscillator, the smallest complete use of the AFT
// (aft.hpp): m x'' + c x' + k x + T(x) = F cos(omega t), with a Jenkins contact between the mass and
// the ground at constant normal load N0 (v = 0). The frequency-domain balance of thesis eqs
// 3.13-3.15 with H harmonics, solved by Newton's method (eq 3.35) with the exact AFT Jacobian and a
// backtracking line search. Units: SI.
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <string>

#include "contact/aft.hpp"
#include "contact/jenkins_contact.hpp"

namespace bb::contact {

struct FrictionOscillator {
  double mass = 0.0;       // m [kg], > 0
  double damping = 0.0;    // c [N s/m], >= 0
  double stiffness = 0.0;  // k [N/m], >= 0
  double force = 0.0;      // F [N], amplitude of the cosine excitation
  // Contact to the ground, u = x. The normal gap does not move, so N = N0 throughout and kn plays
  // no part; a stuck contact is the spring kt from x = aft.initial_slider.
  JenkinsParameters contact;
};

struct HbmOptions {
  int harmonics = 1;        // H
  // AFT options; samples = 0 picks max(64, 16 (2H + 1)), enough for coefficient errors ~1e-4 on
  // stick-slip loops (the forces have kinks, their harmonics converge as 1 / n_t^2).
  AftOptions aft{};
  int max_iterations = 50;
  // Converged when ||R|| <= tolerance * (|F| + mu N0), R the harmonic force balance [N].
  double tolerance = 1e-9;
  // Backtracking halves the Newton step until ||R|| drops by the Armijo factor (1 - 1e-4 alpha);
  // after this many halvings the iteration stops as failed.
  int max_backtracks = 30;
};

struct HbmSolution {
  Eigen::VectorXd x;              // harmonic coefficients of x(t) [m], layout of aft.hpp
  int iterations = 0;             // Newton iterations taken
  double residual = 0.0;          // ||R|| at x [N]
  bool converged = false;
  std::string failure;            // why not converged; empty when converged
  AftResult contact;              // the AFT at x: contact forces, Jacobian, time history, closure

  // sqrt(a1^2 + b1^2) [m]
  double first_harmonic_amplitude() const;
};

// Solves R(x) = A(omega) x + T(x) - F e_a1 = 0, A block-diagonal with k for the static term and
// [[k - m h^2 w^2, c h w], [-c h w, k - m h^2 w^2]] for harmonic h. Without `initial`, Newton starts
// from the better (smaller ||R||) of the two linear solutions, contact stuck (k + kt) or free (k):
// the limits of small and large amplitude. Throws std::invalid_argument on invalid parameters or
// options, never on non-convergence: that is returned with converged == false and a reason.
[[nodiscard]] HbmSolution solve_friction_oscillator(const FrictionOscillator& oscillator, double omega_rad_s,
                                                    const HbmOptions& options = {},
                                                    const std::optional<Eigen::VectorXd>& initial = std::nullopt);

}  // namespace bb::contact
