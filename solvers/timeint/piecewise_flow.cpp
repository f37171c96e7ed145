#include "timeint/piecewise_flow.hpp"

#include <fmt/format.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <stdexcept>

#include "common/errors.hpp"
#include "timeint/flow_trace.hpp"

namespace bb::timeint {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::RowVectorXd;
using Eigen::VectorXd;
using friction::ContactState;

namespace {

double sign_of(ContactState m) { return m == ContactState::slip_negative ? -1.0 : 1.0; }
bool slipping(ContactState m) { return m == ContactState::slip_positive || m == ContactState::slip_negative; }

// exp(a tau), its rows of the states (1, cos, sin) from `one` on held to the rotation they are:
// scaling and squaring loses them, and the motion with them, where a load or a stiffness dwarfs the
// rest of the generator (a load of 1e30 N gave an exponential of zeros, a "converged" motion of 0).
MatrixXd exponential(const MatrixXd& a, double tau, Index one, double omega) {
  MatrixXd e = (a * tau).exp();
  const double c = std::cos(tau), s = std::sin(tau);
  const double off =
      std::max({std::abs(e(one, one) - 1.0), std::abs(e(one + 1, one + 1) - c), std::abs(e(one + 1, one + 2) + s),
                std::abs(e(one + 2, one + 1) - s), std::abs(e(one + 2, one + 2) - c)});
  if (!(off <= 1e-9))
    throw SolverError(fmt::format(
        "shooting at omega = {:.6g} rad/s: the exact flow's exponential over {:.3g} rad is off by {:.3g} in its "
        "harmonic rows (a load or a stiffness too large beside the rest of the model to resolve in double "
        "precision); lower the force levels or the stiffness",
        omega, tau, off));
  return e;
}

}  // namespace

PiecewiseFlow::PiecewiseFlow(const friction::FrictionModel& model, double omega_rad_s, double step, bool rigid_stick)
    : model_(model),
      omega_(omega_rad_s),
      step_(step),
      rigid_(rigid_stick),
      n_(model.mass.rows()),
      nc_(static_cast<Index>(model.contacts.size())),
      size_(2 * n_ + nc_ + 3) {
  if (!(omega_ > 0.0 && std::isfinite(omega_))) throw std::invalid_argument("exact flow: omega must be finite and > 0");
  for (const Eigen::VectorXcd& f : model_.higher_loads)  // the flow carries one harmonic oscillator: harmonic 1
    if (f.size() > 0 && !f.isZero(0.0))
      throw std::invalid_argument(
          "exact flow: the excitation has harmonics above the first (a base motion's): use period_map = \"newmark\"");
  for (const friction::ContactElement& c : model.contacts)
    if (!c.law->piecewise_linear())
      throw std::invalid_argument(fmt::format(
          "exact flow: the {} law has no piecewise-linear form; shoot on the Newmark step (period_map = \"newmark\")",
          c.law->name()));
  const Eigen::FullPivLU<MatrixXd> lu(model.mass);
  if (!lu.isInvertible()) throw std::invalid_argument("exact flow: the mass matrix is singular");
  mass_inverse_ = lu.inverse();
}

const PiecewiseFlow::Generator& PiecewiseFlow::mode_data(const std::vector<ContactState>& modes) const {
  const auto found = generators_.find(modes);
  if (found != generators_.end()) return found->second;
  MatrixXd stiffness = model_.stiffness, slider_force = MatrixXd::Zero(n_, nc_);
  VectorXd constant = model_.static_load;  // f_static minus the contacts' constant forces
  for (Index k = 0; k < nc_; ++k) {
    const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
    const friction::PointParameters& law = c.point;
    const VectorXd at = c.tangential.transpose(), an = c.normal.transpose();
    const ContactState m = modes[static_cast<size_t>(k)];
    if (m == ContactState::lift_off) continue;
    stiffness += law.kn * an * an.transpose();
    constant -= law.n0 * an;
    if (rigid(m)) continue;  // held by the constraint below
    if (m == ContactState::stick) {
      stiffness += law.kt * at * at.transpose();
      constant += law.kt * c.tangential_offset * at;
      slider_force.col(k) = -law.kt * at;
    } else {
      const double s = sign_of(m);
      stiffness += s * law.mu * law.kn * at * an.transpose();
      constant -= s * law.mu * law.n0 * at;
    }
  }
  const double w2 = omega_ * omega_;
  const Index p = n_, w = 2 * n_, one = 2 * n_ + nc_;
  MatrixXd a = MatrixXd::Zero(size_, size_);
  a.block(0, p, n_, n_).setIdentity();
  a.block(p, 0, n_, n_) = -mass_inverse_ * stiffness / w2;
  a.block(p, p, n_, n_) = -mass_inverse_ * model_.damping / omega_;
  a.block(p, w, n_, nc_) = -mass_inverse_ * slider_force / w2;
  a.block(p, one, n_, 1) = mass_inverse_ * constant / w2;
  a.block(p, one + 1, n_, 1) = mass_inverse_ * model_.harmonic_load.real() / w2;
  a.block(p, one + 2, n_, 1) = -mass_inverse_ * model_.harmonic_load.imag() / w2;
  a(one + 1, one + 2) = -1.0;  // (cos theta)' = -sin theta
  a(one + 2, one + 1) = 1.0;
  Generator g;
  rigid_constraints(modes, a, g.stuck_force);
  g.a = std::move(a);
  g.events = events(modes, g.stuck_force);
  const Eigen::EigenSolver<MatrixXd> solver(g.a, true);
  if (solver.info() == Eigen::Success) {
    g.lambda = solver.eigenvalues();
    g.vectors = solver.eigenvectors();
    g.basis.compute(g.vectors);
    g.basis_rcond = g.basis.rcond();
    g.spectral = g.basis_rcond > 1e-12;
    for (const Event& ev : g.events) g.modal.push_back(ev.row.cast<std::complex<double>>() * g.vectors);
  }
  if (!g.spectral) {
    // Pieces of at most 1 rad of the fastest motion: an event function then turns at most once in one.
    const double fastest =
        Eigen::EigenSolver<MatrixXd>(g.a.topLeftCorner(2 * n_, 2 * n_), false).eigenvalues().cwiseAbs().maxCoeff();
    // Counted in double: a stiffness of 1e90 asks more pieces than an int holds.
    const double pieces = fastest * step_ > 1.0 ? std::ceil(fastest * step_) : 1.0;
    if (!(pieces <= static_cast<double>(kMaxPieces)))
      throw SolverError(fmt::format(
          "shooting at omega = {:.6g} rad/s: {:.3g} pieces of the exact flow in one step, more than {} (the cap of "
          "PiecewiseFlow::kMaxPieces): a stiffness or a force so large that its motion needs pieces too short to "
          "resolve; lower kt or the force, or use period_map = \"newmark\"",
          omega_, pieces, kMaxPieces));
    g.piece = step_ / pieces;
    g.piece_exponential = exponential(g.a, g.piece, 2 * n_ + nc_, omega_);
  }
  return generators_.emplace(modes, std::move(g)).first->second;
}

MatrixXd PiecewiseFlow::stuck_rows(const std::vector<ContactState>& modes, std::vector<Index>& stuck) const {
  stuck.clear();
  for (Index k = 0; k < nc_; ++k)
    if (rigid(modes[static_cast<size_t>(k)])) stuck.push_back(k);
  MatrixXd g(static_cast<Index>(stuck.size()), n_);
  for (size_t i = 0; i < stuck.size(); ++i)
    g.row(static_cast<Index>(i)) = model_.contacts[static_cast<size_t>(stuck[i])].tangential;
  return g;
}

void PiecewiseFlow::rigid_constraints(const std::vector<ContactState>& modes, MatrixXd& a,
                                      std::vector<RowVectorXd>& stuck_force) const {
  stuck_force.assign(static_cast<size_t>(nc_), RowVectorXd());
  std::vector<Index> stuck;
  const MatrixXd g = stuck_rows(modes, stuck);
  if (stuck.empty()) return;
  const auto r = static_cast<Index>(stuck.size());
  const MatrixXd mg = mass_inverse_ * g.transpose();
  const Eigen::FullPivLU<MatrixXd> schur(g * mg);
  if (!schur.isInvertible())
    throw std::invalid_argument(
        "exact flow: the stuck contacts' tangential directions are dependent (rigid stick holds independent ones)");
  // p' = B z + M^-1 G^T mu with G p' = 0; the contact pulls on the model with -a_t^T T = G^T mu omega^2.
  const MatrixXd multiplier = -schur.solve(g * a.middleRows(n_, n_));
  a.middleRows(n_, n_) += mg * multiplier;
  for (Index i = 0; i < r; ++i)
    stuck_force[static_cast<size_t>(stuck[static_cast<size_t>(i)])] = -omega_ * omega_ * multiplier.row(i);
}

MatrixXd PiecewiseFlow::stuck_projection(const std::vector<ContactState>& modes) const {
  std::vector<Index> stuck;
  const MatrixXd g = stuck_rows(modes, stuck);
  MatrixXd projection = MatrixXd::Identity(n_, n_);
  if (stuck.empty()) return projection;
  const MatrixXd mg = mass_inverse_ * g.transpose();
  projection -= mg * (g * mg).fullPivLu().solve(g);  // the rate a stuck u cannot have, as a plastic impact
  return projection;
}

int PiecewiseFlow::halvings(const Generator& mode, const Eigen::VectorXcd& coordinates) const {
  const Eigen::VectorXd speed = mode.lambda.cwiseAbs();
  int k = 0;
  for (const Eigen::RowVectorXcd& modal : mode.modal) {
    const Eigen::VectorXd weight = modal.transpose().cwiseProduct(coordinates).cwiseAbs();
    const double total = weight.sum();
    for (; k < 40; ++k) {
      const double tau = step_ / std::ldexp(1.0, k);
      double fast = 0.0;
      for (Index i = 0; i < speed.size(); ++i) fast += speed[i] * tau > 1.0 ? weight[i] : 0.0;
      if (fast <= 1e-9 * total) break;
    }
  }
  return k;
}

VectorXd PiecewiseFlow::pack(const FlowState& s) const {
  VectorXd z(size_);
  z << s.q, s.p, s.w, 1.0, std::cos(s.theta), std::sin(s.theta);
  return z;
}

void PiecewiseFlow::unpack(const VectorXd& z, FlowState& s) const {
  s.q = z.head(n_);
  s.p = z.segment(n_, n_);
  s.w = z.segment(2 * n_, nc_);
}

RowVectorXd PiecewiseFlow::slider_row(Index k, ContactState m) const {
  const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
  if (!slipping(m) || rigid_) return c.tangential;
  return c.tangential - sign_of(m) * c.point.mu * c.point.kn / c.point.kt * c.normal;
}

double PiecewiseFlow::algebraic_slider(const FlowState& s, Index k, ContactState m) const {
  const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
  return slider_row(k, m).dot(s.q) - c.tangential_offset -
         (slipping(m) && !rigid_ ? sign_of(m) * c.point.mu * c.point.n0 / c.point.kt : 0.0);
}

void PiecewiseFlow::tie_sliders(FlowState& s, MatrixXd* jacobian) const {
  for (Index k = 0; k < nc_; ++k) {
    const ContactState m = s.modes[static_cast<size_t>(k)];
    if (m == ContactState::stick && !rigid_) continue;
    s.w[k] = algebraic_slider(s, k, m);
    if (jacobian) jacobian->row(2 * n_ + k) = slider_row(k, m) * jacobian->topRows(n_);
  }
}

void PiecewiseFlow::settle(FlowState& s) const {
  s.modes.assign(static_cast<size_t>(nc_), ContactState::stick);
  for (Index k = 0; k < nc_; ++k) {
    const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
    const friction::PointParameters& law = c.point;
    const double normal = law.n0 + law.kn * c.normal.dot(s.q);
    ContactState& m = s.modes[static_cast<size_t>(k)];
    if (normal <= 0.0) {
      m = ContactState::lift_off;
    } else if (law.mu == 0.0) {
      m = ContactState::slip_positive;  // T = 0 either way; the slider follows u
    } else if (rigid_) {
      // Stuck at rest (u' at the rounding of p), where the constraint force allows it (below).
      const double rate = c.tangential.dot(s.p), rounding = 1e-13 * c.tangential.cwiseAbs().dot(s.p.cwiseAbs());
      if (rate > rounding) m = ContactState::slip_positive;
      if (rate < -rounding) m = ContactState::slip_negative;
    } else {
      const double u = c.tangential.dot(s.q) - c.tangential_offset;
      const double trial = law.kt * (u - s.w[k]);
      // On the limit to rounding: kt times the rounding of u - w, which a stiff contact makes large.
      const double limit = law.mu * normal,
                   near = limit * (1.0 - 1e-12) - 1e-14 * law.kt * (std::abs(u) + std::abs(s.w[k]));
      const auto rate = [&](ContactState slip) { return slider_row(k, slip).dot(s.p); };
      if (trial > limit || (trial >= near && rate(ContactState::slip_positive) > 0.0))
        m = ContactState::slip_positive;
      else if (trial < -limit || (trial <= -near && rate(ContactState::slip_negative) < 0.0))
        m = ContactState::slip_negative;
    }
  }
  for (Index pass = 0; rigid_ && pass < nc_; ++pass) {  // a stick that needs more than mu N slips
    bool changed = false;
    for (Index k = 0; k < nc_ && !changed; ++k) {  // the others' forces change with one that slips
      ContactState& m = s.modes[static_cast<size_t>(k)];
      if (!rigid(m)) continue;
      m = held_or_slipping(s, k);
      changed = m != ContactState::stick;
    }
    if (!changed) break;
  }
  tie_sliders(s, nullptr);
}

ContactState PiecewiseFlow::held_or_slipping(const FlowState& s, Index k) const {
  const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
  std::vector<ContactState> modes = s.modes;
  modes[static_cast<size_t>(k)] = ContactState::stick;
  const double force = mode_data(modes).stuck_force[static_cast<size_t>(k)].dot(pack(s)),
               limit = c.point.mu * std::max(c.point.n0 + c.point.kn * c.normal.dot(s.q), 0.0);
  if (std::abs(force) <= limit) return ContactState::stick;
  return force > 0.0 ? ContactState::slip_positive : ContactState::slip_negative;
}

MatrixXd PiecewiseFlow::start_jacobian(const FlowState& settled) const {
  MatrixXd j = MatrixXd::Identity(state_size(), state_size());
  if (rigid_) j.block(n_, n_, n_, n_) = stuck_projection(settled.modes);
  FlowState copy = settled;
  tie_sliders(copy, &j);
  return j;
}

std::vector<PiecewiseFlow::Event> PiecewiseFlow::events(const std::vector<ContactState>& modes,
                                                        const std::vector<RowVectorXd>& stuck_force) const {
  std::vector<Event> out;
  const Index p = n_, one = 2 * n_ + nc_;
  for (Index k = 0; k < nc_; ++k) {
    const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
    const friction::PointParameters& law = c.point;
    const ContactState m = modes[static_cast<size_t>(k)];
    if (law.kn > 0.0) {
      RowVectorXd open = RowVectorXd::Zero(size_);  // N <= 0, in metres of v
      open.head(n_) = -c.normal;
      open[one] = -law.n0 / law.kn;
      if (m == ContactState::lift_off) {
        out.push_back({k, law.mu > 0.0 ? ContactState::stick : ContactState::slip_positive, -open});
        continue;
      }
      out.push_back({k, ContactState::lift_off, open});
    } else if (m == ContactState::lift_off) {
      continue;  // kn = 0: the normal load is N0 for ever, so a contact neither opens nor closes
    }
    if (rigid(m)) {
      // |T| reaching mu N, divided by mu N0 + kn (newtons per metre of v)
      RowVectorXd limit = RowVectorXd::Zero(size_);
      limit.head(n_) = law.mu * law.kn * c.normal;
      limit[one] = law.mu * law.n0;
      const double scale = 1.0 / (law.mu * law.n0 + law.kn + 1e-300);
      for (const double s : {1.0, -1.0})
        out.push_back({k, s > 0 ? ContactState::slip_positive : ContactState::slip_negative,
                       scale * (s * stuck_force[static_cast<size_t>(k)] - limit)});
    } else if (m == ContactState::stick) {
      // |kt (u - w)| reaching mu N, divided by kt (metres of u)
      for (const double s : {1.0, -1.0}) {
        RowVectorXd row = RowVectorXd::Zero(size_);
        row.head(n_) = s * c.tangential - law.mu * law.kn / law.kt * c.normal;
        row[2 * n_ + k] = -s;
        row[one] = -s * c.tangential_offset - law.mu * law.n0 / law.kt;
        out.push_back({k, s > 0 ? ContactState::slip_positive : ContactState::slip_negative, row});
      }
    } else if (law.mu > 0.0) {
      RowVectorXd row = RowVectorXd::Zero(size_);  // the slider's rate turning against the slip
      row.segment(p, n_) = -sign_of(m) * slider_row(k, m);
      out.push_back({k, ContactState::stick, row});
    }
  }
  return out;
}

template <class TraceOf>
void PiecewiseFlow::extremes_in_piece(const MatrixXd& a, const VectorXd& z0, const VectorXd& z1, double tau,
                                      const std::vector<Index>& watch, VectorXd& extremes, const TraceOf& trace) const {
  for (size_t i = 0; i < watch.size(); ++i) {
    const Index d = watch[i];
    const auto e = static_cast<Index>(i);
    extremes[e] = std::max({extremes[e], std::abs(z0[d]), std::abs(z1[d])});
    const double r0 = z0[n_ + d], r1 = z1[n_ + d];
    if (!((r0 > 0.0 && r1 < 0.0) || (r0 < 0.0 && r1 > 0.0))) continue;
    RowVectorXd rate = RowVectorXd::Zero(size_);
    rate[n_ + d] = r0 > 0.0 ? -1.0 : 1.0;
    const double at = crossing(trace(rate, nullptr), 0.0, tau);
    extremes[e] = std::max(extremes[e], std::abs(((a * at).exp() * z0)[d]));
  }
}

void PiecewiseFlow::switch_contact(FlowState& s, const Event& ev, const MatrixXd& a, MatrixXd* jacobian) const {
  const Index ns = state_size();
  const Index k = ev.contact;
  const ContactState before = s.modes[static_cast<size_t>(k)];
  s.modes[static_cast<size_t>(k)] = ev.next;
  if (rigid_ && before == ContactState::lift_off && ev.next == ContactState::stick) {
    // Closing at N = 0: no force jumps, and it slips the way it moves (sticking would take an impulse).
    const double rate = model_.contacts[static_cast<size_t>(k)].tangential.dot(s.p);
    if (rate != 0.0)
      s.modes[static_cast<size_t>(k)] = rate > 0.0 ? ContactState::slip_positive : ContactState::slip_negative;
  } else if (rigid_ && ev.next == ContactState::stick) {
    // u' stops. A stick that needs more than mu N reverses the slip at once; either way the
    // acceleration jumps: the saltation I + (f+ - f-) g' / (g' f-).
    s.modes[static_cast<size_t>(k)] = held_or_slipping(s, k);
    if (jacobian) {
      const VectorXd at = pack(s), before_rate = a * at;
      const double crossing_rate = ev.row.dot(before_rate);
      if (crossing_rate > 0.0) {
        const VectorXd jump = (mode_data(s.modes).a * at - before_rate).head(ns);
        const RowVectorXd gradient = ev.row.head(ns) * *jacobian;
        *jacobian += jump * gradient / crossing_rate;
      }
    }
  } else if (before == ContactState::lift_off) {
    // Closing: the slider sticks at u(theta_c), theta_c moving with the start.
    const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
    s.w[k] = c.tangential.dot(s.q) - c.tangential_offset;
    if (jacobian) {
      const double closing_rate = c.normal.dot(s.p);
      RowVectorXd row = c.tangential * jacobian->topRows(n_);
      if (closing_rate > 0.0) row -= c.tangential.dot(s.p) / closing_rate * (c.normal * jacobian->topRows(n_));
      jacobian->row(2 * n_ + k) = row;
    }
  }
}

void PiecewiseFlow::advance(FlowState& s, double theta_end, MatrixXd* jacobian, int max_events, Advance& log,
                            const std::vector<Index>& watch, VectorXd* extremes, MatrixXd* fourier) const {
  if (log.switched.size() != static_cast<size_t>(nc_)) log.switched.assign(static_cast<size_t>(nc_), 0);
  const Index ns = state_size();
  while (theta_end - s.theta > kPhaseResolution) {
    // Not a failure of one period that another start could avoid: the model cannot be resolved, so
    // the whole analysis stops (exit 3) instead of trying every frequency and start at this cost.
    if (++log.pieces > kMaxPieces)
      throw SolverError(fmt::format(
          "shooting at omega = {:.6g} rad/s: more than {} pieces of the exact flow in one period (the cap of "
          "PiecewiseFlow::kMaxPieces) at phase {:.6g} rad: a stiffness or a force so large that its motion needs "
          "pieces too short to resolve; lower kt or the force, or use period_map = \"newmark\"",
          omega_, kMaxPieces, s.theta));
    const Generator& mode = mode_data(s.modes);
    const MatrixXd& a = mode.a;
    const VectorXd z = pack(s);
    Eigen::VectorXcd coordinates;
    double piece = mode.piece;
    const MatrixXd* piece_exponential = &mode.piece_exponential;
    if (mode.spectral) {
      coordinates = mode.basis.solve(z.cast<std::complex<double>>());
      const int k = halvings(mode, coordinates);
      piece = step_ / std::ldexp(1.0, k);
      auto found = mode.halvings.find(k);
      if (found == mode.halvings.end())
        found = mode.halvings.emplace(k, exponential(a, piece, 2 * n_ + nc_, omega_)).first;
      piece_exponential = &found->second;
    }
    const bool whole = theta_end - s.theta >= piece * (1.0 - 1e-12);
    const double tau_end = whole ? piece : theta_end - s.theta;
    MatrixXd e = whole ? *piece_exponential : exponential(a, tau_end, 2 * n_ + nc_, omega_);
    VectorXd z_end = e * z;
    const auto trace = [&](const RowVectorXd& row, const Eigen::RowVectorXcd* modal) {
      Eigen::RowVectorXcd own;
      if (mode.spectral && !modal) own = row.cast<std::complex<double>>() * mode.vectors, modal = &own;
      return FlowTrace(row, a, z, mode.spectral ? modal : nullptr, &mode.lambda, &coordinates, tau_end, row.dot(z_end));
    };
    // The earliest transition in (0, tau_end].
    double first = std::numeric_limits<double>::infinity();
    const Event* next = nullptr;
    for (size_t i = 0; i < mode.events.size(); ++i) {
      const Event& ev = mode.events[i];
      const Eigen::RowVectorXcd* modal = mode.spectral ? &mode.modal[i] : nullptr;
      const double g_end = ev.row.dot(z_end);
      double hi = std::numeric_limits<double>::quiet_NaN();
      std::optional<FlowTrace> g;
      if (g_end > 0.0) {
        hi = tau_end;
      } else if (ev.row.dot(z) <= 0.0 && ev.row.dot(a * z) > 0.0 && ev.row.dot(a * z_end) < 0.0) {
        g.emplace(trace(ev.row, modal));
        const double peak = turning_point(*g, tau_end);
        if (g->value(peak) > 0.0) hi = peak;
      }
      if (!(hi <= tau_end) || hi >= first) continue;
      if (!g) g.emplace(trace(ev.row, modal));
      const double at = crossing(*g, 0.0, hi);
      if (at < first) first = at, next = &ev;
    }
    if (next) {
      // The exact state there must have crossed (the modal values carry rounding): step on until it has.
      for (int polish = 0; polish < 8; ++polish) {
        e = exponential(a, first, 2 * n_ + nc_, omega_);
        z_end = e * z;
        const double g = next->row.dot(z_end), rate = next->row.dot(a * z_end);
        if (g > 0.0 || !(rate > 0.0) || first >= tau_end) break;
        first = std::min(tau_end, first + std::max(-1.5 * g / rate, kPhaseResolution));
      }
    }
    const double tau = next ? first : tau_end;
    if (extremes) extremes_in_piece(a, z, z_end, tau, watch, *extremes, trace);
    if (fourier)
      add_fourier_integrals(a, z, mode.spectral && mode.basis_rcond > 1e-6 ? &coordinates : nullptr, &mode.vectors,
                            &mode.lambda, s.theta, tau, watch, *fourier);
    unpack(z_end, s);
    s.theta = next ? s.theta + first : (whole ? s.theta + tau_end : theta_end);
    if (jacobian) *jacobian = e.topLeftCorner(ns, ns) * *jacobian;
    tie_sliders(s, jacobian);
    if (!next) continue;
    switch_contact(s, *next, a, jacobian);
    log.switched[static_cast<size_t>(next->contact)] = 1;
    tie_sliders(s, jacobian);
    if (++log.events > max_events) {
      log.failure = fmt::format("more than {} contact transitions in one period (chatter) at phase {:.6g} rad",
                                max_events, s.theta);
      return;
    }
  }
  s.theta = theta_end;
}

ContactSample PiecewiseFlow::sample(const FlowState& s, Index k) const {
  const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
  const friction::PointParameters& law = c.point;
  const ContactState m = s.modes[static_cast<size_t>(k)];
  ContactSample out;
  out.u = c.tangential.dot(s.q) - c.tangential_offset;
  out.v = c.normal.dot(s.q);
  out.state = m;
  out.slider = s.w[k];
  if (m == ContactState::lift_off) return out;
  out.normal = std::max(law.n0 + law.kn * out.v, 0.0);
  if (rigid(m))
    out.tangential = mode_data(s.modes).stuck_force[static_cast<size_t>(k)].dot(pack(s));
  else
    out.tangential = m == ContactState::stick ? law.kt * (out.u - s.w[k]) : sign_of(m) * law.mu * out.normal;
  return out;
}

}  // namespace bb::timeint
