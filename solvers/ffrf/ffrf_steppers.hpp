// Internal to ffrf/: the generalized-alpha steppers of ffrf/ffrf_integrator.hpp, one for a
// prescribed rotation (linear, one solve per step) and one for a free rotor (Newton per step).
// Both keep, for the state they hold, the inertia and force terms of the last balance (the
// alpha-weighted parts of the next one). SI units.
#pragma once
#include <Eigen/Dense>

#include <string>

#include "ffrf/ffrf_dynamics.hpp"
#include "ffrf/ffrf_integrator.hpp"

namespace bb::ffrf::detail {

struct StepState {
  double t = 0.0;
  double theta = 0.0, omega = 0.0;
  double alpha = 0.0;    // prescribed: alpha(t); free rotor: the algorithmic rotor acceleration
  Eigen::VectorXd q, v;  // elastic coordinates and velocities
  Eigen::VectorXd a;     // algorithmic elastic acceleration
};

struct StepCounters {
  int factorizations = 0;
  long iterations = 0;     // corrections or Newton iterations
  int max_iterations = 0;  // in one step
  double max_residual = 0.0;
};

class PrescribedStepper {
 public:
  PrescribedStepper(const Dynamics& dynamics, const RotationProfile& rotation, const FfrfOptions& options);
  // State at t = 0 from q0, v0 (true initial acceleration).
  StepState start(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0);
  void step(StepState& s);
  // True elastic acceleration q'' of the held state (M q'' = f - C q' - K q).
  Eigen::VectorXd true_acceleration() const;
  // Torque the rotor must apply: dH/dt - Q_g (rotor row of eq 2.31 with the true accelerations).
  double driving_torque(const StepState& s) const;
  const StepCounters& counters() const { return counters_; }

 private:
  Eigen::VectorXd residual(double t, double omega, double alpha, double theta, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v);
  void update_operators(double omega, double alpha);
  Eigen::VectorXd solve_effective(double omega, double alpha, const Eigen::VectorXd& b);
  void effective_matrix(double omega, double alpha, CoordinateMatrix& out) const;

  const Dynamics& d_;
  const RotationProfile& rotation_;
  FfrfOptions options_;
  GeneralizedAlpha ga_;
  double dt_;
  Eigen::VectorXd r_;   // C v + K q - f at the held state
  Eigen::VectorXd ma_;  // M a at the held state
  CoordinateSolver mass_solver_, effective_;
  CoordinateMatrix current_;
  CoordinateMatrix k_, c_;  // K(Omega, alpha), C(Omega) of the last update_operators
  bool operators_ready_ = false;
  double operators_omega_ = 0.0, operators_alpha_ = 0.0;
  bool factored_ = false;
  double factored_omega_ = 0.0, factored_alpha_ = 0.0;
  StepCounters counters_;
};

class FreeRotorStepper {
 public:
  FreeRotorStepper(const Dynamics& dynamics, const RotationProfile& rotation, const FfrfOptions& options);
  StepState start(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0);
  // Throws SolverError naming the time when Newton does not converge.
  void step(StepState& s);
  // True accelerations (rotor alpha, elastic q'') of the held state from the coupled mass matrix.
  std::pair<double, Eigen::VectorXd> true_accelerations(const StepState& s) const;
  const StepCounters& counters() const { return counters_; }

 private:
  struct Trial {  // one Newton iterate: end-of-step state, inertia, forces and residual
    StepState state;
    Eigen::VectorXd hq, c, i_q, f_q, r_q;
    double j = 0.0, i_theta = 0.0, f_theta = 0.0, r_theta = 0.0, relative_residual = 0.0;
  };
  Trial evaluate(const StepState& pred, double a_theta, const Eigen::VectorXd& a_q) const;
  void newton_update(const Trial& tr, int iteration, double& a_theta, Eigen::VectorXd& a_q);
  void forces(const StepState& s, double& f_theta, Eigen::VectorXd& f_q, double* scale_theta = nullptr,
              double* scale_q = nullptr) const;

  const Dynamics& d_;
  const RotationProfile& rotation_;
  FfrfOptions options_;
  GeneralizedAlpha ga_;
  double dt_;
  double i_theta_ = 0.0, f_theta_ = 0.0;  // inertia and force terms of the held state
  Eigen::VectorXd i_q_, f_q_;
  CoordinateSolver mass_solver_, jacobian_;
  CoordinateMatrix jqq_;
  StepCounters counters_;
};

}  // namespace bb::ffrf::detail
