// Implicit direct time integration of a small dense model with point friction contacts: thesis
// section 3.4 (eqs 3.36, 3.43), the friction system of hbm/friction_system.hpp. Units: SI.
//
//   M q'' + C q' + K q + sum_k (a_t,k^T T_k + a_n,k^T N_k) = f_static + f(t),
//
// T_k, N_k the Table XII slider of contact k (timeint/contact_step.hpp, = friction::jenkins_step).
//
// Scheme: Newmark with the HHT-alpha modification (Hilber, Hughes, Taylor 1977): alpha in
// [-1/3, 0], beta = (1 - alpha)^2 / 4, gamma = 1/2 - alpha; the balance is written at
// t_n+1+alpha with every force (inertia excepted) weighted (1 + alpha) at n+1 and -alpha at n.
// alpha = 0 is the average-acceleration (trapezoidal) rule, beta = 1/4, gamma = 1/2: second order,
// unconditionally stable for the linear part and energy-conserving; alpha < 0 stays second order
// and damps the highest frequencies (numerical dissipation grows with omega dt).
//
// Solution per step. With the predictors q~ = q_n + dt v_n + dt^2 (1/2 - beta) a_n and
// v~ = v_n + dt (1 - gamma) a_n, the end-of-step balance in q = q_n+1 is
//   K_eff q + (1 + alpha) g(q) = b,   K_eff = M / (beta dt^2) + (1 + alpha) (gamma / (beta dt) C + K),
// g the generalized contact force. K_eff is factorized once (constructor, one dt). g touches only
// the contact DOFs c (any nonzero entry of some a_t or a_n); the other DOFs o are condensed exactly,
// S = K_eff,cc - K_eff,co K_eff,oo^-1 K_eff,oc (the condensation of hbm/friction_system.hpp, which
// the harmonic balance applies per harmonic), and Newton's method (linalg/damped_newton.hpp) runs
// on the |c| contact DOFs with the consistent tangent of the slider (ContactSample::tangent): the law is
// piecewise linear, so once the states are right the next iterate is exact, and the step size is
// set by accuracy only. Each Newton step is backtracked (Armijo on ||R||) so that a state switch
// cannot make the iteration cycle.
//
// The slider is advanced from its converged position at the start of the step (return mapping), so
// a step is exact for contact motion that is monotone within the step; stick-slip transitions
// inside a step are not located, so once the contacts slip the global order is no longer a clean
// two (the friction oscillator's first harmonic: observed orders 1.3 to 2.6 between 128 and 512
// steps per period, error 1.2e-4 relative at 512; tests/unit/time_contact_test.cpp).
#pragma once
#include <Eigen/Dense>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "friction/friction_system.hpp"
#include "timeint/contact_step.hpp"

