#include "time/newmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "common/errors.hpp"

namespace bb::timeint {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd select(const MatrixXd& a, const std::vector<Index>& rows, const std::vector<Index>& cols) {
  MatrixXd out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) out(static_cast<Index>(i), static_cast<Index>(j)) = a(rows[i], cols[j]);
  return out;
}

VectorXd select(const VectorXd& v, const std::vector<Index>& rows) {
  VectorXd out(static_cast<Index>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i) out[static_cast<Index>(i)] = v[rows[i]];
  return out;
}

double model_force_scale(const hbm::HbmModel& m) {
  double s = m.static_load.norm();
  for (const hbm::ContactElement& c : m.contacts) s += (1.0 + c.law.mu) * c.law.n0;
  return s;
}

// Generalized contact force sum_k a_t^T T + a_n^T N and its Jacobian over the columns of the rows
// given (restricted or full), for the sliders `before` and displacements x.
struct ContactEval {
  std::vector<ContactSample> samples;
  VectorXd force;
  MatrixXd jacobian;
};

ContactEval evaluate_contacts(const std::vector<hbm::ContactElement>& contacts, const std::vector<double>& before,
                              const VectorXd& x, bool with_jacobian) {
  ContactEval e;
  const Index n = x.size();
  e.force = VectorXd::Zero(n);
  if (with_jacobian) e.jacobian = MatrixXd::Zero(n, n);
  e.samples.reserve(contacts.size());
  for (size_t k = 0; k < contacts.size(); ++k) {
    const hbm::ContactElement& c = contacts[k];
    const ContactSample s = contact_step(c, before[k], x);
    e.force += c.tangential.transpose() * s.tangential + c.normal.transpose() * s.normal;
    if (with_jacobian) {
      const ContactTangent d = contact_tangent(c, s);
      e.jacobian += c.tangential.transpose() * (d.dt_du * c.tangential + d.dt_dv * c.normal) +
                    d.dn_dv * c.normal.transpose() * c.normal;
    }
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

Excitation no_excitation(Index dofs) {
  return [dofs](double) -> VectorXd { return VectorXd::Zero(dofs); };
}

NewmarkIntegrator::NewmarkIntegrator(hbm::HbmModel model, NewmarkOptions options)
    : model_(std::move(model)), options_(options) {
  hbm::validate_model(model_, "Newmark");
  const auto fail = [](const std::string& what) { throw std::invalid_argument("Newmark: " + what); };
  const double dt = options_.time_step, alpha = options_.alpha;
  if (!(std::isfinite(dt) && dt > 0.0)) fail(fmt::format("time step must be finite and > 0 (got {})", dt));
  if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0)) fail(fmt::format("HHT alpha must lie in [-1/3, 0] (got {})", alpha));
  if (options_.max_iterations < 1 || options_.max_backtracks < 0 || !(options_.tolerance > 0.0))
    fail("max_iterations >= 1, max_backtracks >= 0 and tolerance > 0");
  beta_ = 0.25 * (1.0 - alpha) * (1.0 - alpha);
  gamma_ = 0.5 - alpha;

  const Index n = model_.mass.rows();
  mass_lu_.compute(model_.mass);
  if (!(std::abs(mass_lu_.determinant()) > 0.0) || !std::isfinite(mass_lu_.rcond()) || mass_lu_.rcond() < 1e-14)
    fail("M must be invertible (every DOF needs mass for the initial acceleration)");

  std::vector<bool> touched(static_cast<size_t>(n), false);
  for (const hbm::ContactElement& e : model_.contacts)
    for (Index i = 0; i < n; ++i)
      if (e.tangential[i] != 0.0 || e.normal[i] != 0.0) touched[static_cast<size_t>(i)] = true;
  for (Index i = 0; i < n; ++i) (touched[static_cast<size_t>(i)] ? contact_dofs_ : other_dofs_).push_back(i);

  keff_ = model_.mass / (beta_ * dt * dt) + (1.0 + alpha) * (gamma_ / (beta_ * dt) * model_.damping + model_.stiffness);
  if (!other_dofs_.empty()) {
    keff_oo_lu_.compute(select(keff_, other_dofs_, other_dofs_));
    if (!(keff_oo_lu_.rcond() > 1e-14)) fail("effective stiffness of the non-contact DOFs is singular");
  }
  if (!contact_dofs_.empty()) {
    const MatrixXd kcc = select(keff_, contact_dofs_, contact_dofs_);
    keff_co_ = select(keff_, contact_dofs_, other_dofs_);
    if (!other_dofs_.empty()) {
      koo_inv_koc_ = keff_oo_lu_.solve(select(keff_, other_dofs_, contact_dofs_));
      schur_ = kcc - keff_co_ * koo_inv_koc_;
    } else {
      schur_ = kcc;
    }
    contacts_c_ = model_.contacts;
    for (hbm::ContactElement& r : contacts_c_) {
      r.tangential = select(VectorXd(r.tangential.transpose()), contact_dofs_).transpose();
      r.normal = select(VectorXd(r.normal.transpose()), contact_dofs_).transpose();
    }
  }
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
    const hbm::ContactElement& c = model_.contacts[k];
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
  const VectorXd y_o = other_dofs_.empty() ? VectorXd() : VectorXd(keff_oo_lu_.solve(select(b, other_dofs_)));
  if (contact_dofs_.empty()) {
    for (size_t i = 0; i < other_dofs_.size(); ++i) q[other_dofs_[i]] = y_o[static_cast<Index>(i)];
    report.converged = true;
  } else {
    const VectorXd b_c = other_dofs_.empty() ? select(b, contact_dofs_) : VectorXd(select(b, contact_dofs_) - keff_co_ * y_o);
    const double tolerance = options_.tolerance * (force_scale_ + b_c.norm());
    const std::vector<double> before = sliders_of(state.contacts);
    const auto residual = [&](const VectorXd& x, bool jac) {
      ContactEval e = evaluate_contacts(contacts_c_, before, x, jac);
      e.force = schur_ * x + (1.0 + alpha) * e.force - b_c;
      if (jac) e.jacobian = schur_ + (1.0 + alpha) * e.jacobian;
      return e;
    };
    VectorXd x = select(qt, contact_dofs_);
    ContactEval e = residual(x, true);
    double r = e.force.norm();
    while (!(r <= tolerance) && report.iterations < options_.max_iterations) {
      ++report.iterations;
      const VectorXd dx = e.jacobian.partialPivLu().solve(-e.force);
      double lambda = 1.0;
      bool accepted = false;
      for (int k = 0; k <= options_.max_backtracks; ++k, lambda *= 0.5) {
        const VectorXd trial = x + lambda * dx;
        ContactEval et = residual(trial, true);
        const double rt = et.force.norm();
        if (std::isfinite(rt) && rt <= (1.0 - 1e-4 * lambda) * r) {
          x = trial;
          e = std::move(et);
          r = rt;
          accepted = true;
          break;
        }
      }
      if (!accepted) break;
    }
    report.residual = r;
    report.converged = r <= tolerance;
    if (!report.converged) {
      report.failure = fmt::format("Newmark step to t = {:.9g} s did not converge: |R| = {:.3e} N after {} Newton "
                                   "iterations (tolerance {:.3e} N)",
                                   t1, r, report.iterations, tolerance);
      return report;
    }
    for (size_t i = 0; i < contact_dofs_.size(); ++i) q[contact_dofs_[i]] = x[static_cast<Index>(i)];
    if (!other_dofs_.empty()) {
      const VectorXd xo = y_o - koo_inv_koc_ * x;
      for (size_t i = 0; i < other_dofs_.size(); ++i) q[other_dofs_[i]] = xo[static_cast<Index>(i)];
    }
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
    if (i < 0 || i >= n) throw std::invalid_argument(fmt::format("Newmark run: recorded DOF {} is not in [0, {})", i, n));
  TimeHistory h;
  h.final_state = start;
  const auto keep = [&](const DynamicState& s, Index row) {
    h.time.push_back(s.time);
    for (size_t j = 0; j < record.dofs.size(); ++j) h.displacement(row, static_cast<Index>(j)) = s.displacement[record.dofs[j]];
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

StaticState static_initial_state(const hbm::HbmModel& input, const StaticOptions& options) {
  hbm::HbmModel m = input;
  hbm::validate_model(m, "static initial state");
  if (options.max_iterations < 1 || options.max_backtracks < 0 || !(options.tolerance > 0.0))
    throw std::invalid_argument("static initial state: max_iterations >= 1, max_backtracks >= 0 and tolerance > 0");
  const Index n = m.mass.rows();
  const bool stuck = options.friction == StaticFriction::stuck_at_offset;
  const double tolerance = options.tolerance * (model_force_scale(m) + 1.0);

  const auto evaluate = [&](const VectorXd& q, VectorXd& r, MatrixXd& j) {
    r = m.stiffness * q - m.static_load;
    j = m.stiffness;
    for (const hbm::ContactElement& c : m.contacts) {
      const double v = c.normal.dot(q);
      const double normal = std::max(c.law.n0 + c.law.kn * v, 0.0);
      r += c.normal.transpose() * normal;
      // Semismooth choice at N0 + kn v == 0: closed, so a contact that just touches is stiff.
      if (c.law.n0 + c.law.kn * v >= 0.0) j += c.law.kn * c.normal.transpose() * c.normal;
      if (stuck) {
        r += c.tangential.transpose() * (c.law.kt * (c.tangential.dot(q) - c.tangential_offset));
        j += c.law.kt * c.tangential.transpose() * c.tangential;
      }
    }
  };

  StaticState s;
  VectorXd q = VectorXd::Zero(n), r;
  MatrixXd j;
  evaluate(q, r, j);
  double norm = r.norm();
  while (!(norm <= tolerance) && s.iterations < options.max_iterations) {
    ++s.iterations;
    const Eigen::FullPivLU<MatrixXd> lu(j);
    if (!lu.isInvertible()) {
      s.failure = fmt::format(
          "static initial state: singular tangent at iteration {} (|R| = {:.3e} N): the model is not held in some "
          "direction{}",
          s.iterations, norm, stuck ? "" : " with friction neglected; try StaticFriction::stuck_at_offset");
      break;
    }
    const VectorXd dq = lu.solve(-r);
    double lambda = 1.0;
    bool accepted = false;
    for (int k = 0; k <= options.max_backtracks; ++k, lambda *= 0.5) {
      const VectorXd trial = q + lambda * dq;
      VectorXd rt;
      MatrixXd jt;
      evaluate(trial, rt, jt);
      if (std::isfinite(rt.norm()) && rt.norm() <= (1.0 - 1e-4 * lambda) * norm) {
        q = trial;
        r = rt;
        j = jt;
        norm = rt.norm();
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
  }
  s.residual = norm;
  s.converged = norm <= tolerance;
  if (!s.converged) {
    if (s.failure.empty())
      s.failure = fmt::format("static initial state did not converge: |R| = {:.3e} N after {} iterations (tolerance "
                              "{:.3e} N)",
                              norm, s.iterations, tolerance);
    s.q = VectorXd::Zero(n);
  } else {
    s.q = q;
  }
  for (const hbm::ContactElement& c : m.contacts) {
    const double w = stuck ? 0.0 : c.tangential.dot(s.q) - c.tangential_offset;
    s.sliders.push_back(w);
    s.contacts.push_back(contact_step(c, w, s.q));
  }
  return s;
}

}  // namespace bb::timeint
