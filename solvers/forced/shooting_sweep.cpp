#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "common/constants.hpp"
#include "forced/hbm_level_system.hpp"
#include "forced/time_sweep.hpp"
#include "timeint/newmark_shooting.hpp"
#include "timeint/shooting.hpp"

namespace bb {
namespace {

using Eigen::Index;

timeint::ShootingOptions shooting_options(const TimeSpec& spec, const std::vector<Index>& dofs) {
  timeint::ShootingOptions o;
  o.dofs = dofs;
  o.steps_per_period = spec.steps_per_period;
  o.harmonics = spec.system.harmonics;
  o.tolerance = spec.system.tolerance;
  o.max_iterations = spec.system.max_iterations;
  o.floquet = spec.floquet;
  o.rigid_stick = spec.rigid_stick;
  // The Newmark map's start from rest: a lightly damped model (1 % at 175 Hz) needs tens of periods
  // before Newton's nonsmooth map is near enough; the march stops once a period changes by 1e-3.
  if (spec.period_map == TimeSpec::PeriodMap::newmark) o.warmup_periods = 400;
  return o;
}

// The periodic state of the chosen map, with the start it leaves for the next frequency.
struct Start {
  std::optional<timeint::FlowState> flow;
  std::optional<Eigen::VectorXd> newmark;
};

timeint::ShootingResult shoot(const TimeSpec& spec, const friction::FrictionModel& model, double omega,
                              const timeint::ShootingOptions& options, Start& start) {
  if (spec.period_map == TimeSpec::PeriodMap::newmark) {
    timeint::NewmarkShootingResult s = timeint::newmark_shooting(model, omega, options, spec.alpha, start.newmark);
    if (s.result.steady.converged) start.newmark = std::move(s.state);
    return std::move(s.result);
  }
  timeint::ShootingResult s = timeint::shooting(model, omega, options, start.flow);
  if (s.steady.converged) start.flow = s.start;
  return s;
}

// The Newmark map's state x = (q, dq/dtheta, d2q/dtheta2, sliders) at theta = 0 of the harmonic
// balance's solution at omega (empty without a converged point there): every DOF's harmonics
// recovered, each slider from T = kt (u - w) at theta = 0.
// `system`: the balance hbm was solved with.
std::optional<Eigen::VectorXd> harmonic_balance_start(const hbm::HarmonicBalance& system,
                                                      const friction::FrictionModel& model, const HbmLevel& hbm,
                                                      double omega) {
  if (hbm.path.points.empty()) return std::nullopt;
  const hbm::ContinuationPoint& point = nearest_point(hbm.path, omega);
  if (std::abs(point.omega - omega) > 1e-9 * omega) return std::nullopt;
  const Eigen::MatrixXd c = system.recover(point.x, omega);
  const Index n = c.rows(), nc = static_cast<Index>(model.contacts.size());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3 * n + nc);
  x.head(n) = c.col(0);
  for (int k = 1; k <= hbm.harmonics; ++k) {
    const auto a = c.col(2 * k - 1), b = c.col(2 * k);
    x.head(n) += a;
    x.segment(n, n) += k * b;
    x.segment(2 * n, n) -= (k * k) * a;
  }
  const hbm::HarmonicBalance::ContactForces forces = system.contact_forces(point.x);
  if (static_cast<Index>(forces.contacts.size()) != nc) return std::nullopt;
  for (Index k = 0; k < nc; ++k) {
    const friction::ContactElement& e = model.contacts[static_cast<size_t>(k)];
    const Eigen::VectorXd& t = forces.contacts[static_cast<size_t>(k)].tangential;
    double t0 = t[0];
    for (Index j = 1; j < t.size(); j += 2) t0 += t[j];
    x[3 * n + k] = e.tangential.dot(x.head(n)) - e.tangential_offset - t0 / e.point.kt;
  }
  return x;
}

// Where Newton found no periodic solution on the Newmark map: the march from where it started
// (the harmonic balance's solution, else the previous frequency's orbit, else the static state).
// A march that settles gives Newton a start next to the stable orbit it found; one that does not
// is what the model does instead, its envelope kept in the level (no stable periodic solution near
// the start). Frequency i of `level` gets the march's change, period and envelope.
timeint::ShootingResult march_then_shoot(TimeLevel& level, Index i, const TimeSpec& spec,
                                         const friction::FrictionModel& model, double omega,
                                         const timeint::ShootingOptions& options,
                                         const timeint::SteadyStateOptions& march, const TrackedDofs& tracked,
                                         const Start& from, const std::string& newton_failure, Start& tried) {
  std::optional<timeint::DynamicState> begin;
  if (from.newmark) begin = timeint::newmark_state(model, omega, *from.newmark);
  const timeint::SteadyState m = timeint::steady_state(model, omega, march, begin);
  const auto f = static_cast<size_t>(i);
  level.change[f] = m.change;
  level.period_multiple[f] = m.period_multiple;
  if (m.envelope.rows() >= level.envelope_min.cols())
    for (Index r = 0; r < level.envelope_min.cols(); ++r)
      level.envelope_min(i, r) = m.envelope(r, 0), level.envelope_max(i, r) = m.envelope(r, 1);
  level.envelope_span[f] = peak_quantity_span(m, tracked, level.envelope_min.cols());
  timeint::ShootingResult s;
  if (m.converged) {
    tried = {};
    tried.newmark = timeint::newmark_packed(m.final_state, omega);
    s = shoot(spec, model, omega, options, tried);
    s.steady.cycles += m.cycles;
    if (s.steady.converged) return s;
  }
  s.steady = m;
  s.steady.converged = false;
  s.residual = std::numeric_limits<double>::quiet_NaN();
  s.largest_multiplier = std::numeric_limits<double>::quiet_NaN();
  s.steady.failure = fmt::format(
      "no periodic solution found: Newton failed ({}), and the march from {} {}", newton_failure,
      from.newmark ? "there" : "the static state",
      m.converged ? "settled, but Newton failed from its orbit as well"
      : m.period_multiple > 1
          ? fmt::format("repeats every {} periods after {} (a subharmonic response)", m.period_multiple, m.cycles)
          : fmt::format("repeats within no {} periods after {} (cycle-to-cycle change {:.3g}): its envelope "
                        "stands for the response",
                        march.max_period_multiple, m.cycles, m.change));
  return s;
}

}  // namespace

