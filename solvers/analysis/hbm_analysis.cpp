#include "analysis/hbm_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <optional>

#include "analysis/hbm_stepped_sines.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "forced/hbm_levels.hpp"
#include "forced/hbm_nonlinear_modes.hpp"
#include "forced/hbm_response.hpp"
#include "forced/stuck_limit.hpp"
#include "frf/receptance.hpp"
#include "frf/sweep.hpp"
#include "friction/state_fractions.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;

// Energy the contact dissipates per cycle: T against u along each tangential direction, u's
// coefficients from its samples (exact: u holds H harmonics and the AFT takes at least 2H + 1 samples).
double friction_work(const friction::AftResult& a) {
  const Eigen::Index m = a.normal.size();
  const Eigen::MatrixXd analysis = friction::analysis_matrix(friction::harmonics_of(m), static_cast<int>(a.u.size()));
  double work = friction::cycle_work(a.tangential.head(m), analysis * a.u);
  if (a.u_2.size() > 0) work += friction::cycle_work(a.tangential.tail(m), analysis * a.u_2);
  return work;
}

// A level whose sweep found no solution, or a peak whose refinement failed, is a failed run: a
// peak is never reported at a failed solve.
void require_solutions(const HbmOutcome& o) {
  for (const HbmLevel& level : o.levels) {
    if (level.path.points.empty())
      throw SolverError(
          fmt::format("harmonic balance at Fe = {:g} N found no solution: {}", level.force, level.path.failure));
    for (const HbmPeak& pk : level.peaks)
      if (!pk.solution.converged)
        throw SolverError(fmt::format(
            "harmonic balance at Fe = {:g} N: the {} peak's solve did not converge ({}); no peak is reported",
            level.force, pk.kind, pk.solution.failure));
  }
}

std::vector<std::string> peak_kinds(const PreparedHbm& p) {
  return p.ip_oop ? std::vector<std::string>{"ip", "oop"} : std::vector<std::string>{"peak"};
}

// The peaks' log-sensitivities (columns <kind>_hz / _amp_m / _amp_per_n _dlog_<parameter>), NaN
// where a peak has none.
void add_peak_sensitivity_row(const PreparedHbm& p, const HbmSpec& spec, const HbmLevel& level,
                              std::vector<double>& row) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> none;
  for (size_t k = 0; k < peak_kinds(p).size(); ++k) {
    const bool has = k < level.peaks.size();
    const std::vector<double>& frequency = has ? level.peaks[k].frequency_hz_dlog : none;
    const std::vector<double>& amplitude = has ? level.peaks[k].amplitude_dlog : none;
    const std::pair<const std::vector<double>*, double> columns[] = {
        {&frequency, 1.0}, {&amplitude, 1.0}, {&amplitude, 1.0 / level.force}};  // _hz, _amp_m, _amp_per_n
    for (const auto& [d, scale] : columns)
      for (size_t j = 0; j < spec.sensitivities.size(); ++j) row.push_back(j < d->size() ? (*d)[j] * scale : nan);
  }
}

