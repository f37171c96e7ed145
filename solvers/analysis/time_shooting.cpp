#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "analysis/time_sweeps.hpp"
#include "common/constants.hpp"
#include "forced/hbm_level_system.hpp"
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
    x[3 * n + k] = e.tangential.dot(x.head(n)) - e.tangential_offset - t0 / e.law.kt;
  }
  return x;
}

}  // namespace

void periodic_sweep(TimeLevel& level, const PreparedHbm& p, const TimeSpec& spec, const friction::FrictionModel& model,
                    const TrackedDofs& tracked, Index responses, const HbmProgress& progress) {
  const auto nf = static_cast<Index>(level.frequency_hz.size());
  const timeint::ShootingOptions options = shooting_options(spec, tracked.dofs);
  level.largest = Eigen::MatrixXd::Constant(nf, responses, std::numeric_limits<double>::quiet_NaN());
  std::optional<hbm::HarmonicBalance> balance;  // the one level.hbm was solved with, built once
  if (spec.period_map == TimeSpec::PeriodMap::newmark && level.hbm) {
    HbmSpec h = spec.system;
    h.harmonics = level.hbm->harmonics;
    balance.emplace(level_system(p, h, level.hbm->force, level.hbm->harmonics, level.hbm->samples));
  }
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
