#include "timeint/newmark_shooting.hpp"

#include <limits>
#include <memory>
#include <stdexcept>

#include "common/constants.hpp"
#include "timeint/newmark.hpp"
#include "timeint/period_newton.hpp"
#include "timeint/steady_state.hpp"

namespace bb::timeint {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using friction::ContactState;

namespace {

// x = (q, v / omega, a / omega^2, w): every entry in metres, so one tolerance scales them all.
class NewmarkPeriod {
 public:
  NewmarkPeriod(const friction::FrictionModel& model, double omega, int steps, double alpha)
      : integrator_(model, {.time_step = kTwoPi / (omega * steps), .alpha = alpha}),
        excitation_(model_excitation(integrator_.model(), omega)),
        omega_(omega),
        steps_(steps),
        n_(model.mass.rows()),
        nc_(static_cast<Index>(model.contacts.size())) {
    const NewmarkOptions& o = integrator_.options();
    const double dt = o.time_step, b = integrator_.beta(), g = integrator_.gamma();
    const friction::FrictionModel& m = integrator_.model();
    inertia_ = m.mass / (b * dt * dt) + (1.0 + o.alpha) * g / (b * dt) * m.damping;
    keff_ = inertia_ + (1.0 + o.alpha) * m.stiffness;
  }

  Index size() const { return 3 * n_ + nc_; }
  Index dofs() const { return n_; }

  // The state x as a Newmark state at t = 0, its sliders settled onto their modes (contact_step).
  DynamicState unpack(const VectorXd& x) const {
    DynamicState s;
    s.displacement = x.head(n_);
    s.velocity = omega_ * x.segment(n_, n_);
    s.acceleration = omega_ * omega_ * x.segment(2 * n_, n_);
    s.load = integrator_.model().static_load + excitation_(0.0);
    for (Index k = 0; k < nc_; ++k) s.contacts.push_back(contact_step(contact(k), x[3 * n_ + k], s.displacement));
    return s;
  }

  VectorXd pack(const DynamicState& s) const { return newmark_packed(s, omega_); }

  // One period from x; `record` (when not null) gets every step's state.
  PeriodEval period(const VectorXd& x, bool jacobian, std::vector<DynamicState>* record = nullptr) const {
    PeriodEval out;
    DynamicState s = unpack(x);
    out.free_slider.resize(static_cast<size_t>(nc_));
    for (Index k = 0; k < nc_; ++k)  // stuck at the start; cleared below if it ever switches
      out.free_slider[static_cast<size_t>(k)] = s.contacts[static_cast<size_t>(k)].state == ContactState::stick;
    MatrixXd phi;
    if (jacobian) phi = settle_jacobian(s);
    if (record) record->push_back(s);
    for (int i = 0; i < steps_; ++i) {
      DynamicState next = s;
      const StepReport r = integrator_.step(next, excitation_);
      if (!r.converged) {
        out.failure = r.failure;
        return out;
      }
      if (jacobian) phi = step_jacobian(s, next, phi);
      for (Index k = 0; k < nc_; ++k)
        if (next.contacts[static_cast<size_t>(k)].state != s.contacts[static_cast<size_t>(k)].state) {
          ++out.transitions;
          out.free_slider[static_cast<size_t>(k)] = 0;
        }
      s = std::move(next);
      if (record) record->push_back(s);
    }
    out.end = pack(s);
    if (jacobian) {
      // d x_end / d x_start in the packed (scaled) variables.
      VectorXd d = VectorXd::Ones(size());
      d.segment(n_, n_).setConstant(omega_);
      d.segment(2 * n_, n_).setConstant(omega_ * omega_);
      out.monodromy = d.cwiseInverse().asDiagonal() * phi * d.asDiagonal();
    }
    return out;
  }

 private:
  const friction::ContactElement& contact(Index k) const {
    return integrator_.model().contacts[static_cast<size_t>(k)];
  }

  // d w_after / d q of a contact that is not stuck (its slider follows u), as a row over q.
  Eigen::RowVectorXd slider_row(Index k, ContactState state) const {
    const friction::ContactElement& c = contact(k);
    if (state == ContactState::lift_off) return c.tangential;
    const double ratio = c.point.mu * c.point.kn / c.point.kt;
    return c.tangential + (state == ContactState::slip_positive ? -ratio : ratio) * c.normal;
  }

  // The settling of unpack(): sliders of contacts that are not stuck tied to q.
  MatrixXd settle_jacobian(const DynamicState& s) const {
    MatrixXd j = MatrixXd::Identity(size(), size());
    for (Index k = 0; k < nc_; ++k) {
      const ContactState state = s.contacts[static_cast<size_t>(k)].state;
      if (state == ContactState::stick) continue;
      j.row(3 * n_ + k).setZero();
      j.block(3 * n_ + k, 0, 1, n_) = slider_row(k, state);
    }
    return j;
  }