// peaks, energy_balance, contact_states and sweep_cost: one row per level, peak or contact.
void add_peak_tables(HbmOutcome& o, const HbmSpec& spec) {
  const PreparedHbm& p = o.prepared;
  const double cf = spec.damper ? spec.damper->centrifugal_force : 0.0;
  // peaks, energy balance, contact states, cost
  std::vector<std::vector<double>> peak_rows, energy_rows, state_rows, cost_rows;
  std::vector<std::string> state_contacts, state_peaks;
  for (size_t l = 0; l < o.levels.size(); ++l) {
    const HbmLevel& level = o.levels[l];
    const double key = static_cast<double>(l + 1);
    std::vector<double> row = {key, level.force};
    if (spec.damper) row.push_back(cf / level.force);
    if (level.peaks.empty()) row.insert(row.end(), p.ip_oop ? 6 : 3, std::numeric_limits<double>::quiet_NaN());
    for (const HbmPeak& pk : level.peaks) {
      const bool ok = pk.solution.converged;
      const double nan = std::numeric_limits<double>::quiet_NaN();
      row.insert(row.end(),
                 {ok ? pk.frequency_hz : nan, ok ? pk.amplitude : nan, ok ? pk.amplitude / level.force : nan});
      if (!ok) continue;
      const hbm::CycleEnergy& e = pk.energy;
      const size_t k = static_cast<size_t>(&pk - level.peaks.data());
      energy_rows.push_back(
          {key * 10 + static_cast<double>(k + 1), level.force, pk.frequency_hz, e.excitation, e.viscous, e.friction,
           e.normal,
           std::abs(e.excitation - e.viscous - e.friction - e.normal) / std::max(std::abs(e.excitation), 1e-300)});
      for (size_t c = 0; c < pk.solution.contacts.size(); ++c) {
        const friction::AftResult& a = pk.solution.contacts[c];
        const friction::StateFractions f = friction::state_fractions(a.state);
        state_rows.push_back({key * 1000 + static_cast<double>(k + 1) * 100 + static_cast<double>(c + 1), level.force,
                              pk.frequency_hz, f.stick, f.slip, f.lift_off, a.normal[0], a.n.minCoeff(), a.n.maxCoeff(),
                              friction_work(a)});
        state_contacts.push_back(p.contact_names[c]);
        state_peaks.push_back(pk.kind);
      }
    }
    row.push_back(level.path.converged ? 1.0 : 0.0);
    for (const HbmPeak& pk : level.peaks) row.push_back(pk.trusted ? 1.0 : 0.0);
    for (const HbmPeak& pk : level.peaks) row.push_back(pk.sampling_error);
    for (const HbmPeak& pk : level.peaks) row.push_back(pk.truncation.largest());
    row.push_back(static_cast<double>(level.harmonics));
    if (spec.stability != HbmSpec::Stability::none) {
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      for (const HbmPeak& pk : level.peaks) row.push_back(pk.stability ? pk.stability->verdict() : nan);
      for (const HbmPeak& pk : level.peaks)
        row.push_back(pk.stability && pk.stability->ok ? pk.stability->max_real : nan);
    }
    add_peak_sensitivity_row(p, spec, level, row);
    peak_rows.push_back(row);
    cost_rows.push_back({key, level.force, static_cast<double>(level.path.points.size()),
                         static_cast<double>(level.path.corrector_iterations),
                         static_cast<double>(level.path.rejected_steps), static_cast<double>(level.path.turning_points),
                         static_cast<double>(level.path.jumps), static_cast<double>(level.path.corners),
                         level.path.converged ? 1.0 : 0.0, static_cast<double>(level.samples),
                         static_cast<double>(level.harmonics), level.seconds});
  }
  std::vector<std::string> peak_columns = {"level", "fe_n"};
  if (spec.damper) peak_columns.push_back("cf_over_fe");
  const std::vector<std::string> kinds = peak_kinds(p);
  for (const std::string& k : kinds)
    for (const char* s : {"_hz", "_amp_m", "_amp_per_n"}) peak_columns.push_back(k + s);
  peak_columns.push_back("reached_end");
  for (const std::string& k : kinds) peak_columns.push_back(k + "_trusted");
  for (const std::string& k : kinds) peak_columns.push_back(k + "_aft_error");
  for (const std::string& k : kinds) peak_columns.push_back(k + "_harmonic_share");
  peak_columns.push_back("harmonics");
  if (spec.stability != HbmSpec::Stability::none) {
    for (const std::string& k : kinds) peak_columns.push_back(k + "_stable");
    for (const std::string& k : kinds) peak_columns.push_back(k + "_floquet_max_re");
  }
  for (const std::string& k : kinds)
    for (const char* q : {"_hz_dlog_", "_amp_m_dlog_", "_amp_per_n_dlog_"})
      for (const HbmParameter& parameter : spec.sensitivities) peak_columns.push_back(k + q + parameter.label);
  o.tables.emplace("peaks", table_from_rows("peaks", peak_columns, peak_rows));
  o.tables.emplace("energy_balance", table_from_rows("energy_balance",
                                                     {"peak", "fe_n", "frequency_hz", "excitation_j", "viscous_j",
                                                      "friction_j", "normal_j", "relative_error"},
                                                     energy_rows));
  ResultTable states = table_from_rows("contact_states",
                                       {"key", "fe_n", "frequency_hz", "stick", "slip", "lift_off", "mean_normal_n",
                                        "min_normal_n", "max_normal_n", "friction_work_j"},
                                       state_rows);
  states.add_text_column("peak", state_peaks);
  states.add_text_column("contact", state_contacts);
  o.tables.emplace("contact_states", std::move(states));
  o.tables.emplace("sweep_cost", table_from_rows("sweep_cost",
                                                 {"level", "fe_n", "points", "corrector_iterations", "rejected_steps",
                                                  "turning_points", "jumps", "corners", "reached_end", "samples",
                                                  "harmonics", "seconds"},
                                                 cost_rows));
}

