#include "friction/aft_events.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "common/constants.hpp"
#include "friction/aft_pieces.hpp"
#include "friction/illinois.hpp"

namespace bb::friction {
namespace {

// [1, cos t, sin t, ..., cos Ht, sin Ht] and its derivative in theta.
void basis_at(double theta, int harmonics, Eigen::RowVectorXd& phi, Eigen::RowVectorXd& dphi) {
  phi.resize(2 * harmonics + 1);
  dphi.resize(2 * harmonics + 1);
  phi[0] = 1.0;
  dphi[0] = 0.0;
  double s1 = 0.0, c1 = 0.0;
  sincos(theta, &s1, &c1);  // glibc: the values of std::sin and std::cos, in one call
  double c = 1.0, s = 0.0;
  for (int h = 1; h <= harmonics; ++h) {
    const double cn = c * c1 - s * s1;
    s = s * c1 + c * s1;
    c = cn;
    phi[2 * h - 1] = c;
    phi[2 * h] = s;
    dphi[2 * h - 1] = -h * s;
    dphi[2 * h] = h * c;
  }
}

// The relative displacements and their theta-derivatives at one instant.
struct Motion {
  double theta = 0.0, u = 0.0, v = 0.0, du = 0.0, dv = 0.0, ddu = 0.0, ddv = 0.0;
};

// What ends a phase. The first four end stick or slip, the last two open or close the contact.
enum class Event { slip_up, slip_down, stop_positive, stop_negative, open, close };

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The basis and its derivative at the samples: a sweep evaluates thousands of motions of one H
// and n, and most sample intervals hold no event.
struct Grid {
  int harmonics = -1, samples = -1;
  RowMajor phi, dphi;  // (n + 1) x m at theta_k (k = n is 2 pi)

  static const Grid& of(int harmonics, int samples) {
    thread_local Grid grid;
    if (grid.harmonics != harmonics || grid.samples != samples) {
      const Eigen::Index m = harmonic_size(harmonics);
      grid.phi.resize(samples + 1, m);
      grid.dphi.resize(samples + 1, m);
      Eigen::RowVectorXd phi, dphi;
      for (int k = 0; k <= samples; ++k) {
        basis_at(kTwoPi * k / samples, harmonics, phi, dphi);
        grid.phi.row(k) = phi;
        grid.dphi.row(k) = dphi;
      }
      grid.harmonics = harmonics;
      grid.samples = samples;
    }
    return grid;
  }
  double theta(int k) const { return kTwoPi * k / samples; }
};

class EventMarch {
 public:
  EventMarch(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Grid& grid)
      : p_(p),
        u_(u),
        v_(v),
        harmonics_(harmonics_of(u.size())),
        grid_(grid),
        frictionless_(!(p.mu > 0.0)),
        ddu_(u.size()),
        ddv_(v.size()),
        samples_(static_cast<size_t>(grid.samples + 1)) {
    // Coefficients of u'' and v'': -h^2 times those of u and v.
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      const double h = static_cast<double>((i + 1) / 2);
      ddu_[i] = -h * h * u[i];
      ddv_[i] = -h * h * v[i];
    }
    // sum_h h^k |(a_h, b_h)|: bounds of the k-th derivatives of u and v over the period, k = 2, 3.
    for (int h = 1; h <= harmonics_; ++h) {
      const double au = std::hypot(u[2 * h - 1], u[2 * h]), av = std::hypot(v[2 * h - 1], v[2 * h]);
      const double h2 = static_cast<double>(h) * h;
      u_bound_[0] += h2 * au;
      v_bound_[0] += h2 * av;
      u_bound_[1] += h2 * h * au;
      v_bound_[1] += h2 * h * av;
    }
  }