namespace bb::timeint {

struct NewmarkOptions {
  double time_step = 0.0;   // dt [s], > 0, finite
  double alpha = 0.0;       // HHT alpha in [-1/3, 0]; 0 = average acceleration
  int max_iterations = 30;  // Newton iterations per step
  // A step has converged when ||R|| <= tolerance * (force_scale + ||b_c||) [N]: R the condensed
  // balance on the contact DOFs, force_scale() = ||f_static|| + sum_k (1 + mu_k) N0_k, b_c the
  // condensed right-hand side (inertia included), with which the round-off in R grows at small dt.
  double tolerance = 1e-10;
  int max_backtracks = 20;  // halvings of a Newton step
};

// External load beyond f_static, a function of time [N], one entry per DOF.
using Excitation = std::function<Eigen::VectorXd(double)>;

// f(t) = Re(F e^{i omega t}) (cos for real F): the harmonic_load of a friction::FrictionModel.
Excitation harmonic_excitation(const Eigen::VectorXcd& amplitude, double omega_rad_s);
// f(t) = Re sum_h F_h e^{i h omega t} over the model's excitation (harmonic_load and higher_loads).
Excitation model_excitation(const friction::FrictionModel& model, double omega_rad_s);
// f(t) = 0.
Excitation no_excitation(Eigen::Index dofs);

// Cumulative work since the start of a run [J], each integral by the trapezoidal rule over the
// steps (exact bookkeeping for average acceleration: excitation - viscous - friction - normal equals
// the change of kinetic + strain energy to round-off).
struct WorkLedger {
  double excitation = 0.0;  // integral of (f_static + f) . dq
  double viscous = 0.0;     // integral of (C q') . dq
  double friction = 0.0;    // sum_k integral of T_k du_k
  double normal = 0.0;      // sum_k integral of N_k dv_k
};

// Everything a step needs from the previous one.
struct DynamicState {
  double time = 0.0;                    // [s]
  Eigen::VectorXd displacement;         // q [m]
  Eigen::VectorXd velocity;             // q' [m/s]
  Eigen::VectorXd acceleration;         // q'' [m/s^2], in balance with the forces below
  Eigen::VectorXd load;                 // f_static + f(time) [N]
  std::vector<ContactSample> contacts;  // per contact; .slider is the slider position now
  WorkLedger work;
};

struct StepReport {
  int iterations = 0;
  double residual = 0.0;  // ||R|| at the accepted iterate [N]
  bool converged = false;
  std::string failure;  // with the time and the residual; empty when converged
};

class NewmarkIntegrator {
 public:
  // Validates the model (sizes, finite entries, laws; contacts may be empty: a linear model), the
  // options, M (must be invertible: the initial acceleration) and factorizes K_eff and S.
  // Throws std::invalid_argument naming the requirement that fails.
  NewmarkIntegrator(friction::FrictionModel model, NewmarkOptions options);

  const friction::FrictionModel& model() const { return model_; }
  const NewmarkOptions& options() const { return options_; }
  const std::vector<Eigen::Index>& contact_dofs() const { return system_.contact_dofs(); }
  double force_scale() const { return force_scale_; }
  double beta() const { return beta_; }
  double gamma() const { return gamma_; }

  // State at time t0 from q0, v0 and each contact's slider position (empty: every slider at its
  // u, i.e. closed with zero tangential force). The contact forces are those of contact_step from
  // the given slider (a slider beyond the Coulomb limit is pulled back onto it) and the acceleration
  // balances M a = f_static + f(t0) - C v0 - K q0 - g.
  DynamicState initial_state(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double t0,
                             const Excitation& excitation, const std::vector<double>& sliders = {}) const;

  // Advances `state` by one time step. On failure the state is left unchanged.
  StepReport step(DynamicState& state, const Excitation& excitation) const;

  // 1/2 q'^T M q' + 1/2 q^T K q [J] (contact springs excluded).
  double mechanical_energy(const DynamicState& state) const;

 private:
  Eigen::VectorXd contact_force(const std::vector<ContactSample>& samples) const;  // g on all DOFs

  friction::FrictionModel model_;
  NewmarkOptions options_;
  double beta_ = 0.25, gamma_ = 0.5;
  friction::FrictionSystem system_;
  Eigen::PartialPivLU<Eigen::MatrixXd> mass_lu_;
  std::optional<friction::Condensation<double>> keff_;  // K_eff condensed onto the contact DOFs
  double force_scale_ = 0.0;
};

// ---- Runs ----

struct RecordOptions {
  std::vector<Eigen::Index> dofs;  // DOFs whose displacement is recorded at every step
  bool contacts = true;            // record every contact's sample at every step
};

struct TimeHistory {
  std::vector<double> time;                          // steps + 1 instants (the start included)
  Eigen::MatrixXd displacement;                      // (steps + 1) x dofs.size() [m]
  std::vector<std::vector<ContactSample>> contacts;  // [contact][instant]
  std::vector<int> iterations;                       // Newton iterations per step
  int steps = 0;                                     // steps taken (fewer than asked on failure)
  long total_iterations = 0;
  int max_iterations = 0;
  bool converged = false;    // every step converged
  std::string failure;       // the failed step's message (time, residual)
  DynamicState final_state;  // after the last converged step
};

// `steps` steps from `start`. Stops at the first step that fails, with its message.
[[nodiscard]] TimeHistory integrate(const NewmarkIntegrator& integrator, const DynamicState& start,
                                    const Excitation& excitation, int steps, const RecordOptions& record = {});

}  // namespace bb::timeint
