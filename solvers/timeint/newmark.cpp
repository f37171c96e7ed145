#include "timeint/newmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <utility>

#include "linalg/damped_newton.hpp"

namespace bb::timeint {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

friction::FrictionModel validated(friction::FrictionModel model) {
  friction::validate_model(model, "Newmark");
  return model;
}

double model_force_scale(const friction::FrictionModel& m) {
  double s = m.static_load.norm();
  for (const friction::ContactElement& c : m.contacts) s += (1.0 + c.point.mu) * c.point.n0;
  return s;
}

// Generalized contact force sum_k a_t^T T + a_n^T N and its Jacobian over the columns of the rows
// given (restricted to the contact DOFs), for the sliders `before` and displacements x.
struct ContactEval {
  std::vector<ContactSample> samples;
  VectorXd force;
  MatrixXd jacobian;
};

ContactEval evaluate_contacts(const std::vector<friction::ContactElement>& contacts, const std::vector<double>& before,
                              const VectorXd& x) {
  ContactEval e;
  const Index n = x.size();
  e.force = VectorXd::Zero(n);
  e.jacobian = MatrixXd::Zero(n, n);
  e.samples.reserve(contacts.size());
  for (size_t k = 0; k < contacts.size(); ++k) {
    const friction::ContactElement& c = contacts[k];
    const ContactSample s = contact_step(c, before[k], x);
    e.force += c.tangential.transpose() * s.tangential + c.normal.transpose() * s.normal;
    const ContactTangent& d = s.tangent;
    e.jacobian += c.tangential.transpose() * (d.dt_du * c.tangential + d.dt_dv * c.normal) +
                  d.dn_dv * c.normal.transpose() * c.normal;
    e.samples.push_back(s);
  }
  return e;
}

std::vector<double> sliders_of(const std::vector<ContactSample>& samples) {
  std::vector<double> w;
  w.reserve(samples.size());
  for (const ContactSample& s : samples) w.push_back(s.slider);
  return w;
}

}  // namespace

Excitation harmonic_excitation(const Eigen::VectorXcd& amplitude, double omega_rad_s) {
  return [amplitude, omega_rad_s](double t) -> VectorXd {
    return (amplitude * std::exp(std::complex<double>(0.0, omega_rad_s * t))).real();
  };
}

Excitation model_excitation(const friction::FrictionModel& model, double omega_rad_s) {
  if (model.higher_loads.empty()) return harmonic_excitation(model.harmonic_load, omega_rad_s);
  std::vector<Eigen::VectorXcd> loads{model.harmonic_load};
  for (const Eigen::VectorXcd& f : model.higher_loads) loads.push_back(f);
  return [loads, omega_rad_s](double t) -> VectorXd {
    VectorXd f = VectorXd::Zero(loads.front().size());
    for (size_t k = 0; k < loads.size(); ++k)
      if (loads[k].size() > 0)
        f += (loads[k] * std::exp(std::complex<double>(0.0, static_cast<double>(k + 1) * omega_rad_s * t))).real();
    return f;
  };
}

Excitation no_excitation(Index dofs) {
  return [dofs](double) -> VectorXd { return VectorXd::Zero(dofs); };
}

NewmarkIntegrator::NewmarkIntegrator(friction::FrictionModel model, NewmarkOptions options)
    : model_(validated(std::move(model))), options_(options), system_(model_) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("Newmark: " + what); };
  const double dt = options_.time_step, alpha = options_.alpha;
  if (!(std::isfinite(dt) && dt > 0.0)) fail(fmt::format("time step must be finite and > 0 (got {})", dt));
  if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0)) fail(fmt::format("HHT alpha must lie in [-1/3, 0] (got {})", alpha));
  if (options_.max_iterations < 1 || options_.max_backtracks < 0 || !(options_.tolerance > 0.0))
    fail("max_iterations >= 1, max_backtracks >= 0 and tolerance > 0");
  beta_ = 0.25 * (1.0 - alpha) * (1.0 - alpha);
  gamma_ = 0.5 - alpha;

  mass_lu_.compute(model_.mass);
  if (!(std::abs(mass_lu_.determinant()) > 0.0) || !std::isfinite(mass_lu_.rcond()) || mass_lu_.rcond() < 1e-14)
    fail("M must be invertible (every DOF needs mass for the initial acceleration)");

  const MatrixXd keff =
      model_.mass / (beta_ * dt * dt) + (1.0 + alpha) * (gamma_ / (beta_ * dt) * model_.damping + model_.stiffness);
  keff_.emplace(system_.condense(keff));
  if (!(keff_->rcond() > 1e-14)) fail("effective stiffness of the non-contact DOFs is singular");
  force_scale_ = model_force_scale(model_);
}

