#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <numbers>

#include "analysis/time_sweeps.hpp"
#include "timeint/newmark_shooting.hpp"
#include "timeint/shooting.hpp"

namespace bb {
namespace {

using Eigen::Index;
constexpr double kTwoPi = 2 * std::numbers::pi;

timeint::ShootingOptions shooting_options(const TimeSpec& spec, const std::vector<Index>& dofs) {
  timeint::ShootingOptions o;
  o.dofs = dofs;
  o.steps_per_period = spec.steps_per_period;
  o.harmonics = spec.system.harmonics;
  o.tolerance = spec.system.tolerance;
  o.max_iterations = spec.system.max_iterations;
  o.floquet = spec.floquet;
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

}  // namespace

void periodic_sweep(TimeLevel& level, const TimeSpec& spec, const friction::FrictionModel& model,
                    const TrackedDofs& tracked, Index responses, const HbmProgress& progress) {
  const auto nf = static_cast<Index>(level.frequency_hz.size());
  const timeint::ShootingOptions options = shooting_options(spec, tracked.dofs);
  level.largest = Eigen::MatrixXd::Constant(nf, responses, std::numeric_limits<double>::quiet_NaN());
  Start start;
  for (Index i = 0; i < nf; ++i) {
    const double hz = level.frequency_hz[static_cast<size_t>(i)];
    Start tried = start;
    timeint::ShootingResult s = shoot(spec, model, kTwoPi * hz, options, tried);
    if (!s.steady.converged && (start.flow || start.newmark)) {
      tried = {};
      s = shoot(spec, model, kTwoPi * hz, options, tried);  // from the static state
    }
    level.cycles.push_back(s.steady.cycles);
    level.steady.push_back(s.steady.converged);
    level.failure.push_back(s.steady.failure);
    level.residual.push_back(s.residual);
    level.transitions.push_back(s.transitions);
    level.floquet_max.push_back(s.largest_multiplier);
    level.steps += static_cast<long>(s.steady.cycles) * spec.steps_per_period;
    level.newton_iterations += s.steady.total_iterations;
    level.max_step_iterations = std::max(level.max_step_iterations, static_cast<int>(s.steady.total_iterations));
    if (s.steady.converged && store_first_harmonics(level, i, s.steady.coefficients, tracked, responses)) {
      level.largest.row(i) = s.largest.head(responses).transpose();
      start = std::move(tried);
    }
    if (progress && i % 5 == 0)
      progress(fmt::format("Fe = {:g} N: {:.3f} Hz, shooting {} iterations{}", level.force, hz,
                           s.steady.total_iterations, s.steady.converged ? "" : " (no periodic solution found)"));
  }
}

TimeHistoryRecord periodic_history(const PreparedHbm& p, const TimeSpec& spec) {
  TimeHistoryRecord rec;
  rec.frequency_hz = *spec.history_hz;
  rec.force = spec.system.force_levels.front();
  friction::FrictionModel m = p.model;
  m.harmonic_load *= rec.force;
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