// aft_sampling: with aft_tolerance, every sweep each level took on the way to its samples.
void add_sampling_table(HbmOutcome& o) {
  std::vector<std::vector<double>> rows;
  for (size_t l = 0; l < o.levels.size(); ++l) {
    const auto& trials = o.levels[l].sampling_trials;
    for (size_t t = 0; t < trials.size(); ++t)
      rows.push_back({static_cast<double>(rows.size() + 1), static_cast<double>(l + 1), o.levels[l].force,
                      static_cast<double>(trials[t].samples), trials[t].aft_error, trials[t].reached_end ? 1.0 : 0.0,
                      trials[t].trusted ? 1.0 : 0.0, trials[t].seconds, t + 1 == trials.size() ? 1.0 : 0.0});
  }
  if (rows.empty()) return;
  o.tables.emplace("aft_sampling", table_from_rows("aft_sampling",
                                                   {"trial", "level", "fe_n", "samples", "aft_error", "reached_end",
                                                    "trusted", "seconds", "chosen"},
                                                   rows));
}

// harmonic_selection: with harmonic_tolerance, every H each level tried on the way to its choice.
void add_harmonic_table(HbmOutcome& o) {
  std::vector<std::vector<double>> rows;
  for (size_t l = 0; l < o.levels.size(); ++l)
    for (const HbmLevel::HarmonicTrial& t : o.levels[l].harmonic_trials)
      rows.push_back({static_cast<double>(rows.size() + 1), static_cast<double>(l + 1), o.levels[l].force,
                      static_cast<double>(t.harmonics), static_cast<double>(t.samples), t.share, t.change,
                      t.estimated_error, t.reached_end ? 1.0 : 0.0, t.trusted ? 1.0 : 0.0, t.seconds,
                      t.chosen ? 1.0 : 0.0, t.window_hz, t.band_change});
  if (rows.empty()) return;
  o.tables.emplace("harmonic_selection", table_from_rows("harmonic_selection",
                                                         {"trial", "level", "fe_n", "harmonics", "samples",
                                                          "harmonic_share", "change", "estimated_error", "reached_end",
                                                          "trusted", "seconds", "chosen", "window_hz", "band_change"},
                                                         rows));
}

// harmonics_per_point: with the point scope, how many path points of each level were solved at
// each H, and how many of them kept it without two H agreeing.
void add_point_harmonics_table(HbmOutcome& o, const HbmSpec& spec) {
  std::vector<std::vector<double>> rows;
  for (size_t l = 0; l < o.levels.size(); ++l) {
    const HbmLevel& level = o.levels[l];
    std::map<int, std::pair<int, int>> by_h;  // H -> (points, unmet)
    for (size_t i = 0; i < level.point_harmonics.size(); ++i) {
      auto& [points, unmet] = by_h[level.point_harmonics[i]];
      ++points;
      if (!(level.point_change[i] <= spec.harmonic_tolerance)) ++unmet;
    }
    for (const auto& [h, n] : by_h)
      rows.push_back({static_cast<double>(l + 1), level.force, static_cast<double>(h), static_cast<double>(n.first),
                      static_cast<double>(n.second)});
  }
  if (rows.empty()) return;
  o.tables.emplace("harmonics_per_point",
                   table_from_rows("harmonics_per_point", {"level", "fe_n", "harmonics", "points", "unmet"}, rows));
}

