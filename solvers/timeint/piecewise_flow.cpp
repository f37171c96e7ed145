#include "timeint/piecewise_flow.hpp"

#include <fmt/format.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <stdexcept>

namespace bb::timeint {

using contact::ContactState;
using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::RowVectorXd;
using Eigen::VectorXd;

namespace {

double sign_of(ContactState m) { return m == ContactState::slip_negative ? -1.0 : 1.0; }
bool slipping(ContactState m) { return m == ContactState::slip_positive || m == ContactState::slip_negative; }

// Phases below this are one point: a transition is located to it (rad; the period is 2 pi).
constexpr double kPhaseResolution = 1e-13;

// One linear function of the state along one piece, g(tau) = row . exp(a tau) z: by the modes of a
// (O(size) per value) where their basis reproduces the piece's end, else by the exponential.
class Trace {
 public:
  // modal: row V and lambda the eigenvalues of a (a = V diag(lambda) V^-1), coordinates V^-1 z; null
  // without a usable basis.
  Trace(const RowVectorXd& row, const MatrixXd& a, const VectorXd& z, const Eigen::RowVectorXcd* modal,
        const Eigen::VectorXcd* lambda, const Eigen::VectorXcd* coordinates, double check_tau, double check_value)
      : row_(row), a_(a), z_(z) {
    if (!modal) return;
    weights_ = modal->transpose().cwiseProduct(*coordinates);
    lambda_ = *lambda;
    const double scale = row.cwiseAbs().dot(z.cwiseAbs()) + std::abs(check_value);
    spectral_ = std::abs(value(check_tau) - check_value) <= 1e-9 * scale;
  }
  double value(double tau) const {
    if (tau == 0.0) return row_.dot(z_);
    if (!spectral_) return row_.dot((a_ * tau).exp() * z_);
    return (weights_.array() * (lambda_.array() * tau).exp()).sum().real();
  }
  double rate(double tau) const {
    if (!spectral_) return (row_ * a_).dot((a_ * tau).exp() * z_);
    return (weights_.array() * lambda_.array() * (lambda_.array() * tau).exp()).sum().real();
  }

