#include "forced/time_sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>

#include "common/constants.hpp"
#include "common/seconds_since.hpp"
#include "forced/hbm_level_system.hpp"
#include "forced/stuck_limit.hpp"
#include "timeint/newmark.hpp"
#include "timeint/shooting.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;

// The stepped sine of one force level: the steady state at each grid frequency, each starting from
// the previous one's final state.
void stepped_sine(TimeLevel& level, const PreparedHbm& p, const TimeSpec& spec, const friction::FrictionModel& m,
                  const timeint::SteadyStateOptions& options, const TrackedDofs& tracked, const HbmProgress& progress) {
  const std::vector<double>& frequencies = level.frequency_hz;
  const auto nf = static_cast<Index>(frequencies.size());
  const auto nr = static_cast<Index>(p.responses.size());
  const std::vector<Index>& dofs = tracked.dofs;
  const double force = level.force;
  std::optional<timeint::DynamicState> start;
  level.envelope_min = level.envelope_max = Eigen::MatrixXd::Constant(nf, nr, kNan);
  for (Index i = 0; i < nf; ++i) {
    const double omega = kTwoPi * frequencies[static_cast<size_t>(i)];
    const timeint::SteadyState s = timeint::steady_state(m, omega, options, start);
    level.cycles.push_back(s.cycles);
    level.steady.push_back(s.converged);
    level.steps += static_cast<long>(s.cycles) * spec.steps_per_period;
    level.newton_iterations += s.total_iterations;
    level.max_step_iterations = std::max(level.max_step_iterations, s.max_iterations);
    level.failure.push_back(s.failure);
    level.change.push_back(s.change);
    level.period_multiple.push_back(s.period_multiple);
    if (s.envelope.rows() == static_cast<Index>(dofs.size()))
      for (Index r = 0; r < nr; ++r)
        level.envelope_min(i, r) = s.envelope(r, 0), level.envelope_max(i, r) = s.envelope(r, 1);
    level.envelope_span.push_back(peak_quantity_span(s, tracked, nr));
    if (s.coefficients.rows() == static_cast<Index>(dofs.size()) &&
        store_first_harmonics(level, i, s.coefficients, tracked, nr))
      start = s.final_state;  // the next frequency starts from here (also when not yet steady)
    if (progress && i % 5 == 0)
      progress(fmt::format("Fe = {:g} N: {:.3f} Hz, {} cycles{}", force, frequencies[static_cast<size_t>(i)], s.cycles,
                           s.converged ? "" : " (not steady)"));
  }
}

// The linear model (every contact replaced by its springs kn, kt; eq 3.51) by direct solves on the grid.
void linear_on_grid(TimeLevel& level, const PreparedHbm& p, const friction::FrictionModel& m, bool pair) {
  const std::vector<double>& frequencies = level.frequency_hz;
  const auto nf = static_cast<Index>(frequencies.size());
  const auto nr = static_cast<Index>(p.responses.size());
  level.linear = Eigen::MatrixXd(nf, nr);
  if (pair) level.linear_components = Eigen::MatrixXd(nf, 2);
  for (Index i = 0; i < nf; ++i) {
    const double w = kTwoPi * frequencies[static_cast<size_t>(i)];
    const Eigen::VectorXcd z = stuck_response(m, w);
    for (Index r = 0; r < nr; ++r) level.linear(i, r) = std::abs(z[p.responses[static_cast<size_t>(r)]]);
    if (pair) {
      level.linear_components(i, 0) = std::abs(z[p.ip_oop->first] + z[p.ip_oop->second]) / 2;
      level.linear_components(i, 1) = std::abs(z[p.ip_oop->second] - z[p.ip_oop->first]) / 2;
    }
  }
}

// One force level: the stepped sine, the linear model and (when asked) the harmonic balance on the grid.
}  // namespace

TimeLevel sweep_level(const PreparedHbm& p, const TimeSpec& spec, const timeint::SteadyStateOptions& options,
                      const TrackedDofs& tracked, const std::vector<double>& frequencies, double force,
                      const HbmProgress& progress) {
  const auto t0 = Clock::now();
  const auto nf = static_cast<Index>(frequencies.size());
  const auto nr = static_cast<Index>(p.responses.size());
  TimeLevel level;
  level.force = force;
  level.frequency_hz = frequencies;
  level.amplitude = level.phase = Eigen::MatrixXd::Constant(nf, nr, kNan);
  if (tracked.pair) level.components = Eigen::MatrixXd::Constant(nf, 2, kNan);
  friction::FrictionModel m = p.model;
  friction::scale_excitation(m, force);
  if (spec.compare_harmonics > 0) {  // first: shooting on the Newmark map starts from it
    HbmSpec h = spec.system;
    h.harmonics = spec.compare_harmonics;
    h.time_samples = 0;
    level.hbm = sweep_hbm_level(p, h, force, spec.compare_harmonics);
  }
  if (spec.method == TimeSpec::Method::shooting)
    periodic_sweep(level, p, spec, m, tracked, nr, options, progress);
  else
    stepped_sine(level, p, spec, m, options, tracked, progress);
  linear_on_grid(level, p, m, tracked.pair.has_value());
  level.seconds = seconds_since(t0);
  return level;
}

