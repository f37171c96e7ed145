// Time integration of a deformable body on a rotor turning about a fixed axis (floating frame of
// reference, ffrf/rotating_body.hpp), in the coordinates of an elastic basis. SI units.
//
// Prescribed rotation theta(t): the linear time-varying equations of the elastic coordinates
//   M q'' + (2 Omega G + C) q' + (K + s Omega^2 K_s1 - Omega^2 M_p + alpha G) q
//       = Omega^2 f_c + alpha f_alpha + F_g R(theta)^T g + f_ext(t),
// (thesis eqs 2.13, 2.31; Shabana ch. 5), C = a_M M + b_K K (Rayleigh), s = 1 with stiffening.
// Free rotation under a torque tau(t): theta is an unknown; Lagrange's equation for theta (the
// rotor row of eq 2.31, with the quadratic-velocity vector Q_v) couples it to q:
//   [J(q)            (g0 + G q)^T] [theta'']   [2 Omega q'^T h(q)                         ]   [tau + Q_g]
//   [g0 + G q        M           ] [q''     ] + [(2 Omega G + C) q' + K q - Omega^2 h(q)   ] = [f_g + f_ext]
// with h(q) = f_c + (M_p - s K_s1) q, J(q) = J_rotor + J0 + q^T (f_c + h(q)), g0 = -f_alpha.
// The stiffening enters as the second-order (foreshortening) part of the kinetic energy,
// -1/2 s Omega^2 q^T K_s1 q (Kane, Ryan & Banerjee 1987; Simo & Vu-Quoc 1987), so that
//   T = 1/2 q'^T M q' + Omega q'^T (g0 + G q) + 1/2 Omega^2 J(q),   H = dT/dOmega = Omega J(q) + q'^T (g0 + G q),
// and for a free rotor without gravity, damping or f_ext: d(T + U)/dt = tau Omega, dH/dt = tau.
//
// Scheme: generalized-alpha (Chung & Hulbert 1993) with alpha_m = (2 rho - 1)/(rho + 1),
// alpha_f = rho/(rho + 1), gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4:
// second order, unconditionally stable for linear systems, high-frequency spectral radius rho_inf.
// Inertia and force terms are weighted (1 - alpha) at t_n+1 and alpha at t_n ("force interpolation",
// which keeps second order with time-varying coefficients). Prescribed rotation: one linear solve
// per step, the effective matrix refactorized only when (Omega, alpha) change (constant speed: one
// factorization per run). Free rotation: Newton per step on the accelerations (exact Jacobian;
// nodal basis: modified Newton with one factorization per step).
#pragma once
#include <Eigen/Dense>

#include <functional>
#include <vector>

#include "common/errors.hpp"
#include "ffrf/elastic_basis.hpp"
#include "ffrf/rotation_profile.hpp"