 private:
  const RowVectorXd& row_;
  const MatrixXd& a_;
  const VectorXd& z_;
  Eigen::VectorXcd weights_, lambda_;
  bool spectral_ = false;
};

// The first zero of g in [lo, hi], g(lo) <= 0 < g(hi): Illinois, returning a phase on the far side
// (g > 0), so the transition has happened there.
double crossing(const Trace& g, double lo, double hi) {
  double g_lo = g.value(lo), g_hi = g.value(hi);
  if (g_lo > 0.0) return lo;
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > kPhaseResolution; ++it) {
    double mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (!(mid > lo && mid < hi) || it % 8 == 7) mid = 0.5 * (lo + hi);  // bisect now and then: bounded
    const double v = g.value(mid);
    if (v > 0.0) {
      hi = mid, g_hi = v;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    } else {
      lo = mid, g_lo = v;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    }
  }
  return hi;
}

// The phase in (0, hi) where g' changes from + to - (bisection).
double turning_point(const Trace& g, double hi) {
  double lo = 0.0;
  for (int it = 0; it < 200 && hi - lo > kPhaseResolution; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g.rate(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

PiecewiseFlow::PiecewiseFlow(const friction::FrictionModel& model, double omega_rad_s, double step)
    : model_(model),
      omega_(omega_rad_s),
      step_(step),
      n_(model.mass.rows()),
      nc_(static_cast<Index>(model.contacts.size())),
      size_(2 * n_ + nc_ + 3) {
  if (!(omega_ > 0.0 && std::isfinite(omega_))) throw std::invalid_argument("exact flow: omega must be finite and > 0");
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
    const contact::JenkinsParameters& law = c.law;
    const VectorXd at = c.tangential.transpose(), an = c.normal.transpose();
    const ContactState m = modes[static_cast<size_t>(k)];
    if (m == ContactState::lift_off) continue;
    stiffness += law.kn * an * an.transpose();
    constant -= law.n0 * an;
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
  g.a = std::move(a);
  g.events = events(modes);
  const Eigen::EigenSolver<MatrixXd> solver(g.a, true);
  if (solver.info() == Eigen::Success) {
    g.lambda = solver.eigenvalues();
    g.vectors = solver.eigenvectors();
    g.basis.compute(g.vectors);
    g.spectral = g.basis.rcond() > 1e-12;
    for (const Event& ev : g.events) g.modal.push_back(ev.row.cast<std::complex<double>>() * g.vectors);
  }
  if (!g.spectral) {
    // Pieces of at most 1 rad of the fastest motion: an event function then turns at most once in one.
    const double fastest =
        Eigen::EigenSolver<MatrixXd>(g.a.topLeftCorner(2 * n_, 2 * n_), false).eigenvalues().cwiseAbs().maxCoeff();
    const int pieces = fastest * step_ > 1.0 ? static_cast<int>(std::ceil(fastest * step_)) : 1;
    g.piece = step_ / pieces;
    g.piece_exponential = (g.a * g.piece).exp();
  }
  return generators_.emplace(modes, std::move(g)).first->second;
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
  if (!slipping(m)) return c.tangential;
  return c.tangential - sign_of(m) * c.law.mu * c.law.kn / c.law.kt * c.normal;
}

double PiecewiseFlow::algebraic_slider(const FlowState& s, Index k, ContactState m) const {
  const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
  return slider_row(k, m).dot(s.q) - c.tangential_offset -
         (slipping(m) ? sign_of(m) * c.law.mu * c.law.n0 / c.law.kt : 0.0);
}

void PiecewiseFlow::tie_sliders(FlowState& s, MatrixXd* jacobian) const {
  for (Index k = 0; k < nc_; ++k) {
    const ContactState m = s.modes[static_cast<size_t>(k)];
    if (m == ContactState::stick) continue;
    s.w[k] = algebraic_slider(s, k, m);
    if (jacobian) jacobian->row(2 * n_ + k) = slider_row(k, m) * jacobian->topRows(n_);
  }
}

void PiecewiseFlow::settle(FlowState& s) const {
  s.modes.assign(static_cast<size_t>(nc_), ContactState::stick);
  for (Index k = 0; k < nc_; ++k) {
    const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
    const contact::JenkinsParameters& law = c.law;
    const double normal = law.n0 + law.kn * c.normal.dot(s.q);
    ContactState& m = s.modes[static_cast<size_t>(k)];
    if (normal <= 0.0) {
      m = ContactState::lift_off;
    } else if (law.mu == 0.0) {
      m = ContactState::slip_positive;  // T = 0 either way; the slider follows u
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
  tie_sliders(s, nullptr);
}

MatrixXd PiecewiseFlow::start_jacobian(const FlowState& settled) const {
  MatrixXd j = MatrixXd::Identity(state_size(), state_size());
  FlowState copy = settled;
  tie_sliders(copy, &j);
  return j;
}

std::vector<PiecewiseFlow::Event> PiecewiseFlow::events(const std::vector<ContactState>& modes) const {
  std::vector<Event> out;
  const Index p = n_, one = 2 * n_ + nc_;
  for (Index k = 0; k < nc_; ++k) {
    const friction::ContactElement& c = model_.contacts[static_cast<size_t>(k)];
    const contact::JenkinsParameters& law = c.law;
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
    if (m == ContactState::stick) {
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

void PiecewiseFlow::advance(FlowState& s, double theta_end, MatrixXd* jacobian, int max_events, Advance& log,
                            const std::vector<Index>& watch, VectorXd* extremes) const {
  if (log.switched.size() != static_cast<size_t>(nc_)) log.switched.assign(static_cast<size_t>(nc_), 0);
  const Index ns = state_size();
  while (theta_end - s.theta > kPhaseResolution) {
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
      if (found == mode.halvings.end()) found = mode.halvings.emplace(k, (a * piece).exp()).first;
      piece_exponential = &found->second;
    }
    const bool whole = theta_end - s.theta >= piece * (1.0 - 1e-12);
    const double tau_end = whole ? piece : theta_end - s.theta;
    MatrixXd e = whole ? *piece_exponential : MatrixXd((a * tau_end).exp());
    VectorXd z_end = e * z;
    const auto trace = [&](const RowVectorXd& row, const Eigen::RowVectorXcd* modal) {
      Eigen::RowVectorXcd own;
      if (mode.spectral && !modal) own = row.cast<std::complex<double>>() * mode.vectors, modal = &own;
      return Trace(row, a, z, mode.spectral ? modal : nullptr, &mode.lambda, &coordinates, tau_end, row.dot(z_end));
    };
    // The earliest transition in (0, tau_end].
    double first = std::numeric_limits<double>::infinity();
    const Event* next = nullptr;
    for (size_t i = 0; i < mode.events.size(); ++i) {
      const Event& ev = mode.events[i];
      const Eigen::RowVectorXcd* modal = mode.spectral ? &mode.modal[i] : nullptr;
      const double g_end = ev.row.dot(z_end);
      double hi = std::numeric_limits<double>::quiet_NaN();
      std::optional<Trace> g;
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
        e = (a * first).exp();
        z_end = e * z;
        const double g = next->row.dot(z_end), rate = next->row.dot(a * z_end);
        if (g > 0.0 || !(rate > 0.0) || first >= tau_end) break;
        first = std::min(tau_end, first + std::max(-1.5 * g / rate, kPhaseResolution));
      }
    }
    const double tau = next ? first : tau_end;
    if (extremes) extremes_in_piece(a, z, z_end, tau, watch, *extremes, trace);
    unpack(z_end, s);
    s.theta = next ? s.theta + first : (whole ? s.theta + tau_end : theta_end);
    if (jacobian) *jacobian = e.topLeftCorner(ns, ns) * *jacobian;
    tie_sliders(s, jacobian);
    if (!next) continue;
    const Index k = next->contact;
    const ContactState before = s.modes[static_cast<size_t>(k)];
    s.modes[static_cast<size_t>(k)] = next->next;
    log.switched[static_cast<size_t>(k)] = 1;
    if (before == ContactState::lift_off) {
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
  const contact::JenkinsParameters& law = c.law;
  const ContactState m = s.modes[static_cast<size_t>(k)];
  ContactSample out;
  out.u = c.tangential.dot(s.q) - c.tangential_offset;
  out.v = c.normal.dot(s.q);
  out.state = m;
  out.slider = s.w[k];
  if (m == ContactState::lift_off) return out;
  out.normal = std::max(law.n0 + law.kn * out.v, 0.0);
  out.tangential = m == ContactState::stick ? law.kt * (out.u - s.w[k]) : sign_of(m) * law.mu * out.normal;
  return out;
}

}  // namespace bb::timeint
