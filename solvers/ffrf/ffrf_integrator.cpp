#include "ffrf/ffrf_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "common/errors.hpp"
#include "ffrf/ffrf_steppers.hpp"

namespace bb::ffrf {
namespace {

// Steps between two energy and divergence checks when no output is due.
constexpr int kCheckInterval = 16;

void validate(const ProjectedBody& body, const RotationProfile& rotation, const FfrfOptions& o) {
  if (!(o.time_step > 0.0) || !std::isfinite(o.time_step))
    throw InputError(fmt::format("FFRF integrator: time_step must be > 0 s, got {}", o.time_step));
  if (!(o.end_time >= o.time_step) || !std::isfinite(o.end_time))
    throw InputError(fmt::format("FFRF integrator: end_time ({} s) must be finite and at least one time step ({} s)",
                                 o.end_time, o.time_step));
  if (!(o.rho_infinity >= 0.0 && o.rho_infinity <= 1.0))
    throw InputError(fmt::format("FFRF integrator: rho_infinity must be in [0, 1], got {}", o.rho_infinity));
  if (o.output_stride < 1)
    throw InputError(fmt::format("FFRF integrator: output_stride must be >= 1, got {}", o.output_stride));
  if (!o.gravity.allFinite() || (body.dim == 2 && o.gravity.z() != 0.0))
    throw InputError("FFRF integrator: gravity must be finite, and in the plane (z = 0) for a 2D body");
  if (!(o.rayleigh_mass >= 0.0) || !(o.rayleigh_stiffness >= 0.0))
    throw InputError("FFRF integrator: Rayleigh damping coefficients must be >= 0");
  if (!(o.rotor_inertia >= 0.0)) throw InputError("FFRF integrator: rotor_inertia must be >= 0 kg m^2");
  if (!(o.max_deflection_ratio > 0.0)) throw InputError("FFRF integrator: max_deflection_ratio must be > 0");
  if (o.max_newton_iterations < 1 || !(o.newton_tolerance > 0.0))
    throw InputError("FFRF integrator: max_newton_iterations must be >= 1 and newton_tolerance > 0");
  if (!rotation.prescribed() && o.external_load)
    throw InputError(
        "FFRF integrator: external_load with a free rotor is not supported (its moment on the rotor is "
        "not modelled); prescribe the rotation or apply the load as a torque");
  if (!rotation.prescribed() && o.rotor_inertia + body.mass_properties.axis_inertia <= 0.0)
    throw InputError("FFRF integrator: a free rotor needs a positive inertia about the axis (rotor_inertia)");
}

detail::Switches switches_of(const FfrfOptions& o) {
  return {o.stiffening, o.coriolis, o.rayleigh_mass, o.rayleigh_stiffness, o.rotor_inertia, o.gravity, o.external_load};
}

// Cumulative works by the trapezoidal rule over the steps, and the energy checks of a run. The
// per-step part is cheap (no matrix product unless the speed varies); the energies need a full
// snapshot, taken at the check instants (every output sample and every kCheckInterval steps).
class Ledger {
 public:
  // energy_scale: the run's natural energy (rigid rotation at the largest speed, gravity over the
  // body size), the floor of the growth check so that round-off at the quiet start cannot trip it.
  Ledger(const detail::Dynamics& d, const FfrfOptions& o, double energy_scale, bool prescribed, bool constant_speed)
      : d_(d), o_(o), scale_(energy_scale), prescribed_(prescribed), constant_speed_(constant_speed) {}

  void start(const detail::StepState& s, const detail::Snapshot& snap, double torque) {
    e0_ = snap.kinetic + snap.strain;
    v0_ = snap.gravity_potential;
    h0_ = h_ = snap.momentum;
    q_g_ = snap.gravity_moment;
    t_ = s.t;
    omega_ = s.omega;
    tau_ = torque;
    p_ext_ = power_external(s);
    p_damp_ = power_damping(s);
  }