// turning_points and coexisting_solutions: where an arclength path folds back in frequency, and the
// frequency bands between its turning points in which it holds several solutions at once (counted
// as the path segments crossing the band's middle; with stability on the path, the stable ones).
void add_fold_tables(HbmOutcome& o) {
  std::vector<std::vector<double>> turns, bands;
  for (size_t l = 0; l < o.levels.size(); ++l) {
    const HbmLevel& level = o.levels[l];
    const auto& pts = level.path.points;
    std::vector<double> breaks;
    for (size_t i = 1; i < pts.size(); ++i)
      if ((pts[i].tangent_omega > 0) != (pts[i - 1].tangent_omega > 0)) {
        turns.push_back({static_cast<double>(turns.size() + 1), static_cast<double>(l + 1), level.force,
                         level.frequency_hz[i], level.amplitude(static_cast<Index>(i), 0),
                         pts[i].tangent_omega > 0 ? 1.0 : -1.0});
        breaks.push_back(level.frequency_hz[i]);
      }
    if (breaks.empty()) continue;
    std::sort(breaks.begin(), breaks.end());
    for (size_t b = 0; b + 1 < breaks.size(); ++b) {
      const double mid = 0.5 * (breaks[b] + breaks[b + 1]);
      int crossing = 0, stable = 0;
      for (size_t i = 1; i < pts.size(); ++i) {
        const double f0 = level.frequency_hz[i - 1], f1 = level.frequency_hz[i];
        if ((f0 - mid) * (f1 - mid) > 0) continue;
        ++crossing;
        if (!level.stable.empty() && level.stable[i - 1] == 1.0 && level.stable[i] == 1.0) ++stable;
      }
      if (crossing >= 2)
        bands.push_back(
            {static_cast<double>(bands.size() + 1), static_cast<double>(l + 1), level.force, breaks[b], breaks[b + 1],
             static_cast<double>(crossing),
             level.stable.empty() ? std::numeric_limits<double>::quiet_NaN() : static_cast<double>(stable)});
    }
  }
  if (turns.empty()) return;
  o.tables.emplace("turning_points",
                   table_from_rows("turning_points",
                                   {"turn", "level", "fe_n", "frequency_hz", "amplitude_m", "direction_after"}, turns));
  if (!bands.empty())
    o.tables.emplace(
        "coexisting_solutions",
        table_from_rows("coexisting_solutions",
                        {"band", "level", "fe_n", "from_hz", "to_hz", "solutions", "stable_solutions"}, bands));
}

// frf_<Fe>: the path points of each level in order.
void add_frf_tables(HbmOutcome& o, const HbmSpec& spec) {
  const PreparedHbm& p = o.prepared;
  for (const HbmLevel& level : o.levels) {
    std::vector<std::string> cols = {"point", "frequency_hz"};
    for (const std::string& r : p.response_names) cols.push_back(r + "_amp_m");
    for (const std::string& r : p.response_names) cols.push_back(r + "_phase_deg");
    for (const std::string& r : p.response_names) cols.push_back(r + "_max_m");
    if (p.ip_oop) cols.insert(cols.end(), {"ip_component_m", "oop_component_m"});
    cols.insert(cols.end(), {"residual_n", "iterations"});
    if (!level.stable.empty()) cols.insert(cols.end(), {"stable", "floquet_max_re"});
    if (!level.harmonic_share.empty()) cols.push_back("harmonic_share");
    if (!level.point_harmonics.empty()) cols.insert(cols.end(), {"harmonics", "harmonic_change"});
    for (size_t j = 0; j < level.amplitude_dlog.size(); ++j)
      for (const char* q : {"_amp_m_dlog_", "_phase_deg_dlog_"})
        for (const std::string& r : p.response_names) cols.push_back(r + q + spec.sensitivities[j].label);
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < level.path.points.size(); ++i) {
      std::vector<double> row = {static_cast<double>(i + 1), level.frequency_hz[i]};
      for (Index r = 0; r < level.amplitude.cols(); ++r) row.push_back(level.amplitude(static_cast<Index>(i), r));
      for (Index r = 0; r < level.phase_deg.cols(); ++r) row.push_back(level.phase_deg(static_cast<Index>(i), r));
      for (Index r = 0; r < level.excursion.cols(); ++r) row.push_back(level.excursion(static_cast<Index>(i), r));
      if (p.ip_oop)
        row.insert(row.end(), {level.components(static_cast<Index>(i), 0), level.components(static_cast<Index>(i), 1)});
      row.insert(row.end(), {level.path.points[i].residual, static_cast<double>(level.path.points[i].iterations)});
      if (!level.stable.empty()) row.insert(row.end(), {level.stable[i], level.floquet_max_real[i]});
      if (!level.harmonic_share.empty()) row.push_back(level.harmonic_share[i]);
      if (!level.point_harmonics.empty())
        row.insert(row.end(), {static_cast<double>(level.point_harmonics[i]), level.point_change[i]});
      for (size_t j = 0; j < level.amplitude_dlog.size(); ++j)
        for (const Eigen::MatrixXd* d : {&level.amplitude_dlog[j], &level.phase_dlog_deg[j]})
          for (Index r = 0; r < d->cols(); ++r) row.push_back((*d)(static_cast<Index>(i), r));
      rows.push_back(row);
    }
    const std::string name = hbm_frf_table_name(level.force);
    o.tables.emplace(name, table_from_rows(name, cols, rows));
  }
}