namespace bb::ffrf {

// How a prescribed, time-varying speed reuses the effective matrix's factorization (nodal basis;
// a modal basis refactorizes its small dense matrix whenever it changes).
enum class FactorizationReuse {
  every_change,     // refactorize whenever (Omega, alpha) change: every step of a spin-up
  with_correction,  // keep a stale factorization and correct iteratively (x += A_old^-1 (b - A x)),
                    // refactorizing when the correction converges slowly (bench/bench_ffrf.cpp measures)
};

struct FfrfOptions {
  // dt [s], required: > 0, <= end_time; shortened (never lengthened) so that an integer number of
  // steps ends exactly at end_time. A sensible choice: 20-40 steps per period of the highest mode
  // whose response matters (rotating_modes at the run's speeds); the generalized-alpha period error
  // is (omega dt)^2 / 12, 0.2 % at 40 steps per period.
  double time_step = 0.0;
  double end_time = 0.0;  // [s], required; the run starts at t = 0
  // Spectral radius at infinite frequency. 0.9 by default: the sudden start of a constant-speed run
  // excites every mode, and the unresolved high ones would otherwise ring forever at aliased
  // frequencies (rho = 1 is the trapezoidal rule, no dissipation); with 0.9 they lose 10 % per step,
  // while a mode resolved by 20 (40) steps per period loses 1.4e-5 (1.8e-6) of its amplitude per
  // period (spectral radius of the amplification matrix of Chung & Hulbert's scheme).
  double rho_infinity = 0.9;
  int output_stride = 1;                              // record every n-th step (the first and last instants always)
  bool stiffening = true;                             // geometric stiffening s Omega^2 K_s1 (s = 1), off: s = 0
  bool coriolis = true;                               // the gyroscopic term 2 Omega G q' of the elastic equations
  double rotor_inertia = 0.0;                         // J_rotor about the axis [kg m^2]: T, H and the torque include it
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // inertial frame [m/s^2]; 2D: z must be 0
  double rayleigh_mass = 0.0;                         // a_M [1/s] of C = a_M M + b_K K
  double rayleigh_stiffness = 0.0;                    // b_K [s]
  std::vector<int> output_dofs;                       // global DOFs (node * dim + dir) recorded, rotating frame
  // Start from the steady state at Omega(0) (static centrifugal + gravity deflection at theta(0),
  // at rest in the rotating frame) instead of from the undeformed body at rest.
  bool start_from_steady_state = false;
  // External load in the body frame on the free DOFs [N], as a function of time; empty = none.
  std::function<Eigen::VectorXd(double)> external_load;
  // Spin-up of the 480-DOF beam: every_change 3000 factorizations, with_correction 5 (and ~4
  // corrections per step), 35 % less time (bench/bench_ffrf.cpp).
  FactorizationReuse factorization = FactorizationReuse::with_correction;
  // Divergence, checked at every output sample and every 16 steps: the run stops with SolverError
  // when the mass-weighted RMS elastic displacement sqrt(q^T M q / m) exceeds this fraction of the
  // body size (the small-deformation FFRF model is meaningless beyond), when T + U exceeds the
  // energy supplied (initial + works) by more than 10 % of the run's energy scale (max of
  // 1/2 J Omega_max^2 + m |g| size and the energies met so far: numerical energy growth), or when
  // a value is not finite.
  double max_deflection_ratio = 0.5;
  int max_newton_iterations = 25;   // free rotor
  double newton_tolerance = 1e-10;  // relative to the size of the terms of each equation
};

struct FfrfHistory {
  std::vector<double> time;                        // [s]
  Eigen::MatrixXd displacement;                    // samples x output_dofs [m], rotating frame
  std::vector<double> angle, speed, acceleration;  // theta [rad], Omega [rad/s], alpha [rad/s^2]
  std::vector<double> kinetic_energy;              // T, inertial frame, body + rotor [J]
  std::vector<double> strain_energy;               // U = 1/2 q^T K q [J]
  std::vector<double> driving_work;                // integral tau Omega dt [J]
  std::vector<double> gravity_work;                // work of gravity, -(V_g - V_g0) [J]
  std::vector<double> external_work;               // integral f_ext . q' dt [J]
  std::vector<double> damping_work;                // integral q'^T C q' dt >= 0 [J]
  std::vector<double> angular_momentum;            // H about the axis [kg m^2/s]
  std::vector<double> driving_torque;  // prescribed: torque needed (dH/dt - gravity moment); free: applied [N m]
  Eigen::VectorXd final_coordinates;   // eta at the end
  Eigen::VectorXd final_velocity;
  int steps = 0;
  int factorizations = 0;     // of the effective (or Jacobian q-q) matrix
  long solve_iterations = 0;  // corrections (prescribed) or Newton iterations (free), summed
  int max_step_iterations = 0;
  double max_residual = 0.0;  // largest relative residual accepted (free rotor)

  // max over samples of |T + U - T0 - U0 - (driving + gravity + external - damping work)| [J].
  double energy_balance_error() const;
};

// A run that blew up (energy growth, a deflection beyond the small-deformation model, a non-finite
// value): a SolverError that also says when, for callers that report the divergence as a finding.
class DivergenceError : public SolverError {
 public:
  DivergenceError(const std::string& message, double time, double speed)
      : SolverError(message), time_(time), speed_(speed) {}
  double time() const { return time_; }    // [s]
  double speed() const { return speed_; }  // Omega then [rad/s]

 private:
  double time_, speed_;
};

// Integrates from t = 0 to end_time. Throws InputError for invalid options (message says what to
// change), DivergenceError when the run diverges and SolverError when a step does not converge
// (messages name the time).
[[nodiscard]] FfrfHistory integrate(const ProjectedBody& body, const RotationProfile& rotation,
                                    const FfrfOptions& options);

// Generalized-alpha parameters of Chung & Hulbert (1993) for a spectral radius rho_inf in [0, 1].
struct GeneralizedAlpha {
  double alpha_m, alpha_f, gamma, beta;
};
GeneralizedAlpha chung_hulbert(double rho_infinity);

}  // namespace bb::ffrf