  // Prescribed rotation: integral tau Omega = integral Omega dH - integral Q_g Omega (tau = dH/dt - Q_g),
  // with H needed at every step only when Omega varies. Free rotor: trapezoid of tau(t) Omega.
  void advance(const detail::StepState& s, double torque) {
    const double dt = s.t - t_;
    if (prescribed_) {
      const double q_g = o_.gravity.isZero() ? 0.0 : d_.gravity_moment(s.theta, s.q);
      moment_work_ += 0.5 * dt * (q_g_ * omega_ + q_g * s.omega);
      q_g_ = q_g;
      if (!constant_speed_) {
        const double h = d_.momentum(s.omega, s.q, s.v);
        omega_dh_ += 0.5 * (omega_ + s.omega) * (h - h_);
        h_ = h;
      }
    } else {
      driving += 0.5 * dt * (tau_ * omega_ + torque * s.omega);
    }
    const double p_ext = power_external(s), p_damp = power_damping(s);
    external += 0.5 * dt * (p_ext_ + p_ext);
    damping += 0.5 * dt * (p_damp_ + p_damp);
    p_ext_ = p_ext;
    p_damp_ = p_damp;
    t_ = s.t;
    omega_ = s.omega;
    tau_ = torque;
  }

  // Completes the works at a snapshot of the current state (constant speed: Omega (H - H0), exact).
  void sync(const detail::Snapshot& snap) {
    gravity = v0_ - snap.gravity_potential;
    if (!prescribed_) return;
    if (constant_speed_) omega_dh_ = omega_ * (snap.momentum - h0_);
    driving = omega_dh_ - moment_work_;
  }

  // SolverError when the state is not finite, the deflection exceeds the bound, or T + U grew
  // beyond the energy supplied.
  void check(const detail::StepState& s, const detail::Snapshot& snap) {
    const double e = snap.kinetic + snap.strain;
    scale_ = std::max(scale_, std::abs(snap.kinetic) + std::abs(snap.strain) + std::abs(driving) + std::abs(gravity) +
                                  std::abs(external) + damping + std::abs(e0_));
    if (!s.q.allFinite() || !s.v.allFinite() || !std::isfinite(e) || !std::isfinite(s.omega))
      fail(s, "the state is not finite");
    const double bound = o_.max_deflection_ratio * d_.body().size;
    if (snap.rms_deflection > bound)
      fail(s, fmt::format("the RMS elastic displacement {:.4g} m exceeds {} x the body size ({:.4g} m), the range of "
                          "the small-deformation FFRF model",
                          snap.rms_deflection, o_.max_deflection_ratio, d_.body().size));
    const double excess = e - (e0_ + driving + gravity + external - damping);
    if (excess > 0.1 * scale_)
      fail(s, fmt::format("T + U exceeds the energy supplied by {:.4g} J (energy scale {:.4g} J): numerical "
                          "instability, reduce the time step",
                          excess, scale_));
  }

  double driving = 0.0, gravity = 0.0, external = 0.0, damping = 0.0;

 private:
  double power_external(const detail::StepState& s) const { return d_.loaded() ? d_.external_load(s.t).dot(s.v) : 0.0; }
  double power_damping(const detail::StepState& s) const { return d_.damped() ? d_.damping().form(s.v, s.v) : 0.0; }

  [[noreturn]] void fail(const detail::StepState& s, const std::string& why) const {
    std::string hint;
    if (!o_.stiffening)
      hint =
          " Geometric stiffening is off: above the lowest natural frequency of the motions in the plane of "
          "rotation the spin-softened model has no stable equilibrium, the divergence of the linear FFRF model "
          "described by Kane, Ryan & Banerjee (1987).";
    throw DivergenceError(
        fmt::format("FFRF run diverged at t = {:.6g} s (Omega = {:.6g} rad/s): {}.{}", s.t, s.omega, why, hint), s.t,
        s.omega);
  }