  Motion motion(double theta) {
    basis_at(theta, harmonics_, phi_, dphi_);
    return current(theta);
  }
  // The motion at sample k (k = n: 2 pi), evaluated once per AFT: the scale, every marched period
  // and the closure read the same samples.
  Motion sample(int k) {
    auto& cached = samples_[static_cast<size_t>(k)];
    if (!cached) {
      load_sample_basis(k);
      cached = current(grid_.theta(k));
    }
    return *cached;
  }
  double normal_raw(const Motion& m) const { return p_.n0 + p_.kn * m.v; }

  // The value whose sign change is the event, and whether `value` is past it.
  double value(Event e, const Motion& m) const {
    const double slip_rate = p_.mu * p_.kn * m.dv / p_.kt;
    switch (e) {
      case Event::slip_up:
        return p_.kt * (m.u - stuck().w) - p_.mu * normal_raw(m);
      case Event::slip_down:
        return p_.kt * (m.u - stuck().w) + p_.mu * normal_raw(m);
      case Event::stop_positive:
        return m.du - slip_rate;
      case Event::stop_negative:
        return m.du + slip_rate;
      case Event::open:
      case Event::close:
        return normal_raw(m);
    }
    return 0.0;
  }
  // The value's theta-derivative.
  double rate(Event e, const Motion& m) const {
    switch (e) {
      case Event::slip_up:
        return p_.kt * m.du - p_.mu * p_.kn * m.dv;
      case Event::slip_down:
        return p_.kt * m.du + p_.mu * p_.kn * m.dv;
      case Event::stop_positive:
        return m.ddu - p_.mu * p_.kn * m.ddv / p_.kt;
      case Event::stop_negative:
        return m.ddu + p_.mu * p_.kn * m.ddv / p_.kt;
      case Event::open:
      case Event::close:
        return p_.kn * m.dv;
    }
    return 0.0;
  }
  // +1 where the event is a rise of its value through zero, -1 where it is a fall.
  static double orientation(Event e) {
    return e == Event::slip_up || e == Event::stop_negative || e == Event::close ? 1.0 : -1.0;
  }
  static bool past(Event e, double value) { return orientation(e) * value > 0.0; }

  // The events that can end the current state (at most three).
  struct Watched {
    std::array<Event, 3> events;
    int count = 0;
  };
  Watched watched() const {
    switch (state_) {
      case ContactState::stick:
        return {{Event::slip_up, Event::slip_down, Event::open}, 3};
      case ContactState::slip_positive:
        return frictionless_ ? Watched{{Event::open}, 1} : Watched{{Event::stop_positive, Event::open}, 2};
      case ContactState::slip_negative:
        return frictionless_ ? Watched{{Event::open}, 1} : Watched{{Event::stop_negative, Event::open}, 2};
      case ContactState::lift_off:
        return {{Event::close}, 1};
    }
    return {};
  }

  // A bound of the value's second theta-derivative over the period.
  double curvature_bound(Event e) const {
    switch (e) {
      case Event::slip_up:
      case Event::slip_down:
        return p_.kt * u_bound_[0] + p_.mu * p_.kn * v_bound_[0];
      case Event::stop_positive:
      case Event::stop_negative:
        return u_bound_[1] + p_.mu * p_.kn / p_.kt * v_bound_[1];
      case Event::open:
      case Event::close:
        return p_.kn * v_bound_[0];
    }
    return 0.0;
  }
  // Whether the value can pass the event inside (a, b) though it is before it at both ends: not
  // when the Taylor bound from either end (its slope there, the curvature bounded) stays before it.
  bool may_pass_between(Event e, double a, const Motion& begin, double b, const Motion& end) const {
    const double o = orientation(e), k = 0.5 * curvature_bound(e), d = b - a;
    const double from_a = o * value(e, begin) + std::max(o * rate(e, begin), 0.0) * d + k * d * d;
    const double from_b = o * value(e, end) + std::max(-o * rate(e, end), 0.0) * d + k * d * d;
    return std::min(from_a, from_b) > 0.0;
  }