  // phi_after = d(step)/d(state before) * phi, block by block (unscaled q, v, a, w).
  MatrixXd step_jacobian(const DynamicState& s0, const DynamicState& s1, const MatrixXd& phi) const {
    const NewmarkOptions& o = integrator_.options();
    const friction::FrictionModel& m = integrator_.model();
    const double dt = o.time_step, alpha = o.alpha, b = integrator_.beta(), g = integrator_.gamma();
    const auto q = phi.topRows(n_), v = phi.middleRows(n_, n_), a = phi.middleRows(2 * n_, n_);
    const auto w = phi.bottomRows(nc_);
    const MatrixXd qt = q + dt * v + dt * dt * (0.5 - b) * a;
    const MatrixXd vt = v + dt * (1.0 - g) * a;
    MatrixXd rhs = inertia_ * qt - (1.0 + alpha) * m.damping * vt;
    MatrixXd tangent = keff_;
    for (Index k = 0; k < nc_; ++k) {
      const friction::ContactElement& c = contact(k);
      const ContactSample& before = s0.contacts[static_cast<size_t>(k)];
      const ContactSample& after = s1.contacts[static_cast<size_t>(k)];
      if (alpha != 0.0 && before.state != ContactState::lift_off)  // alpha g(q0, w0): T0 = kt (u0 - w0)
        rhs += alpha * (c.tangential.transpose() * (c.point.kt * (c.tangential * q - w.row(k))) +
                        c.normal.transpose() * (c.point.kn * (c.normal * q)));
      const ContactTangent& d = after.tangent;
      tangent += (1.0 + alpha) * (c.tangential.transpose() * (d.dt_du * c.tangential + d.dt_dv * c.normal) +
                                  d.dn_dv * c.normal.transpose() * c.normal);
      if (after.state == ContactState::stick)  // T1 = kt (u1 - w0)
        rhs += (1.0 + alpha) * c.point.kt * c.tangential.transpose() * w.row(k);
    }
    if (alpha != 0.0) rhs += alpha * (m.damping * v + m.stiffness * q);
    MatrixXd out(phi.rows(), phi.cols());
    out.topRows(n_) = tangent.partialPivLu().solve(rhs);
    out.middleRows(2 * n_, n_) = (out.topRows(n_) - qt) / (b * dt * dt);
    out.middleRows(n_, n_) = vt + g * dt * out.middleRows(2 * n_, n_);
    for (Index k = 0; k < nc_; ++k) {
      const ContactState state = s1.contacts[static_cast<size_t>(k)].state;
      out.row(3 * n_ + k) = state == ContactState::stick ? MatrixXd(w.row(k)) : slider_row(k, state) * out.topRows(n_);
    }
    return out;
  }

  NewmarkIntegrator integrator_;
  Excitation excitation_;
  double omega_;
  int steps_;
  Index n_, nc_;
  MatrixXd inertia_, keff_;  // M / (beta dt^2) + (1 + alpha) gamma / (beta dt) C, and K_eff
};

void record(const NewmarkPeriod& map, const VectorXd& x, const ShootingOptions& o, ShootingResult& out) {
  std::vector<DynamicState> states;
  (void)map.period(x, false, &states);
  const auto nd = static_cast<Index>(o.dofs.size());
  const auto rows = static_cast<Index>(states.size());
  out.samples.resize(rows, nd);
  out.steady.contacts.assign(states.front().contacts.size(), {});
  for (Index k = 0; k < rows; ++k) {
    const DynamicState& s = states[static_cast<size_t>(k)];
    for (Index j = 0; j < nd; ++j) out.samples(k, j) = s.displacement[o.dofs[static_cast<size_t>(j)]];
    for (size_t c = 0; c < s.contacts.size(); ++c) out.steady.contacts[c].push_back(s.contacts[c]);
  }
  out.largest = out.samples.cwiseAbs().colwise().maxCoeff().transpose();
  fill_harmonics({out.samples.topRows(rows - 1)}, o.harmonics, out.steady);
}

}  // namespace

PeriodMap newmark_period_map(const friction::FrictionModel& model, double omega, int steps, double alpha) {
  friction::FrictionModel checked = model;
  friction::validate_model(checked, "shooting");
  auto map = std::make_shared<const NewmarkPeriod>(checked, omega, steps, alpha);
  return [map](const VectorXd& x, bool jacobian) { return map->period(x, jacobian); };
}

DynamicState newmark_state(const friction::FrictionModel& model, double omega, const VectorXd& x) {
  friction::FrictionModel checked = model;
  friction::validate_model(checked, "shooting");
  const NewmarkPeriod map(checked, omega, 2, 0.0);  // the step does not enter the unpacking
  if (x.size() != map.size()) throw std::invalid_argument("newmark_state: the state has the wrong size");
  return map.unpack(x);
}

VectorXd newmark_packed(const DynamicState& s, double omega) {
  const Index n = s.displacement.size(), nc = static_cast<Index>(s.contacts.size());
  VectorXd x(3 * n + nc);
  x << s.displacement, s.velocity / omega, s.acceleration / (omega * omega), VectorXd::Zero(nc);
  for (Index k = 0; k < nc; ++k) x[3 * n + k] = s.contacts[static_cast<size_t>(k)].slider;
  return x;
}

NewmarkShootingResult newmark_shooting(const friction::FrictionModel& input, double omega, const ShootingOptions& o,
                                       double alpha, const std::optional<VectorXd>& start) {
  friction::FrictionModel model = input;
  friction::validate_model(model, "shooting");
  validate_shooting(model, omega, o);
  const NewmarkPeriod map(model, omega, o.steps_per_period, alpha);
  NewmarkShootingResult result;
  ShootingResult& out = result.result;
  out.steady.omega = omega;
  out.largest_multiplier = std::numeric_limits<double>::quiet_NaN();
  int& periods = out.steady.cycles;
  const Index n = map.dofs();
  const PeriodLayout layout{.motion = 3 * n, .slider_offset = 3 * n};
  const PeriodMap period = [&](const VectorXd& from, bool jacobian) { return map.period(from, jacobian); };
  VectorXd x;
  if (start && start->size() == map.size()) {
    x = *start;
  } else {
    x = warm_start(model, period, map.size(), layout.slider_offset, o, periods, out.steady.failure);
    if (!out.steady.failure.empty()) return result;
  }
  const PeriodNewtonResult newton = newton_on_period(period, x, layout, o.tolerance, o.max_iterations, omega);
  if (!take_newton(newton, layout, o.floquet, out)) return result;
  result.state = newton.x;
  record(map, newton.x, o, out);
  ++periods;
  return result;
}

}  // namespace bb::timeint
