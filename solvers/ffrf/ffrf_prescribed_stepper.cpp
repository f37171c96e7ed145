// Generalized-alpha step of the prescribed-rotation equations (ffrf/ffrf_integrator.hpp).
//
// With predictors q~ = q_n + dt v_n + dt^2 (1/2 - beta) a_n, v~ = v_n + dt (1 - gamma) a_n and the
// force residual r(t, q, v) = C(Omega) v + K(Omega, alpha) q - f(t), the balance
//   (1 - a_m) M a_n+1 + a_m M a_n + (1 - a_f) r_n+1 + a_f r_n = 0
// is linear in a_n+1: A a_n+1 = -[(1 - a_f) r(t_n+1, q~, v~) + a_m M a_n + a_f r_n], with
//   A = (1 - a_m) M + (1 - a_f) (gamma dt C(Omega_n+1) + beta dt^2 K(Omega_n+1, alpha_n+1)).
// The prescribed Euler term alpha (g0 + G q) stays in the force group (weighted a_f): putting a
// known function of time with the inertia weights would shift it by (a_m - a_f) dt, first order.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "ffrf/ffrf_steppers.hpp"

namespace bb::ffrf::detail {
namespace {

constexpr int kMaxCorrections = 4;
// Relative residual of a corrected solve: far below the time-discretization error, and above the
// round-off floor of a direct solve (~1e-13 here), which a tighter target would chase in vain.
constexpr double kCorrectionTolerance = 1e-10;

}  // namespace

PrescribedStepper::PrescribedStepper(const Dynamics& dynamics, const RotationProfile& rotation,
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

// K(Omega, alpha) = K - Omega^2 (M_p - s K_s1) + alpha G and C(Omega) = 2 Omega G + C_Rayleigh, combined
// once per (Omega, alpha): a residual then costs two sparse products instead of four.
void PrescribedStepper::update_operators(double omega, double alpha) {
  if (operators_ready_ && omega == operators_omega_ && alpha == operators_alpha_) return;
  const ProjectedBody& p = d_.body();
  const Switches& sw = d_.switches();
  combine_into({{1.0, &p.stiffness}, {-omega * omega, &d_.softening()}, {alpha, &p.gyroscopic}}, k_);
  combine_into({{2.0 * omega * d_.coriolis(), &p.gyroscopic},
                {sw.rayleigh_mass, &p.mass},
                {sw.rayleigh_stiffness, &p.stiffness}},
               c_);
  operators_ready_ = true;
  operators_omega_ = omega;
  operators_alpha_ = alpha;
}

Eigen::VectorXd PrescribedStepper::residual(double t, double omega, double alpha, double theta,
                                            const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  update_operators(omega, alpha);
  Eigen::VectorXd r = k_ * q + c_ * v - d_.static_load(theta, omega, alpha);
  if (d_.loaded()) r -= d_.external_load(t);
  return r;
}

void PrescribedStepper::effective_matrix(double omega, double alpha, CoordinateMatrix& out) const {
  const double af = 1.0 - ga_.alpha_f, gdt = ga_.gamma * dt_, bdt2 = ga_.beta * dt_ * dt_;
  const Switches& sw = d_.switches();
  const ProjectedBody& p = d_.body();
  combine_into({{(1.0 - ga_.alpha_m) + af * gdt * sw.rayleigh_mass, &p.mass},
                {af * (gdt * sw.rayleigh_stiffness + bdt2), &p.stiffness},
                {-af * bdt2 * omega * omega, &d_.softening()},
                {af * (gdt * 2.0 * omega * d_.coriolis() + bdt2 * alpha), &p.gyroscopic}},
               out);
}

// A x = b with A(Omega, alpha). Constant (Omega, alpha): the held factorization. Otherwise either a
// new factorization or, for the nodal basis, iterative correction with the stale one, which
// converges as ||A_old^-1 (A - A_old)|| (of order dOmega dt) and is abandoned when slow.
Eigen::VectorXd PrescribedStepper::solve_effective(double omega, double alpha, const Eigen::VectorXd& b) {
  if (factored_ && omega == factored_omega_ && alpha == factored_alpha_) return effective_.solve(b);
  effective_matrix(omega, alpha, current_);
  const bool correct =
      factored_ && !current_.is_dense() && options_.factorization == FactorizationReuse::with_correction;
  if (correct) {
    Eigen::VectorXd x = effective_.solve(b);
    const double target = kCorrectionTolerance * b.norm();
    double previous = std::numeric_limits<double>::infinity();
    for (int k = 0; k < kMaxCorrections; ++k) {
      const Eigen::VectorXd res = b - current_ * x;
      const double norm = res.norm();
      ++counters_.iterations;
      if (norm <= target) return x;
      if (norm > 0.25 * previous) break;  // contraction too slow: refactorize
      previous = norm;
      x += effective_.solve(res);
    }
  }
  if (!effective_.factorize(current_))
    throw SolverError(fmt::format("FFRF integrator: effective matrix singular at Omega = {:.6g} rad/s: {}", omega,
                                  effective_.message()));
  ++counters_.factorizations;
  factored_ = true;
  factored_omega_ = omega;
  factored_alpha_ = alpha;
  return effective_.solve(b);
}

StepState PrescribedStepper::start(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0) {
  StepState s;
  s.t = 0.0;
  s.theta = rotation_.angle(0.0);
  s.omega = rotation_.speed(0.0);
  s.alpha = rotation_.acceleration(0.0);
  s.q = q0;
  s.v = v0;
  r_ = residual(s.t, s.omega, s.alpha, s.theta, s.q, s.v);
  s.a = -mass_solver_.solve(r_);  // the true initial acceleration
  ma_ = d_.body().mass * s.a;
  return s;
}

void PrescribedStepper::step(StepState& s) {
  const double t1 = s.t + dt_;
  const double theta1 = rotation_.angle(t1), omega1 = rotation_.speed(t1), alpha1 = rotation_.acceleration(t1);
  const double dt2 = dt_ * dt_;
  const Eigen::VectorXd qt = s.q + dt_ * s.v + (dt2 * (0.5 - ga_.beta)) * s.a;
  const Eigen::VectorXd vt = s.v + (dt_ * (1.0 - ga_.gamma)) * s.a;
  const Eigen::VectorXd b =
      -((1.0 - ga_.alpha_f) * residual(t1, omega1, alpha1, theta1, qt, vt) + ga_.alpha_m * ma_ + ga_.alpha_f * r_);
  const Eigen::VectorXd a1 = solve_effective(omega1, alpha1, b);
  s.t = t1;
  s.theta = theta1;
  s.omega = omega1;
  s.alpha = alpha1;
  s.q = qt + (ga_.beta * dt2) * a1;
  s.v = vt + (ga_.gamma * dt_) * a1;
  s.a = a1;
  // The balance gives the new force residual without evaluating it: r_n+1 = -[(1 - a_m) M a_n+1 +
  // a_m M a_n + a_f r_n] / (1 - a_f) (exact to the solve's accuracy, and recomputed from the state
  // at every predictor, so no drift accumulates).
  const Eigen::VectorXd ma1 = d_.body().mass * a1;
  r_ = -((1.0 - ga_.alpha_m) * ma1 + ga_.alpha_m * ma_ + ga_.alpha_f * r_) / (1.0 - ga_.alpha_f);
  ma_ = ma1;
}

Eigen::VectorXd PrescribedStepper::true_acceleration() const { return -mass_solver_.solve(r_); }

double PrescribedStepper::driving_torque(const StepState& s) const {
  const Eigen::VectorXd hq = d_.h(s.q);
  const Eigen::VectorXd qdd = true_acceleration();
  return d_.axis_inertia(s.q, hq) * s.alpha + d_.coupling(s.q).dot(qdd) + 2.0 * s.omega * s.v.dot(hq) -
         d_.gravity_moment(s.theta, s.q);
}

}  // namespace bb::ffrf::detail