  // The first instant in (a, b] past the event; `a` is taken as before it. Bisection while the
  // lower end's value is not clearly before the event (right after a transition it sits on that
  // transition's root), then regula falsi.
  double locate(Event e, double a, double b, double fb) {
    double fa = value(e, motion(a));
    const auto unclear = [&] { return past(e, fa) || std::abs(fa) <= 1e-12 * std::abs(fb); };
    for (int i = 0; i < 60 && unclear() && b - a > 1e-15 * kTwoPi; ++i) {
      const double mid = 0.5 * (a + b), fm = value(e, motion(mid));
      (past(e, fm) ? b : a) = mid;
      (past(e, fm) ? fb : fa) = fm;
    }
    if (unclear()) return b;
    return illinois([&](double t) { return value(e, motion(t)); }, a, b, fa, fb);
  }

  // Where in (a, b) the value comes closest to the event, when it turns back inside the interval
  // (its rate points towards the event at a and away at b); nullopt otherwise. A phase shorter
  // than the interval starts and ends there.
  std::optional<double> turning_point(Event e, double a, const Motion& begin, double b, const Motion& end) {
    const double ra = orientation(e) * rate(e, begin), rb = orientation(e) * rate(e, end);
    if (!(ra > 0.0 && rb < 0.0)) return std::nullopt;
    return illinois([&](double t) { return orientation(e) * rate(e, motion(t)); }, a, b, ra, rb);
  }

  // Enters the state an event leads to, at the event's instant.
  void apply(Event e, const Motion& m) {
    switch (e) {
      case Event::slip_up:
        state_ = ContactState::slip_positive;
        break;
      case Event::slip_down:
        state_ = ContactState::slip_negative;
        break;
      case Event::stop_positive:
        stick_at_limit(m, 1.0);
        break;
      case Event::stop_negative:
        stick_at_limit(m, -1.0);
        break;
      case Event::open:
        state_ = ContactState::lift_off;
        break;
      case Event::close:
        if (frictionless_) {
          state_ = ContactState::slip_positive;
        } else {
          close_at(m);
        }
        break;
    }
  }

  // The state at theta = 0 of the first period from a slider w: the step of jenkins_step.
  void start(double w) {
    load_sample_basis(0);  // for the slider's derivatives
    const Motion m = sample(0);
    const double n = normal_raw(m);
    if (!(n > 0.0)) {
      state_ = ContactState::lift_off;
      return;
    }
    const double reach = p_.mu * n / p_.kt;
    if (frictionless_) {
      state_ = ContactState::slip_positive;
    } else if (w < m.u - reach) {
      if (past(Event::stop_positive, value(Event::stop_positive, m)))
        stick_at_limit(m, 1.0);
      else
        state_ = ContactState::slip_positive;
    } else if (w > m.u + reach) {
      if (past(Event::stop_negative, value(Event::stop_negative, m)))
        stick_at_limit(m, -1.0);
      else
        state_ = ContactState::slip_negative;
    } else {
      sliders_.push_back({w, Eigen::RowVectorXd::Zero(2 * u_.size()), Eigen::RowVector4d::Zero()});
      state_ = ContactState::stick;
    }
  }

  // The slider at an instant of the current state.
  double slider(const Motion& m) const {
    switch (state_) {
      case ContactState::stick:
        return stuck().w;
      case ContactState::slip_positive:
        return m.u - p_.mu * normal_raw(m) / p_.kt;
      case ContactState::slip_negative:
        return m.u + p_.mu * normal_raw(m) / p_.kt;
      case ContactState::lift_off:
        return m.u;
    }
    return 0.0;
  }

