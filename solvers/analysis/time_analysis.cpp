#include "analysis/time_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <mutex>

#include "analysis/time_sweeps.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "common/parallel_indices.hpp"
#include "common/progress_clock.hpp"
#include "common/seconds_since.hpp"
#include "frf/receptance.hpp"
#include "frf/sweep.hpp"
#include "friction/jenkins.hpp"
#include "timeint/newmark.hpp"
#include "timeint/shooting.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;

}  // namespace

TimeOutcome run_time(const Model& model, const TimeSpec& spec, const HbmProgress& progress,
                     const ModelCacheSettings* cache) {
  const auto t_start = Clock::now();
  TimeOutcome o;
  o.prepared = prepare_hbm(model, spec.system, cache);
  const PreparedHbm& p = o.prepared;
  if (spec.rigid_stick) try {
      timeint::validate_rigid_stick(p.model);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("'analysis.stick' = \"rigid\": {}", e.what()));
    }
  const TrackedDofs tracked = tracked_dofs(p);
  timeint::SteadyStateOptions options;
  options.dofs = tracked.dofs;
  options.steps_per_period = spec.steps_per_period;
  options.harmonics = spec.system.harmonics;
  options.tolerance = spec.steady_tolerance;
  options.max_cycles = spec.max_cycles;
  options.newmark.alpha = spec.alpha;
  const std::vector<double> frequencies =
      fixed_grid(spec.system.sweep.f_min, spec.system.sweep.f_max, spec.system.sweep.step_hz);
  const size_t n = spec.system.force_levels.size();
  ProgressClock clock(static_cast<int>(n));
  std::mutex report;  // the progress line and the clock, from every worker
  int done = 0;
  const HbmProgress timed = with_clock_locked(progress, clock, report);
  // Levels are independent (each marches from its own static state): on `threads` workers, the
  // results those of the serial run.
  o.levels.resize(n);
  for_each_index(n, worker_count(n, spec.system.threads), [&](size_t i) {
    o.levels[i] = sweep_level(p, spec, options, tracked, frequencies, spec.system.force_levels[i], timed);
    const std::lock_guard<std::mutex> lock(report);
    clock.finished(++done);
  });
  if (spec.history_hz)
    o.record = spec.method == TimeSpec::Method::shooting ? periodic_history(p, spec) : record_history(p, spec, options);
  o.seconds = seconds_since(t_start);
  add_sweep_tables(o, spec, frequencies, tracked.pair);
  add_history_tables(o, spec);
  return o;
}

}  // namespace bb