  const detail::Dynamics& d_;
  const FfrfOptions& o_;
  double scale_ = 0.0;
  bool prescribed_ = true, constant_speed_ = false;
  double e0_ = 0.0, v0_ = 0.0, h0_ = 0.0, h_ = 0.0, q_g_ = 0.0, t_ = 0.0, omega_ = 0.0, tau_ = 0.0;
  double moment_work_ = 0.0, omega_dh_ = 0.0, p_ext_ = 0.0, p_damp_ = 0.0;
};

Eigen::VectorXd initial_coordinates(const detail::Dynamics& d, const RotationProfile& rotation, const FfrfOptions& o) {
  const int n = d.body().n();
  if (!o.start_from_steady_state) return Eigen::VectorXd::Zero(n);
  const double theta = rotation.prescribed() ? rotation.angle(0.0) : rotation.initial_angle();
  const double omega = rotation.prescribed() ? rotation.speed(0.0) : rotation.initial_speed();
  const double alpha = rotation.prescribed() ? rotation.acceleration(0.0) : 0.0;
  CoordinateSolver solver;
  if (!solver.factorize(d.static_operator(omega, alpha)))
    throw SolverError(
        fmt::format("FFRF integrator: no steady state at Omega = {:.6g} rad/s (static operator "
                    "singular: {})",
                    omega, solver.message()));
  Eigen::VectorXd load = d.static_load(theta, omega, alpha);
  if (d.loaded()) load += d.external_load(0.0);
  return solver.solve(load);
}

// 1/2 (J0 + J_rotor) Omega_max^2 + m |g| size; a free rotor's Omega_max is bounded by
// |Omega0| + integral |tau| dt / J, sampled at the steps.
double energy_scale(const detail::Dynamics& d, const RotationProfile& rotation, const FfrfOptions& o, int steps) {
  const auto& mp = d.body().mass_properties;
  const double j = mp.axis_inertia + o.rotor_inertia;
  double w_max = 0.0;
  if (rotation.prescribed()) {
    w_max = rotation.max_speed(o.end_time);
  } else {
    double impulse = 0.0;
    for (int n = 0; n < steps; ++n) impulse += std::abs(rotation.torque(n * o.time_step)) * o.time_step;
    w_max = std::abs(rotation.initial_speed()) + impulse / j;
  }
  return 0.5 * j * w_max * w_max + mp.mass * o.gravity.norm() * d.body().size;
}

void record(FfrfHistory& h, const Eigen::MatrixXd& rows, const detail::StepState& s, double alpha,
            const detail::Snapshot& snap, const Ledger& ledger, double torque) {
  h.time.push_back(s.t);
  if (h.displacement.cols() > 0)  // a row of a matrix without columns is offset from a null pointer
    h.displacement.row(static_cast<Eigen::Index>(h.time.size()) - 1) = (rows * s.q).transpose();
  h.angle.push_back(s.theta);
  h.speed.push_back(s.omega);
  h.acceleration.push_back(alpha);
  h.kinetic_energy.push_back(snap.kinetic);
  h.strain_energy.push_back(snap.strain);
  h.driving_work.push_back(ledger.driving);
  h.gravity_work.push_back(ledger.gravity);
  h.external_work.push_back(ledger.external);
  h.damping_work.push_back(ledger.damping);
  h.angular_momentum.push_back(snap.momentum);
  h.driving_torque.push_back(torque);
}

// Torque and true rotor acceleration of the held state: prescribed (needed torque, alpha(t)) or free
// (applied torque, alpha from the coupled mass matrix).
std::pair<double, double> torque_and_alpha(const detail::PrescribedStepper& stepper, const detail::StepState& s,
                                           const RotationProfile&) {
  return {stepper.driving_torque(s), s.alpha};
}
std::pair<double, double> torque_and_alpha(const detail::FreeRotorStepper& stepper, const detail::StepState& s,
                                           const RotationProfile& rotation) {
  return {rotation.torque(s.t), stepper.true_accelerations(s).first};
}

template <typename Stepper>
FfrfHistory run(Stepper& stepper, const detail::Dynamics& d, const RotationProfile& rotation, const FfrfOptions& o,
                int steps) {
  const ProjectedBody& p = d.body();
  const Eigen::MatrixXd rows = recovery_rows(*p.body, *p.basis, o.output_dofs);
  FfrfHistory h;
  const int samples = steps / o.output_stride + 1 + (steps % o.output_stride != 0 ? 1 : 0);
  h.displacement.resize(samples, static_cast<Eigen::Index>(o.output_dofs.size()));
  detail::StepState s = stepper.start(initial_coordinates(d, rotation, o), Eigen::VectorXd::Zero(p.n()));
  Ledger ledger(d, o, energy_scale(d, rotation, o, steps), rotation.prescribed(),
                rotation.kind() == RotationProfile::Kind::constant_speed);
  detail::Snapshot snap = d.snapshot(s.theta, s.omega, s.q, s.v);
  double torque = 0.0, alpha = 0.0;
  std::tie(torque, alpha) = torque_and_alpha(stepper, s, rotation);
  ledger.start(s, snap, rotation.prescribed() ? 0.0 : torque);
  ledger.check(s, snap);
  record(h, rows, s, alpha, snap, ledger, torque);
  for (int n = 1; n <= steps; ++n) {
    stepper.step(s);
    ledger.advance(s, rotation.prescribed() ? 0.0 : rotation.torque(s.t));
    const bool output = n % o.output_stride == 0 || n == steps;
    if (!output && n % kCheckInterval != 0) continue;
    snap = d.snapshot(s.theta, s.omega, s.q, s.v);
    ledger.sync(snap);
    ledger.check(s, snap);
    if (output) {
      std::tie(torque, alpha) = torque_and_alpha(stepper, s, rotation);
      record(h, rows, s, alpha, snap, ledger, torque);
    }
  }
  h.final_coordinates = s.q;
  h.final_velocity = s.v;
  h.steps = steps;
  h.factorizations = stepper.counters().factorizations;
  h.solve_iterations = stepper.counters().iterations;
  h.max_step_iterations = stepper.counters().max_iterations;
  h.max_residual = stepper.counters().max_residual;
  return h;
}

}  // namespace

GeneralizedAlpha chung_hulbert(double rho_infinity) {
  const double r = rho_infinity;
  const double am = (2.0 * r - 1.0) / (r + 1.0), af = r / (r + 1.0);
  const double gamma = 0.5 - am + af, beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);
  return {am, af, gamma, beta};
}

double FfrfHistory::energy_balance_error() const {
  double worst = 0.0;
  for (size_t i = 0; i < time.size(); ++i) {
    const double change = kinetic_energy[i] + strain_energy[i] - kinetic_energy[0] - strain_energy[0];
    const double supplied = driving_work[i] + gravity_work[i] + external_work[i] - damping_work[i];
    worst = std::max(worst, std::abs(change - supplied));
  }
  return worst;
}

FfrfHistory integrate(const ProjectedBody& body, const RotationProfile& rotation, const FfrfOptions& options) {
  validate(body, rotation, options);
  // An integer number of steps reaches end_time: the step is shortened if needed (never lengthened).
  const int steps = static_cast<int>(std::ceil(options.end_time / options.time_step - 1e-9));
  FfrfOptions o = options;
  o.time_step = options.end_time / steps;
  const detail::Dynamics dynamics(body, switches_of(o));
  if (rotation.prescribed()) {
    detail::PrescribedStepper stepper(dynamics, rotation, o);
    return run(stepper, dynamics, rotation, o, steps);
  }
  detail::FreeRotorStepper stepper(dynamics, rotation, o);
  return run(stepper, dynamics, rotation, o, steps);
}

}  // namespace bb::ffrf