  // Marches sample interval k from the motion at its start to the motion at its end, splitting it
  // at the events; appends its pieces.
  void march_interval(int k, Motion begin, const Motion& end, std::vector<Piece>& pieces) {
    double a = grid_.theta(k);
    const double b = grid_.theta(k + 1);
    for (int events = 0;; ++events) {
      double first = b;
      std::optional<Event> next;
      if (events < 8)  // more in one interval is a grazing loop: the rest is marched in this state
        for (const Watched w = watched(); Event e : std::span(w.events.data(), static_cast<size_t>(w.count))) {
          double fb = value(e, end), until = b;
          if (!past(e, fb)) {  // past and back within the interval?
            if (!may_pass_between(e, a, begin, b, end)) continue;
            const std::optional<double> turn = turning_point(e, a, begin, b, end);
            if (!turn) continue;
            fb = value(e, motion(*turn));
            if (!past(e, fb)) continue;
            until = *turn;
          }
          const double at = locate(e, a, until, fb);
          if (at < first || !next) {
            first = at;
            next = e;
          }
        }
      const int slider = state_ == ContactState::stick ? static_cast<int>(sliders_.size()) - 1 : -1;
      if (!next) {
        pieces.push_back({a, b, state_, slider});
        return;
      }
      if (first > a) pieces.push_back({a, first, state_, slider});
      begin = motion(first);
      apply(*next, begin);
      a = first;
    }
  }

  ContactState state() const { return state_; }
  const std::vector<StuckSlider>& sliders() const { return sliders_; }
  // The state at an instant as far as the rest of a period depends on it: the stuck slider's index
  // and position in stick, nothing more in slip and lift-off.
  struct Phase {
    ContactState state = ContactState::stick;
    int slider = -1;
    double w = 0.0;
    bool continues(const Phase& o) const { return state == o.state && (state != ContactState::stick || w == o.w); }
  };
  Phase phase() const {
    if (state_ != ContactState::stick) return {state_, -1, 0.0};
    return {state_, static_cast<int>(sliders_.size()) - 1, stuck().w};
  }

 private:
  const StuckSlider& stuck() const { return sliders_.back(); }
  void load_sample_basis(int k) {
    phi_ = grid_.phi.row(k);
    dphi_ = grid_.dphi.row(k);
  }
  Motion current(double theta) const {
    return {theta, phi_.dot(u_), phi_.dot(v_), dphi_.dot(u_), dphi_.dot(v_), phi_.dot(ddu_), phi_.dot(ddv_)};
  }

  // Slip in direction `sign` stops: the slider stays where the Coulomb limit left it.
  void stick_at_limit(const Motion& m, double sign) {
    const Eigen::Index size = u_.size();
    const double n = normal_raw(m);
    StuckSlider s{m.u - sign * p_.mu * n / p_.kt, Eigen::RowVectorXd::Zero(2 * size), Eigen::RowVector4d::Zero()};
    s.dw.head(size) = phi_;
    s.dw.tail(size) = -sign * p_.mu * p_.kn / p_.kt * phi_;
    s.dw_law[law_kn] = -sign * p_.mu * m.v / p_.kt;
    s.dw_law[law_kt] = sign * p_.mu * n / (p_.kt * p_.kt);
    s.dw_law[law_mu] = -sign * n / p_.kt;
    s.dw_law[law_n0] = -sign * p_.mu / p_.kt;
    sliders_.push_back(std::move(s));
    state_ = ContactState::stick;
  }

  // The contact closes (N = 0 rising): it sticks with zero tangential force, w = u(theta_c).
  void close_at(const Motion& m) {
    const Eigen::Index size = u_.size();
    StuckSlider s{m.u, Eigen::RowVectorXd::Zero(2 * size), Eigen::RowVector4d::Zero()};
    s.dw.head(size) = phi_;
    // theta_c moves with n0 + kn v(theta_c) = 0: d theta_c = -(kn dv + v dkn + dn0) / (kn v').
    const double rate = p_.kn * m.dv;
    if (std::abs(rate) > 0.0) {
      s.dw.tail(size) = -m.du * p_.kn / rate * phi_;
      s.dw_law[law_kn] = -m.du * m.v / rate;
      s.dw_law[law_n0] = -m.du / rate;
    }
    sliders_.push_back(std::move(s));
    state_ = ContactState::stick;
  }

