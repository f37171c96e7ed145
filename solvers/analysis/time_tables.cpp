// The tables of a time analysis (analysis/time_analysis.hpp): frf, peaks, peaks_linear, peaks_hbm and
// time_cost from its levels, history and hysteresis loops from its recorded run.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "analysis/time_sweeps.hpp"
#include "common/constants.hpp"
#include "frf/sweep.hpp"

namespace bb {
namespace {

using Eigen::Index;

// The energy a contact's loop encloses over the recorded samples: sum of T du by the trapezoid rule.
double loop_work(const std::vector<timeint::ContactSample>& s) {
  double w = 0.0;
  for (size_t i = 1; i < s.size(); ++i) w += 0.5 * (s[i].tangential + s[i - 1].tangential) * (s[i].u - s[i - 1].u);
  return w;
}

// What the motion at frequency i of a stepped sine did where it reached no steady state.
std::string unsteady_motion(const TimeLevel& level, Index i, const std::string& response) {
  const int k = level.period_multiple[static_cast<size_t>(i)];
  if (k > 1) return fmt::format("it repeats every {} periods: a subharmonic response", k);
  return fmt::format(
      "it repeats within no {} periods: the first-harmonic amplitude of {} spans {:.4g} to {:.4g} m over the "
      "last {}, frf columns *_env_min_m and *_env_max_m",
      timeint::SteadyStateOptions{}.max_period_multiple, response, level.envelope_min(i, 0), level.envelope_max(i, 0),
      timeint::SteadyStateOptions{}.envelope_periods);
}

// The columns of the frf table, and (shooting) those also in each level's own table.
std::vector<std::string> frf_columns(const PreparedHbm& p, const TimeSpec& spec, bool pair,
                                     std::vector<std::string>& periodic_cols) {
  std::vector<std::string> frf_cols = {"point", "fe_n", "frequency_hz"};
  for (const std::string& r : p.response_names) frf_cols.push_back(r + "_amp_m");
  for (const std::string& r : p.response_names) frf_cols.push_back(r + "_phase_deg");
  if (pair) frf_cols.insert(frf_cols.end(), {"ip_component_m", "oop_component_m"});
  frf_cols.insert(frf_cols.end(), {"cycles", "steady"});
  const bool shooting = spec.method == TimeSpec::Method::shooting;
  if (marches(spec)) {  // what a frequency without a steady state (or periodic solution) did instead
    frf_cols.insert(frf_cols.end(), {"change", "period_multiple", "envelope_span"});
    for (const std::string& r : p.response_names) frf_cols.insert(frf_cols.end(), {r + "_env_min_m", r + "_env_max_m"});
  }
  if (shooting) {
    for (const std::string& r : p.response_names) periodic_cols.push_back(r + "_max_m");
    periodic_cols.insert(periodic_cols.end(), {"residual_m", "transitions"});
    if (spec.floquet) periodic_cols.insert(periodic_cols.end(), {"floquet_max", "stable"});
    frf_cols.insert(frf_cols.end(), periodic_cols.begin(), periodic_cols.end());
  }
  for (const std::string& r : p.response_names) frf_cols.push_back("linear_" + r + "_amp_m");
  if (spec.compare_harmonics > 0)
    for (const std::string& r : p.response_names) frf_cols.push_back("hbm_" + r + "_amp_m");
  return frf_cols;
}

// Why the peak of `kind` at grid point `at` (frequency f) of a level is not a result: a point
// it rests on or a neighbour has no steady state; empty when it stands. A peak of the integration
// is a result only where the grid point it rests on and both its neighbours reached the steady
// state: an amplitude still changing from period to period can look like a peak (or hide one) and
// would be checked as if it were the answer.
std::string unsteady_peak(const TimeLevel& level, const TimeSpec& spec, const std::string& kind, Index at, double f,
                          const std::string& response) {
  const std::vector<double>& frequencies = level.frequency_hz;
  const auto nf = static_cast<Index>(frequencies.size());
  for (Index i = std::max<Index>(at - 1, 0); i <= std::min<Index>(at + 1, nf - 1); ++i) {
    if (level.steady[static_cast<size_t>(i)] || steady_first_harmonic(level, spec, i)) continue;
    if (spec.method == TimeSpec::Method::shooting)
      return fmt::format("time analysis at Fe = {:g} N: the {} rests on {:.4f} Hz, where {}", level.force,
                         kind == "peak" ? "peak" : kind + " peak", frequencies[static_cast<size_t>(i)],
                         level.failure[static_cast<size_t>(i)]);
    return fmt::format(
        "time integration at Fe = {:g} N: the {} ({:.4f} Hz) rests on {:.4f} Hz, which did not reach "
        "the steady state within {} periods (cycle-to-cycle change {:.3g} > {:g}; {}); raise max_cycles or "
        "steady_tolerance, or refine steps_per_period",
        level.force, kind == "peak" ? std::string("peak") : (kind == "ip" ? "IP" : "OOP") + std::string(" peak"), f,
        frequencies[static_cast<size_t>(i)], spec.max_cycles, level.change[static_cast<size_t>(i)],
        spec.steady_tolerance, unsteady_motion(level, i, response));
  }
  return {};
}

// A level's row of time_cost.
std::vector<double> cost_row(const TimeLevel& level, size_t l, const TimeSpec& spec) {
  const auto nf = static_cast<Index>(level.frequency_hz.size());
  long not_steady = 0, by_envelope = 0;
  for (Index i = 0; i < nf; ++i) {
    not_steady += level.steady[static_cast<size_t>(i)] ? 0 : 1;
    by_envelope += steady_first_harmonic(level, spec, i) ? 1 : 0;
  }
  return {static_cast<double>(l + 1),
          level.force,
          static_cast<double>(nf),
          static_cast<double>(level.steps),
          static_cast<double>(level.newton_iterations),
          static_cast<double>(level.max_step_iterations),
          static_cast<double>(not_steady),
          static_cast<double>(by_envelope),
          level.seconds,
          1e6 * level.seconds / std::max<double>(1.0, static_cast<double>(level.steps))};
}

}  // namespace

void add_sweep_tables(TimeOutcome& o, const TimeSpec& spec, const std::vector<double>& frequencies,
                      const std::optional<std::pair<Index, Index>>& pair) {
  const PreparedHbm& p = o.prepared;
  const auto nf = static_cast<Index>(frequencies.size());
  const auto nr = static_cast<Index>(p.responses.size());
  const std::vector<std::string> kinds =
      pair ? std::vector<std::string>{"ip", "oop"} : std::vector<std::string>{"peak"};
  const bool shooting = spec.method == TimeSpec::Method::shooting, compare = spec.compare_harmonics > 0;
  std::vector<std::string> periodic_cols;  // shooting: also in one table per level, keyed 1..frequencies
  const std::vector<std::string> frf_cols = frf_columns(p, spec, pair.has_value(), periodic_cols);
  std::vector<std::vector<double>> frf_rows, peak_rows, linear_peak_rows, hbm_peak_rows, cost_rows;
  for (size_t l = 0; l < o.levels.size(); ++l) {
    const TimeLevel& level = o.levels[l];
    // HBM amplitudes at the grid frequencies (its converged points are the grid's).
    std::vector<Eigen::VectorXd> hbm_amp(static_cast<size_t>(nf), Eigen::VectorXd::Constant(nr, kNan));
    if (level.hbm)
      for (size_t k = 0; k < level.hbm->frequency_hz.size(); ++k)
        for (Index i = 0; i < nf; ++i)
          if (std::abs(level.hbm->frequency_hz[k] - frequencies[static_cast<size_t>(i)]) <
              1e-9 * frequencies[static_cast<size_t>(i)])
            hbm_amp[static_cast<size_t>(i)] = level.hbm->amplitude.row(static_cast<Index>(k)).transpose();
    std::vector<std::vector<double>> level_rows;
    for (Index i = 0; i < nf; ++i) {
      std::vector<double> row = {static_cast<double>((l + 1) * 100000 + static_cast<size_t>(i) + 1), level.force,
                                 frequencies[static_cast<size_t>(i)]};
      for (Index r = 0; r < nr; ++r) row.push_back(level.amplitude(i, r));
      for (Index r = 0; r < nr; ++r) row.push_back(level.phase(i, r) * kDegPerRad);
      if (pair) row.insert(row.end(), {level.components(i, 0), level.components(i, 1)});
      row.insert(row.end(), {static_cast<double>(level.cycles[static_cast<size_t>(i)]),
                             level.steady[static_cast<size_t>(i)] ? 1.0 : 0.0});
      if (marches(spec)) {
        row.insert(row.end(), {level.change[static_cast<size_t>(i)],
                               static_cast<double>(level.period_multiple[static_cast<size_t>(i)]),
                               level.envelope_span[static_cast<size_t>(i)]});
        for (Index r = 0; r < nr; ++r) row.insert(row.end(), {level.envelope_min(i, r), level.envelope_max(i, r)});
      }
      std::vector<double> periodic;
      if (shooting) {
        const auto f = static_cast<size_t>(i);
        for (Index r = 0; r < nr; ++r) periodic.push_back(level.largest(i, r));
        periodic.insert(periodic.end(), {level.residual[f], static_cast<double>(level.transitions[f])});
        if (spec.floquet)
          periodic.insert(periodic.end(),
                          {level.floquet_max[f],
                           std::isfinite(level.floquet_max[f]) ? (level.floquet_max[f] < 1.0 ? 1.0 : 0.0) : kNan});
        row.insert(row.end(), periodic.begin(), periodic.end());
        std::vector<double> own = {static_cast<double>(i + 1), frequencies[f]};
        for (Index r = 0; r < nr; ++r) own.push_back(level.amplitude(i, r));
        for (Index r = 0; r < nr; ++r) own.push_back(level.phase(i, r) * kDegPerRad);
        own.insert(own.end(), periodic.begin(), periodic.end());
        level_rows.push_back(own);
      }
      for (Index r = 0; r < nr; ++r) row.push_back(level.linear(i, r));
      if (compare)
        for (Index r = 0; r < nr; ++r) row.push_back(hbm_amp[static_cast<size_t>(i)][r]);
      frf_rows.push_back(row);
    }
    if (shooting) {
      std::vector<std::string> cols = {"point", "frequency_hz"};
      for (const std::string& r : p.response_names) cols.push_back(r + "_amp_m");
      for (const std::string& r : p.response_names) cols.push_back(r + "_phase_deg");
      cols.insert(cols.end(), periodic_cols.begin(), periodic_cols.end());
      const std::string name = fmt::format("frf_{:g}", level.force);
      o.tables.emplace(name, table_from_rows(name, cols, level_rows));
    }
    // Peaks on the grid (parabola through the largest point and its neighbours), the same way for
    // the time integration and the linear model, so that the two compare like for like. The first
    // reason a peak is not a result is the run's failure; its row then holds NaN for that peak.
    const auto require_steady = [&](size_t kind, Index at, double f) -> bool {
      std::string why = unsteady_peak(level, spec, kinds[kind], at, f, p.response_names.front());
      if (why.empty()) return true;
      if (o.failure.empty()) o.failure = std::move(why);
      return false;
    };
    const auto peaks_of = [&](const Eigen::MatrixXd& amplitude, const Eigen::MatrixXd& components, bool integrated) {
      std::vector<double> prow = {static_cast<double>(l + 1), level.force}, envelope;
      for (size_t k = 0; k < kinds.size(); ++k) {
        const Eigen::VectorXd values =
            pair ? Eigen::VectorXd(components.col(static_cast<Index>(k))) : Eigen::VectorXd(amplitude.col(0));
        const Peak sample_peak = largest_sample(frequencies, values);
        const double f = sample_peak.frequency_hz, v = sample_peak.amplitude;
        const Index right = pair ? pair->second : 0;
        Index at = 0;
        if (std::isfinite(f))
          at = static_cast<Index>(std::lround((f - frequencies.front()) / spec.system.sweep.step_hz));
        at = std::clamp<Index>(at, 0, nf - 1);
        const bool stands = !(integrated && spec.require_steady_peaks) || require_steady(k, at, f);
        // The right (or first) response: the parabola's value without ip_oop, else the nearest grid value.
        const double amp = !stands ? kNan : !pair ? v : right < nr ? amplitude(at, right) : v;
        prow.insert(prow.end(), {stands ? f : kNan, amp, amp / level.force});
        // Where the motion at the peak does not repeat: the range its first harmonic spans there.
        if (integrated && marches(spec)) {
          const bool open = stands && !level.steady[static_cast<size_t>(at)] && right < nr;
          envelope.insert(envelope.end(),
                          {open ? level.envelope_min(at, right) : kNan, open ? level.envelope_max(at, right) : kNan});
        }
      }
      prow.insert(prow.end(), envelope.begin(), envelope.end());
      return prow;
    };
    peak_rows.push_back(peaks_of(level.amplitude, level.components, true));
    linear_peak_rows.push_back(peaks_of(level.linear, level.linear_components, false));
    if (level.hbm) {
      std::vector<double> hrow = {static_cast<double>(l + 1), level.force};
      for (const HbmPeak& pk : level.hbm->peaks)
        hrow.insert(hrow.end(),
                    {pk.solution.converged ? pk.frequency_hz : kNan, pk.solution.converged ? pk.amplitude : kNan,
                     pk.solution.converged ? pk.amplitude / level.force : kNan});
      if (level.hbm->peaks.empty()) hrow.insert(hrow.end(), 3 * kinds.size(), kNan);
      hbm_peak_rows.push_back(hrow);
    }
    cost_rows.push_back(cost_row(level, l, spec));
  }
  o.tables.emplace("frf", table_from_rows("frf", frf_cols, frf_rows));
  std::vector<std::string> peak_cols = {"level", "fe_n"};
  for (const std::string& k : kinds)
    for (const char* c : {"_hz", "_amp_m", "_amp_per_n"}) peak_cols.push_back(k + c);
  std::vector<std::string> time_peak_cols = peak_cols;
  if (marches(spec))
    for (const std::string& k : kinds)
      time_peak_cols.insert(time_peak_cols.end(), {k + "_env_min_m", k + "_env_max_m"});
  o.tables.emplace("peaks", table_from_rows("peaks", time_peak_cols, peak_rows));
  o.tables.emplace("peaks_linear", table_from_rows("peaks_linear", peak_cols, linear_peak_rows));
  if (compare) o.tables.emplace("peaks_hbm", table_from_rows("peaks_hbm", peak_cols, hbm_peak_rows));
  o.tables.emplace("time_cost",
                   table_from_rows("time_cost",
                                   {"level", "fe_n", "frequencies", "steps", "newton_iterations", "max_step_iterations",
                                    "not_steady", "steady_first_harmonic", "seconds", "us_per_step"},
                                   cost_rows));
}

// The tables of the recorded history: history, one hysteresis loop per contact, hysteresis_summary.
void add_history_tables(TimeOutcome& o, const TimeSpec& spec) {
  const PreparedHbm& p = o.prepared;
  const auto nr = static_cast<Index>(p.responses.size());
  if (o.record && o.record->history.steps > 0) {
    const TimeHistoryRecord& rec = *o.record;
    const timeint::TimeHistory& h = rec.history;
    std::vector<std::vector<double>> rows;
    std::vector<std::string> cols = {"instant", "time_s"};
    for (const std::string& r : p.response_names) cols.push_back(r + "_m");
    for (size_t i = 0; i < h.time.size(); ++i) {
      std::vector<double> row = {static_cast<double>(i + 1), h.time[i]};
      for (Index r = 0; r < nr; ++r) row.push_back(h.displacement(static_cast<Index>(i), r));
      rows.push_back(row);
    }
    o.tables.emplace("history", table_from_rows("history", cols, rows));
    std::vector<std::vector<double>> summary;
    for (size_t c = 0; c < h.contacts.size(); ++c) {
      const std::vector<timeint::ContactSample>& s = h.contacts[c];
      std::vector<std::vector<double>> loop;
      std::vector<std::string> states;
      double stick = 0, slip = 0, open = 0, coulomb = 0, open_force = 0;
      double su = 0, st = 0, suu = 0, sut = 0, n_stick = 0;
      const double mu = p.model.contacts[c].point.mu, kt = p.model.contacts[c].point.kt;
      for (size_t i = 0; i < s.size(); ++i) {
        loop.push_back({static_cast<double>(i + 1), h.time[i], s[i].u, s[i].tangential, s[i].normal, s[i].slider});
        states.emplace_back(friction::state_name(s[i].state));
        if (i == 0) continue;  // the start instant repeats the previous period's end
        switch (s[i].state) {
          case friction::ContactState::stick:
            ++stick;
            su += s[i].u, st += s[i].tangential, suu += s[i].u * s[i].u, sut += s[i].u * s[i].tangential, ++n_stick;
            break;
          case friction::ContactState::lift_off:
            ++open;
            open_force = std::max({open_force, std::abs(s[i].tangential), s[i].normal});
            break;
          default:
            ++slip;
            break;
        }
        if (s[i].normal > 0 && mu > 0) coulomb = std::max(coulomb, std::abs(s[i].tangential) / (mu * s[i].normal));
      }
      const double n = std::max(1.0, stick + slip + open);
      const double var = suu - su * su / std::max(1.0, n_stick);
      // Slope of T against u over the stuck samples: kt when the loop is a line (needs u to vary).
      const double slope = n_stick >= 2 && var > 1e-30 ? (sut - su * st / n_stick) / var : kNan;
      const std::string name = "hysteresis_" + p.contact_names[c];
      ResultTable t = table_from_rows(
          name, {"instant", "time_s", "relative_tangential_m", "tangential_force_n", "normal_force_n", "slider_m"},
          loop);
      t.add_text_column("state", states);
      o.tables.emplace(name, std::move(t));
      double nmin = std::numeric_limits<double>::infinity(), nmax = 0, nmean = 0;
      for (size_t i = 1; i < s.size(); ++i)
        nmin = std::min(nmin, s[i].normal), nmax = std::max(nmax, s[i].normal), nmean += s[i].normal / (n);
      summary.push_back({static_cast<double>(c + 1), stick / n, slip / n, open / n, slope, slope / kt, coulomb,
                         open_force, loop_work(s) / spec.history_cycles, nmin, nmean, nmax});
    }
    ResultTable t = table_from_rows(
        "hysteresis_summary",
        {"contact", "stick", "slip", "lift_off", "stick_slope_n_per_m", "stick_slope_over_kt", "max_t_over_mu_n",
         "max_force_when_open_n", "loop_work_per_cycle_j", "min_normal_n", "mean_normal_n", "max_normal_n"},
        summary);
    t.add_text_column("name", p.contact_names);
    o.tables.emplace("hysteresis_summary", std::move(t));
  }
}

}  // namespace bb