VectorXd NewmarkIntegrator::contact_force(const std::vector<ContactSample>& samples) const {
  VectorXd g = VectorXd::Zero(model_.mass.rows());
  for (size_t k = 0; k < samples.size(); ++k)
    g += model_.contacts[k].tangential.transpose() * samples[k].tangential +
         model_.contacts[k].normal.transpose() * samples[k].normal;
  return g;
}

DynamicState NewmarkIntegrator::initial_state(const VectorXd& q0, const VectorXd& v0, double t0,
                                              const Excitation& excitation, const std::vector<double>& sliders) const {
  const Index n = model_.mass.rows();
  if (q0.size() != n || v0.size() != n || !q0.allFinite() || !v0.allFinite() || !std::isfinite(t0))
    throw std::invalid_argument(fmt::format("Newmark initial state: q0 and v0 need {} finite entries", n));
  if (!sliders.empty() && sliders.size() != model_.contacts.size())
    throw std::invalid_argument("Newmark initial state: one slider position per contact (or none)");
  DynamicState s;
  s.time = t0;
  s.displacement = q0;
  s.velocity = v0;
  s.load = model_.static_load + excitation(t0);
  for (size_t k = 0; k < model_.contacts.size(); ++k) {
    const friction::ContactElement& c = model_.contacts[k];
    const double w = sliders.empty() ? c.tangential.dot(q0) - c.tangential_offset : sliders[k];
    s.contacts.push_back(contact_step(c, w, q0));
  }
  s.acceleration = mass_lu_.solve(s.load - model_.damping * v0 - model_.stiffness * q0 - contact_force(s.contacts));
  return s;
}