  const PointParameters& p_;
  const Eigen::VectorXd& u_;
  const Eigen::VectorXd& v_;
  const int harmonics_;
  const Grid& grid_;
  const bool frictionless_;
  ContactState state_ = ContactState::stick;
  std::array<double, 2> u_bound_{}, v_bound_{};  // bounds of the 2nd and 3rd derivatives of u, v
  Eigen::VectorXd ddu_, ddv_;                    // coefficients of u'' and v''
  std::vector<StuckSlider> sliders_;
  Eigen::RowVectorXd phi_, dphi_;  // the basis at the last motion() or sample() instant
  std::vector<std::optional<Motion>> samples_;
};

}  // namespace

AftResult aft_jenkins_events(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                             const AftOptions& options) {
  const int n = options.samples;
  const Grid& grid = Grid::of(harmonics_of(u.size()), n);
  EventMarch march(p, u, v, grid);
  AftResult r;
  r.u.resize(n);
  r.v.resize(n);
  r.t.resize(n);
  r.n.resize(n);
  r.w.resize(n);
  r.state.assign(static_cast<size_t>(n), ContactState::stick);
  march.start(options.initial_slider);
  double scale = 0.0;
  for (int k = 0; k < n; ++k) {
    const Motion m = march.sample(k);
    scale = std::max({scale, std::abs(m.u), p.mu * std::max(march.normal_raw(m), 0.0) / p.kt});
  }
  // A period that reaches a sample in the phase the period before had there repeats that period
  // from there on, to the bit: its pieces are copied instead of marched (most periods after the
  // first differ only until their first slip).
  std::vector<Piece> pieces, before;
  std::vector<EventMarch::Phase> phases(static_cast<size_t>(n)), phases_before(static_cast<size_t>(n));
  std::vector<size_t> first_piece(static_cast<size_t>(n)), first_piece_before(static_cast<size_t>(n));
  double slider = march.slider(march.sample(0));
  for (int period = 1; period <= options.max_periods; ++period) {
    const double start = slider;
    std::swap(pieces, before);
    std::swap(phases, phases_before);
    std::swap(first_piece, first_piece_before);
    pieces.clear();
    Motion m = march.sample(0);
    int k = 0;
    for (; k < n; ++k) {
      const EventMarch::Phase phase = march.phase();
      const size_t ku = static_cast<size_t>(k);
      if (period > 1 && phase.continues(phases_before[ku])) break;
      phases[ku] = phase;
      first_piece[ku] = pieces.size();
      const Motion next = march.sample(k + 1);
      r.u[k] = m.u;
      r.v[k] = m.v;
      r.state[ku] = march.state();
      r.w[k] = march.slider(m);
      r.n[k] = march.state() == ContactState::lift_off ? 0.0 : std::max(march.normal_raw(m), 0.0);
      r.t[k] = march.state() == ContactState::lift_off ? 0.0 : p.kt * (m.u - r.w[k]);
      march.march_interval(k, m, next, pieces);
      m = next;
    }
    if (k < n) {
      // The rest as the period before (its samples' records stand in r); its stick run on from
      // sample k continues this period's stuck slider.
      const EventMarch::Phase now = march.phase(), then = phases_before[static_cast<size_t>(k)];
      for (size_t i = first_piece_before[static_cast<size_t>(k)]; i < before.size(); ++i) {
        Piece piece = before[i];
        if (then.slider >= 0 && piece.slider == then.slider) piece.slider = now.slider;
        pieces.push_back(piece);
      }
      r.periods = period;
      r.closure_mismatch = 0.0;  // the period ends where the one before ended, which it started from
      r.closed = true;
      break;
    }
    slider = march.slider(m);  // m is the motion at 2 pi
    r.periods = period;
    r.closure_mismatch = std::abs(slider - start);
    if (period >= 2 && r.closure_mismatch <= options.closure_tolerance * scale) {
      r.closed = true;
      break;
    }
  }
  integrate_pieces(p, u, v, pieces, march.sliders(), options.law_derivatives, r);
  return r;
}

}  // namespace bb::friction