void periodic_sweep(TimeLevel& level, const PreparedHbm& p, const TimeSpec& spec, const friction::FrictionModel& model,
                    const TrackedDofs& tracked, Index responses, const timeint::SteadyStateOptions& march,
                    const HbmProgress& progress) {
  const auto nf = static_cast<Index>(level.frequency_hz.size());
  const timeint::ShootingOptions options = shooting_options(spec, tracked.dofs);
  const bool newmark_map = spec.period_map == TimeSpec::PeriodMap::newmark;
  level.largest = Eigen::MatrixXd::Constant(nf, responses, std::numeric_limits<double>::quiet_NaN());
  if (newmark_map) {  // filled where a frequency is marched
    level.change.assign(static_cast<size_t>(nf), std::numeric_limits<double>::quiet_NaN());
    level.period_multiple.assign(static_cast<size_t>(nf), 0);
    level.envelope_span.assign(static_cast<size_t>(nf), std::numeric_limits<double>::quiet_NaN());
    level.envelope_min = level.envelope_max =
        Eigen::MatrixXd::Constant(nf, responses, std::numeric_limits<double>::quiet_NaN());
  }
  std::optional<hbm::HarmonicBalance> balance;  // the one level.hbm was solved with, built once
  if (newmark_map && level.hbm) {
    HbmSpec h = spec.system;
    h.harmonics = level.hbm->harmonics;
    balance.emplace(level_system(p, h, level.hbm->force, level.hbm->harmonics, level.hbm->samples));
  }
  level.cycles.assign(static_cast<size_t>(nf), 0);
  level.steady.assign(static_cast<size_t>(nf), false);
  level.failure.assign(static_cast<size_t>(nf), {});
  level.residual.assign(static_cast<size_t>(nf), std::numeric_limits<double>::quiet_NaN());
  level.transitions.assign(static_cast<size_t>(nf), 0);
  level.floquet_max.assign(static_cast<size_t>(nf), std::numeric_limits<double>::quiet_NaN());
  // Frequency i's outcome into the level; true where it has a periodic solution.
  const auto record = [&](Index i, const timeint::ShootingResult& s) {
    const auto f = static_cast<size_t>(i);
    if (newmark_map && s.steady.converged) level.period_multiple[f] = 1;
    level.cycles[f] += s.steady.cycles;
    level.steady[f] = s.steady.converged;
    level.failure[f] = s.steady.failure;
    level.residual[f] = s.residual;
    level.transitions[f] = s.transitions;
    level.floquet_max[f] = s.largest_multiplier;
    level.steps += static_cast<long>(s.steady.cycles) * spec.steps_per_period;
    level.newton_iterations += s.steady.total_iterations;
    level.max_step_iterations = std::max(level.max_step_iterations, static_cast<int>(s.steady.total_iterations));
    // A frequency without a periodic solution keeps the first harmonics of the march's last period.
    const bool harmonics = s.steady.coefficients.rows() == static_cast<Index>(tracked.dofs.size()) &&
                           store_first_harmonics(level, i, s.steady.coefficients, tracked, responses);
    if (!(harmonics && s.steady.converged)) return false;
    level.largest.row(i) = s.largest.head(responses).transpose();
    return true;
  };
  std::vector<Start> orbit(static_cast<size_t>(nf));  // each frequency's periodic state, where found
  Start start;
  for (Index i = 0; i < nf; ++i) {
    const double hz = level.frequency_hz[static_cast<size_t>(i)];
    Start tried = start;
    std::optional<Eigen::VectorXd> from_hbm;
    if (balance) from_hbm = harmonic_balance_start(*balance, model, *level.hbm, kTwoPi * hz);
    if (from_hbm) tried.newmark = from_hbm;
    timeint::ShootingResult s = shoot(spec, model, kTwoPi * hz, options, tried);
    if (!s.steady.converged && from_hbm && start.newmark) {
      tried = start;  // from the previous frequency's periodic state
      s = shoot(spec, model, kTwoPi * hz, options, tried);
    }
    if (!s.steady.converged && newmark_map) {
      Start from = start;
      if (from_hbm) from.newmark = from_hbm;
      s = march_then_shoot(level, i, spec, model, kTwoPi * hz, options, march, tracked, from, s.steady.failure, tried);
    } else if (!s.steady.converged && (start.flow || start.newmark)) {
      tried = {};
      s = shoot(spec, model, kTwoPi * hz, options, tried);  // from the static state
    }
    if (record(i, s)) {
      orbit[static_cast<size_t>(i)] = tried;
      start = std::move(tried);
    }
    if (progress && i % 5 == 0)
      progress(fmt::format("Fe = {:g} N: {:.3f} Hz, shooting {} iterations{}", level.force, hz,
                           s.steady.total_iterations, s.steady.converged ? "" : " (no periodic solution found)"));
  }
  // Back down from the frequencies that converged: a frequency Newton missed from below (at the
  // band's start, from the warm start alone; near a stop whose ringing breaks Newton's path) is
  // shot again from the orbit of the frequency above it.
  for (Index i = nf - 2; i >= 0; --i) {
    const auto f = static_cast<size_t>(i);
    if (level.steady[f] || !level.steady[f + 1]) continue;
    Start tried = orbit[f + 1];
    const timeint::ShootingResult s = shoot(spec, model, kTwoPi * level.frequency_hz[f], options, tried);
    if (s.steady.converged && record(i, s)) orbit[f] = std::move(tried);
  }
}