StepReport NewmarkIntegrator::step(DynamicState& state, const Excitation& excitation) const {
  const double dt = options_.time_step, alpha = options_.alpha;
  const double t1 = state.time + dt;
  const VectorXd& q0 = state.displacement;
  const VectorXd& v0 = state.velocity;
  const VectorXd qt = q0 + dt * v0 + dt * dt * (0.5 - beta_) * state.acceleration;
  const VectorXd vt = v0 + dt * (1.0 - gamma_) * state.acceleration;
  const VectorXd f1 = model_.static_load + excitation(t1);
  VectorXd b = (1.0 + alpha) * f1 + model_.mass * qt / (beta_ * dt * dt) +
               (1.0 + alpha) * model_.damping * (gamma_ / (beta_ * dt) * qt - vt);
  if (alpha != 0.0)
    b += -alpha * state.load + alpha * (model_.damping * v0 + model_.stiffness * q0 + contact_force(state.contacts));

  StepReport report;
  VectorXd q(q0.size());
  const friction::Condensation<double>::Load load = keff_->condense(b);
  const std::vector<Index>& c = system_.contact_dofs();
  const std::vector<Index>& o = system_.other_dofs();
  if (c.empty()) {
    q(o) = load.other;
    report.converged = true;
  } else {
    const double tolerance = options_.tolerance * (force_scale_ + load.contact.norm());
    const std::vector<double> before = sliders_of(state.contacts);
    // S x + (1 + alpha) g(x) = b_c on the contact DOFs, with its consistent tangent.
    const auto balance = [&](const VectorXd& x) {
      ContactEval e = evaluate_contacts(system_.contacts_on_c(), before, x);
      NewtonPoint p;
      p.residual = keff_->reduced() * x + (1.0 + alpha) * e.force - load.contact;
      p.jacobian = keff_->reduced() + (1.0 + alpha) * e.jacobian;
      return p;
    };
    const DampedNewtonResult r = damped_newton(balance, VectorXd(qt(c)),
                                               {.tolerance = tolerance,
                                                .max_iterations = options_.max_iterations,
                                                .max_backtracks = options_.max_backtracks,
                                                .step_solve = NewtonStepSolve::partial_pivot_lu});
    // The iteration that failed (line search, non-finite step) is counted.
    report.iterations = r.iterations + (r.converged || r.status == NewtonStatus::iteration_limit ? 0 : 1);
    report.residual = r.residual;
    report.converged = r.converged;
    if (!report.converged) {
      report.failure = fmt::format(
          "Newmark step to t = {:.9g} s did not converge: |R| = {:.3e} N after {} Newton "
          "iterations (tolerance {:.3e} N)",
          t1, r.residual, report.iterations, tolerance);
      return report;
    }
    q(c) = r.x;
    if (!o.empty()) q(o) = keff_->recover(load, r.x);
  }
  if (!q.allFinite()) {
    report.converged = false;
    report.failure = fmt::format("Newmark step to t = {:.9g} s produced a non-finite displacement", t1);
    return report;
  }

  const VectorXd a1 = (q - qt) / (beta_ * dt * dt);
  const VectorXd v1 = vt + gamma_ * dt * a1;
  std::vector<ContactSample> samples;
  samples.reserve(model_.contacts.size());
  for (size_t k = 0; k < model_.contacts.size(); ++k)
    samples.push_back(contact_step(model_.contacts[k], state.contacts[k].slider, q));

  const VectorXd dq = q - q0;
  WorkLedger& w = state.work;
  w.excitation += 0.5 * dq.dot(state.load + f1);
  w.viscous += 0.5 * dq.dot(model_.damping * (v0 + v1));
  for (size_t k = 0; k < samples.size(); ++k) {
    const ContactSample &s0 = state.contacts[k], &s1 = samples[k];
    w.friction += 0.5 * (s1.u - s0.u) * (s0.tangential + s1.tangential);
    w.normal += 0.5 * (s1.v - s0.v) * (s0.normal + s1.normal);
  }
  state.time = t1;
  state.displacement = q;
  state.velocity = v1;
  state.acceleration = a1;
  state.load = f1;
  state.contacts = std::move(samples);
  return report;
}

double NewmarkIntegrator::mechanical_energy(const DynamicState& s) const {
  return 0.5 * s.velocity.dot(model_.mass * s.velocity) + 0.5 * s.displacement.dot(model_.stiffness * s.displacement);
}

TimeHistory integrate(const NewmarkIntegrator& integrator, const DynamicState& start, const Excitation& excitation,
                      int steps, const RecordOptions& record) {
  if (steps < 0) throw std::invalid_argument("Newmark run: the number of steps must be >= 0");
  const Index n = integrator.model().mass.rows();
  for (const Index i : record.dofs)
    if (i < 0 || i >= n)
      throw std::invalid_argument(fmt::format("Newmark run: recorded DOF {} is not in [0, {})", i, n));
  TimeHistory h;
  h.final_state = start;
  const auto keep = [&](const DynamicState& s, Index row) {
    h.time.push_back(s.time);
    for (size_t j = 0; j < record.dofs.size(); ++j)
      h.displacement(row, static_cast<Index>(j)) = s.displacement[record.dofs[j]];
    if (record.contacts)
      for (size_t k = 0; k < s.contacts.size(); ++k) h.contacts[k].push_back(s.contacts[k]);
  };
  h.displacement.resize(steps + 1, static_cast<Index>(record.dofs.size()));
  if (record.contacts) h.contacts.assign(start.contacts.size(), {});
  h.iterations.reserve(static_cast<size_t>(steps));
  keep(start, 0);
  h.converged = true;
  for (int i = 0; i < steps; ++i) {
    const StepReport r = integrator.step(h.final_state, excitation);
    if (!r.converged) {
      h.converged = false;
      h.failure = r.failure;
      break;
    }
    h.iterations.push_back(r.iterations);
    h.total_iterations += r.iterations;
    h.max_iterations = std::max(h.max_iterations, r.iterations);
    ++h.steps;
    keep(h.final_state, h.steps);
  }
  h.displacement.conservativeResize(h.steps + 1, Eigen::NoChange);
  return h;
}

}  // namespace bb::timeint