// limits, limit_peaks and stuck_limit_deviation: the response per newton of the first force of the
// linear model alone (no damper or contacts) and with every contact stuck (kn on the normal, kt on
// the tangential direction, eq 3.51), their peaks, and each level's distance from the stuck one.
void add_limit_tables(HbmOutcome& o, const HbmSpec& spec) {
  const PreparedHbm& p = o.prepared;
  const std::vector<std::string> kinds = peak_kinds(p);
  const friction::FrictionModel& m = p.model;
  const Index nb = p.blade_dofs;
  // Limit 0: the linear model alone (the damper's DOFs left out); 1: every contact stuck.
  const auto limit_solve = [&](int l, double w) -> Eigen::VectorXcd {
    if (l == 1) return stuck_response(m, w);
    if (!m.nodal_diameters.empty()) {  // a cyclic sector: harmonic 1's nodal diameter
      const friction::NodalDiameterOperators& k1 = m.nodal_diameters.of_harmonic(1);
      const Eigen::MatrixXcd d = k1.stiffness + std::complex<double>(0.0, w) * k1.damping - w * w * k1.mass;
      return d.topLeftCorner(nb, nb).partialPivLu().solve(m.harmonic_load.head(nb));
    }
    return direct_response(m.stiffness.topLeftCorner(nb, nb), m.damping.topLeftCorner(nb, nb),
                           m.mass.topLeftCorner(nb, nb), w, m.harmonic_load.head(nb));
  };
  const int n_grid = 2001;
  o.limit_frequency_hz = Eigen::VectorXd::LinSpaced(n_grid, spec.sweep.f_min, spec.sweep.f_max);
  const Index nr = static_cast<Index>(p.responses.size()) + (p.ip_oop ? 2 : 0);
  o.free_response.resize(n_grid, nr);
  o.stuck_response.resize(n_grid, nr);
  auto outputs = [&](const Eigen::VectorXcd& z, Eigen::MatrixXd& into, Index i) {
    for (size_t r = 0; r < p.responses.size(); ++r)
      into(i, static_cast<Index>(r)) = p.responses[r] < z.size() ? std::abs(z[p.responses[r]]) : 0.0;
    if (p.ip_oop)
      for (int k = 0; k < 2; ++k) into(i, static_cast<Index>(p.responses.size()) + k) = peak_values(p, z, k).component;
  };
  for (Index i = 0; i < n_grid; ++i) {
    const double w = kTwoPi * o.limit_frequency_hz[i];
    outputs(limit_solve(0, w), o.free_response, i);
    outputs(limit_solve(1, w), o.stuck_response, i);
  }
  std::vector<std::string> cols = {"point", "frequency_hz"};
  for (const char* limit : {"free", "stuck"}) {
    for (const std::string& r : p.response_names) cols.push_back(fmt::format("{}_{}_amp_per_n", limit, r));
    if (p.ip_oop) cols.insert(cols.end(), {fmt::format("{}_ip_per_n", limit), fmt::format("{}_oop_per_n", limit)});
  }
  std::vector<std::vector<double>> rows;
  for (Index i = 0; i < n_grid; ++i) {
    std::vector<double> row = {static_cast<double>(i + 1), o.limit_frequency_hz[i]};
    for (const Eigen::MatrixXd* lim : {&o.free_response, &o.stuck_response})
      for (Index r = 0; r < nr; ++r) row.push_back((*lim)(i, r));
    rows.push_back(row);
  }
  o.tables.emplace("limits", table_from_rows("limits", cols, rows));
  // Peaks of the limits, in the columns of `peaks`: the grid's largest point, then golden-section
  // search on the linear solve between its neighbours.
  std::vector<std::vector<double>> peak_limit_rows;
  for (int l = 0; l < 2; ++l) {
    const Eigen::MatrixXd& lim = l == 0 ? o.free_response : o.stuck_response;
    std::vector<double> row = {static_cast<double>(l + 1)};
    for (int k = 0; k < (p.ip_oop ? 2 : 1); ++k) {
      const Index col = p.ip_oop ? static_cast<Index>(p.responses.size()) + k : 0;
      const auto value = [&](double f) {
        const Eigen::VectorXcd z = limit_solve(l, kTwoPi * f);
        if (p.ip_oop && std::max(p.ip_oop->first, p.ip_oop->second) >= z.size()) return PeakValues{};
        if (!p.ip_oop && p.responses.front() >= z.size()) return PeakValues{};
        return peak_values(p, z, k);
      };
      Index i = 0;
      lim.col(col).maxCoeff(&i);
      const double lo = o.limit_frequency_hz[std::max<Index>(i - 1, 0)],
                   hi = o.limit_frequency_hz[std::min<Index>(i + 1, n_grid - 1)];
      const GoldenSearch search = golden_section_maximum(
          [&](double f) { return std::optional<double>(value(f).component); }, lo, hi, 60, 1e-12);
      const double a = search.a, b = search.b;
      const double f = 0.5 * (a + b);
      row.insert(row.end(), {f, value(f).amplitude});
    }
    peak_limit_rows.push_back(row);
  }
  std::vector<std::string> lcols = {"limit"};
  for (const std::string& k : kinds) lcols.insert(lcols.end(), {k + "_hz", k + "_amp_per_n"});
  ResultTable t = table_from_rows("limit_peaks", lcols, peak_limit_rows);
  t.add_text_column("model", {"free (no contacts)", "stuck (contacts as springs kn, kt)"});
  // Distance of each level's peaks from the stuck limit: zero as Fe -> 0 (eq 3.51).
  std::vector<std::vector<double>> dev_rows;
  std::vector<std::string> dev_cols = {"level", "fe_n"};
  for (const std::string& k : kinds) dev_cols.insert(dev_cols.end(), {k + "_hz", k + "_amp_per_n"});
  for (size_t l = 0; l < o.levels.size(); ++l) {
    std::vector<double> row = {static_cast<double>(l + 1), o.levels[l].force};
    for (size_t k = 0; k < kinds.size(); ++k) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const bool ok = k < o.levels[l].peaks.size() && o.levels[l].peaks[k].solution.converged;
      const HbmPeak* pk = ok ? &o.levels[l].peaks[k] : nullptr;
      const double f = peak_limit_rows[1][1 + 2 * k], a = peak_limit_rows[1][2 + 2 * k];
      row.push_back(pk ? pk->frequency_hz / f - 1 : nan);
      row.push_back(pk ? pk->amplitude / o.levels[l].force / a - 1 : nan);
    }
    dev_rows.push_back(row);
  }
  o.tables.emplace("limit_peaks", std::move(t));
  o.tables.emplace("stuck_limit_deviation", table_from_rows("stuck_limit_deviation", dev_cols, dev_rows));
}