TimeHistoryRecord periodic_history(const PreparedHbm& p, const TimeSpec& spec) {
  TimeHistoryRecord rec;
  rec.frequency_hz = *spec.history_hz;
  rec.force = spec.system.force_levels.front();
  friction::FrictionModel m = p.model;
  friction::scale_excitation(m, rec.force);
  const double omega = kTwoPi * rec.frequency_hz;
  Start none;
  const timeint::ShootingResult s = shoot(spec, m, omega, shooting_options(spec, p.responses), none);
  rec.steady = s.steady;
  if (!s.steady.converged) return rec;
  // The period repeats: history_cycles copies of its samples.
  timeint::TimeHistory& h = rec.history;
  const int n_t = spec.steps_per_period;
  const auto nr = static_cast<Index>(p.responses.size());
  h.steps = spec.history_cycles * n_t;
  h.displacement.resize(h.steps + 1, nr);
  h.contacts.assign(s.steady.contacts.size(), {});
  for (int k = 0; k <= h.steps; ++k) {
    const int sample = k > 0 && k % n_t == 0 ? n_t : k % n_t;  // a period's end closes its loop
    h.time.push_back(kTwoPi * k / (omega * n_t));
    h.displacement.row(k) = s.samples.row(sample);
    for (size_t c = 0; c < h.contacts.size(); ++c)
      h.contacts[c].push_back(s.steady.contacts[c][static_cast<size_t>(sample)]);
  }
  h.converged = true;
  return rec;
}

}  // namespace bb