// The steady state at history_hz and history_cycles periods after it, every step recorded.
TimeHistoryRecord record_history(const PreparedHbm& p, const TimeSpec& spec,
                                 const timeint::SteadyStateOptions& options) {
  TimeHistoryRecord rec;
  rec.frequency_hz = *spec.history_hz;
  rec.force = spec.system.force_levels.front();
  friction::FrictionModel m = p.model;
  friction::scale_excitation(m, rec.force);
  const double omega = kTwoPi * rec.frequency_hz;
  rec.steady = timeint::steady_state(m, omega, options);
  if (rec.steady.cycles > 0) {
    timeint::NewmarkOptions n = options.newmark;
    n.time_step = kTwoPi / (omega * spec.steps_per_period);
    const timeint::NewmarkIntegrator integrator(m, n);
    timeint::RecordOptions record;
    record.dofs = p.responses;
    rec.history = timeint::integrate(integrator, rec.steady.final_state, timeint::model_excitation(m, omega),
                                     spec.history_cycles * spec.steps_per_period, record);
  }
  return rec;
}

TrackedDofs tracked_dofs(const PreparedHbm& p) {
  TrackedDofs t{p.responses, std::nullopt};
  auto slot = [&](Index dof) {
    const auto it = std::find(t.dofs.begin(), t.dofs.end(), dof);
    if (it != t.dofs.end()) return static_cast<Index>(it - t.dofs.begin());
    t.dofs.push_back(dof);
    return static_cast<Index>(t.dofs.size() - 1);
  };
  if (p.ip_oop) t.pair.emplace(slot(p.ip_oop->first), slot(p.ip_oop->second));
  return t;
}

bool store_first_harmonics(TimeLevel& level, Index i, const Eigen::MatrixXd& coefficients, const TrackedDofs& tracked,
                           Index responses) {
  if (!coefficients.allFinite()) return false;
  Eigen::VectorXcd z(coefficients.rows());
  for (Index j = 0; j < z.size(); ++j) z[j] = std::complex<double>(coefficients(j, 1), -coefficients(j, 2));
  for (Index r = 0; r < responses; ++r) {
    level.amplitude(i, r) = std::abs(z[r]);
    level.phase(i, r) = std::arg(z[r]);
  }
  if (const auto& pair = tracked.pair) {
    level.components(i, 0) = std::abs(z[pair->first] + z[pair->second]) / 2;
    level.components(i, 1) = std::abs(z[pair->second] - z[pair->first]) / 2;
  }
  return true;
}

double peak_quantity_span(const timeint::SteadyState& s, const TrackedDofs& tracked, Index responses) {
  const Eigen::MatrixXcd& z = s.period_harmonics;
  if (z.rows() == 0 || z.cols() != static_cast<Index>(tracked.dofs.size())) return kNan;
  Eigen::MatrixXd amplitude;
  if (tracked.pair) {
    const Eigen::VectorXcd left = z.col(tracked.pair->first), right = z.col(tracked.pair->second);
    amplitude.resize(z.rows(), 2);
    amplitude.col(0) = (left + right).cwiseAbs() / 2;
    amplitude.col(1) = (right - left).cwiseAbs() / 2;
  } else {
    amplitude = z.leftCols(responses).cwiseAbs();
  }
  double span = 0.0;
  for (Index j = 0; j < amplitude.cols(); ++j) {
    const double top = amplitude.col(j).maxCoeff();
    if (top > 0.0) span = std::max(span, 1.0 - amplitude.col(j).minCoeff() / top);
  }
  return span;
}

bool marches(const TimeSpec& spec) {
  return spec.method == TimeSpec::Method::newmark || spec.period_map == TimeSpec::PeriodMap::newmark;
}

bool steady_first_harmonic(const TimeLevel& level, const TimeSpec& spec, Index i) {
  return marches(spec) && spec.envelope_tolerance > 0.0 && !level.steady[static_cast<size_t>(i)] &&
         level.envelope_span[static_cast<size_t>(i)] <= spec.envelope_tolerance;
}

}  // namespace bb
