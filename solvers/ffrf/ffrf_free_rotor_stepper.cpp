// Generalized-alpha step of the free-rotor equations (ffrf/ffrf_integrator.hpp): unknowns the
// accelerations (a_theta, a_q) at t_n+1, residual
//   R = (1 - a_m) I_n+1 + a_m I_n + (1 - a_f) F_n+1 + a_f F_n,
// I = [J(q) a_theta + c(q).a_q ; M a_q + c(q) a_theta] the inertia terms (c = g0 + G q, mass matrix
// of eq 2.31 restricted to theta and q), F the remaining terms moved to the left. Newton's method
// with the exact Jacobian, solved by bordering: the q-q block has the structure of the prescribed
// effective matrix, the theta row and column are dense vectors.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "ffrf/ffrf_steppers.hpp"

namespace bb::ffrf::detail {

namespace {

// Bordered solve of [j_tt, j_tq^T; j_qt, J_qq] [x_t; x_q] = [b_t; b_q] with a factorized J_qq.
std::pair<double, Eigen::VectorXd> bordered_solve(const CoordinateSolver& jqq, double j_tt, const Eigen::VectorXd& j_tq,
                                                  const Eigen::VectorXd& j_qt, double b_t, const Eigen::VectorXd& b_q) {
  const Eigen::VectorXd y1 = jqq.solve(b_q), y2 = jqq.solve(j_qt);
  const double x_t = (b_t - j_tq.dot(y1)) / (j_tt - j_tq.dot(y2));
  return {x_t, y1 - y2 * x_t};
}

}  // namespace

FreeRotorStepper::FreeRotorStepper(const Dynamics& dynamics, const RotationProfile& rotation,
                                   const FfrfOptions& options)
    : d_(dynamics),
      rotation_(rotation),
      options_(options),
      ga_(chung_hulbert(options.rho_infinity)),
      dt_(options.time_step) {
  if (!mass_solver_.factorize(d_.body().mass))
    throw SolverError("FFRF integrator: the mass matrix in the elastic coordinates is singular: " +
                      mass_solver_.message());
}

// F of the state: f_theta = 2 Omega q'.h - tau - Q_g, f_q = K q - Omega^2 h + (2 Omega G + C) q' - f_g.
void FreeRotorStepper::forces(const StepState& s, double& f_theta, Eigen::VectorXd& f_q, double* scale_theta,
                              double* scale_q) const {
  const ProjectedBody& p = d_.body();
  const Eigen::VectorXd hq = d_.h(s.q);
  const double coriolis_torque = 2.0 * s.omega * s.v.dot(hq), tau = rotation_.torque(s.t);
  const double q_g = d_.gravity_moment(s.theta, s.q);
  f_theta = coriolis_torque - tau - q_g;
  const Eigen::VectorXd kq = p.stiffness * s.q;
  const Eigen::VectorXd gyro = (2.0 * s.omega * d_.coriolis()) * (p.gyroscopic * s.v);
  const Eigen::VectorXd damp = d_.damping_force(s.v), grav = d_.gravity_load(s.theta);
  f_q = kq - (s.omega * s.omega) * hq + gyro + damp - grav;
  if (scale_theta) *scale_theta = std::abs(coriolis_torque) + std::abs(tau) + std::abs(q_g);
  if (scale_q) *scale_q = kq.norm() + s.omega * s.omega * hq.norm() + gyro.norm() + damp.norm() + grav.norm();
}

StepState FreeRotorStepper::start(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0) {
  StepState s;
  s.t = 0.0;
  s.theta = rotation_.initial_angle();
  s.omega = rotation_.initial_speed();
  s.q = q0;
  s.v = v0;
  const auto [alpha, qdd] = true_accelerations(s);
  s.alpha = alpha;
  s.a = qdd;
  forces(s, f_theta_, f_q_);
  i_theta_ = -f_theta_;  // the true accelerations balance the forces
  i_q_ = -f_q_;
  return s;
}

std::pair<double, Eigen::VectorXd> FreeRotorStepper::true_accelerations(const StepState& s) const {
  double f_theta = 0.0;
  Eigen::VectorXd f_q;
  forces(s, f_theta, f_q);
  const Eigen::VectorXd c = d_.coupling(s.q);
  const double j = d_.axis_inertia(s.q, d_.h(s.q));
  return bordered_solve(mass_solver_, j, c, c, -f_theta, -f_q);
}

// Residual of the balance at the accelerations (a_theta, a_q) from the predictors `pred`.
FreeRotorStepper::Trial FreeRotorStepper::evaluate(const StepState& pred, double a_theta,
                                                   const Eigen::VectorXd& a_q) const {
  const double b = ga_.beta * dt_ * dt_, g = ga_.gamma * dt_;
  const double am = 1.0 - ga_.alpha_m, af = 1.0 - ga_.alpha_f;
  Trial tr;
  tr.state = pred;
  tr.state.theta = pred.theta + b * a_theta;
  tr.state.omega = pred.omega + g * a_theta;
  tr.state.q = pred.q + b * a_q;
  tr.state.v = pred.v + g * a_q;
  tr.state.alpha = a_theta;
  tr.state.a = a_q;
  double scale_theta = 0.0, scale_q = 0.0;
  forces(tr.state, tr.f_theta, tr.f_q, &scale_theta, &scale_q);
  tr.hq = d_.h(tr.state.q);
  tr.c = d_.coupling(tr.state.q);
  tr.j = d_.axis_inertia(tr.state.q, tr.hq);
  tr.i_theta = tr.j * a_theta + tr.c.dot(a_q);
  tr.i_q = d_.body().mass * a_q + tr.c * a_theta;
  tr.r_theta = am * tr.i_theta + ga_.alpha_m * i_theta_ + af * tr.f_theta + ga_.alpha_f * f_theta_;
  tr.r_q = am * tr.i_q + ga_.alpha_m * i_q_ + af * tr.f_q + ga_.alpha_f * f_q_;
  // Convergence is measured against the size of the terms of each equation (theta: N m, q: N).
  scale_theta = am * (std::abs(tr.j * a_theta) + std::abs(tr.c.dot(a_q))) + af * scale_theta +
                ga_.alpha_m * std::abs(i_theta_) + ga_.alpha_f * std::abs(f_theta_) + 1e-300;
  scale_q = am * tr.i_q.norm() + af * scale_q + ga_.alpha_m * i_q_.norm() + ga_.alpha_f * f_q_.norm() + 1e-300;
  tr.relative_residual = std::max(std::abs(tr.r_theta) / scale_theta, tr.r_q.norm() / scale_q);
  return tr;
}

// One Newton correction of (a_theta, a_q) with the exact Jacobian dR/d(a_theta, a_q), by bordering.
void FreeRotorStepper::newton_update(const Trial& tr, int iteration, double& a_theta, Eigen::VectorXd& a_q) {
  const double b = ga_.beta * dt_ * dt_, g = ga_.gamma * dt_;
  const double am = 1.0 - ga_.alpha_m, af = 1.0 - ga_.alpha_f;
  const ProjectedBody& p = d_.body();
  const Switches& sw = d_.switches();
  const StepState& x = tr.state;
  const bool refactor =
      jqq_.size() == 0 || p.mass.is_dense() || iteration == 0 || iteration == options_.max_newton_iterations / 2;
  if (refactor) {
    combine_into({{am + af * g * sw.rayleigh_mass, &p.mass},
                  {af * (g * sw.rayleigh_stiffness + b), &p.stiffness},
                  {-af * b * x.omega * x.omega, &d_.softening()},
                  {af * g * 2.0 * x.omega * d_.coriolis() + am * b * a_theta, &p.gyroscopic}},
                 jqq_);
    if (!jacobian_.factorize(jqq_))
      throw SolverError(
          fmt::format("FFRF free rotor: Jacobian singular at t = {:.6g} s: {}", x.t, jacobian_.message()));
    ++counters_.factorizations;
  }
  const Eigen::VectorXd gv = p.gyroscopic * x.v;
  const Eigen::VectorXd j_qt = am * tr.c + af * (g * (2.0 * d_.coriolis() * gv - 2.0 * x.omega * tr.hq) -
                                                 b * d_.gravity_load_derivative(x.theta));
  const Eigen::VectorXd j_tq = am * (tr.c + b * (2.0 * a_theta * tr.hq - p.gyroscopic * a_q)) +
                               af * (g * 2.0 * x.omega * tr.hq + b * (2.0 * x.omega * (d_.softening() * x.v) -
                                                                      d_.gravity_moment_gradient(x.theta)));
  const double j_tt = am * tr.j + af * (g * 2.0 * x.v.dot(tr.hq) - b * d_.gravity_moment(x.theta, x.q, 1));
  const auto [d_theta, d_q] = bordered_solve(jacobian_, j_tt, j_tq, j_qt, -tr.r_theta, -tr.r_q);
  a_theta += d_theta;
  a_q += d_q;
}

void FreeRotorStepper::step(StepState& s) {
  const double dt2 = dt_ * dt_, b = ga_.beta, g = ga_.gamma;
  StepState pred = s;  // predictors: the trial accelerations add beta dt^2 a and gamma dt a
  pred.t = s.t + dt_;
  pred.theta = s.theta + dt_ * s.omega + dt2 * (0.5 - b) * s.alpha;
  pred.omega = s.omega + dt_ * (1.0 - g) * s.alpha;
  pred.q = s.q + dt_ * s.v + (dt2 * (0.5 - b)) * s.a;
  pred.v = s.v + (dt_ * (1.0 - g)) * s.a;
  double a_theta = s.alpha;  // the previous accelerations start the iteration
  Eigen::VectorXd a_q = s.a;
  for (int k = 0;; ++k) {
    const Trial tr = evaluate(pred, a_theta, a_q);
    if (tr.relative_residual <= options_.newton_tolerance) {
      counters_.iterations += k;
      counters_.max_iterations = std::max(counters_.max_iterations, k);
      counters_.max_residual = std::max(counters_.max_residual, tr.relative_residual);
      s = tr.state;
      i_theta_ = tr.i_theta;
      i_q_ = tr.i_q;
      f_theta_ = tr.f_theta;
      f_q_ = tr.f_q;
      return;
    }
    if (k == options_.max_newton_iterations)
      throw SolverError(
          fmt::format("FFRF free rotor: Newton did not converge at t = {:.6g} s (Omega = {:.6g} rad/s): "
                      "relative residual {:.3e} > {:.1e} after {} iterations; reduce the time step",
                      pred.t, tr.state.omega, tr.relative_residual, options_.newton_tolerance, k));
    newton_update(tr, k, a_theta, a_q);
  }
}

}  // namespace bb::ffrf::detail