// damper_static: the normal preloads of the static pre-solve.
void add_damper_table(HbmOutcome& o) {
  const PreparedHbm& p = o.prepared;
  if (p.damper_static) {
    const damper::DamperStaticState& s = *p.damper_static;
    std::vector<std::vector<double>> rows;
    for (size_t c = 0; c < p.damper->contacts.size(); ++c)
      rows.push_back({static_cast<double>(c + 1), s.normal_preload[static_cast<Index>(c)],
                      s.normal_displacement[static_cast<Index>(c)], s.open[c] ? 1.0 : 0.0});
    ResultTable t =
        table_from_rows("damper_static", {"contact", "normal_preload_n", "normal_displacement_m", "open"}, rows);
    std::vector<std::string> names;
    for (const auto& c : p.damper->contacts) names.push_back(c.name);
    t.add_text_column("name", names);
    o.tables.emplace("damper_static", std::move(t));
  }
}

}  // namespace

HbmOutcome run_hbm(const Model& model, const HbmSpec& spec, const HbmProgress& progress,
                   const ModelCacheSettings* cache) {
  HbmOutcome o;
  o.prepared = prepare_hbm(model, spec, cache);
  const auto t0 = Clock::now();
  o.levels = sweep_levels(o.prepared, spec, progress);
  o.sweep_seconds = seconds_since(t0);
  require_solutions(o);
  add_peak_tables(o, spec);
  add_sampling_table(o);
  add_harmonic_table(o);
  add_point_harmonics_table(o, spec);
  add_fold_tables(o);
  add_frf_tables(o, spec);
  add_limit_tables(o, spec);
  add_damper_table(o);
  HbmNonlinearModes modes = trace_nonlinear_modes(o.prepared, o.levels, spec);
  o.nonlinear_modes = std::move(modes.branches);
  o.nonlinear_mode_seconds = modes.seconds;
  o.tables.merge(modes.tables);
  run_stepped_sines(o.prepared, spec, progress, o.stepped_sines, o.response_controls, o.tables);
  return o;
}

}  // namespace bb
