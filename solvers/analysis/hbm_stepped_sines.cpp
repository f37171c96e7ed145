#include "analysis/hbm_stepped_sines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "common/errors.hpp"
#include "common/parallel_indices.hpp"

namespace bb {
namespace {

// Each stepped sine (force- or response-controlled) on the analysis's threads; one that converges at
// no frequency fails the run, as a level without a solution does.
template <class Out, class Spec, class Run>
std::vector<Out> run_stepped(const std::vector<Spec>& specs, int threads, const char* what, const Run& run) {
  std::vector<Out> out(specs.size());
  for_each_index(specs.size(), worker_count(specs.size(), threads), [&](size_t i) { out[i] = run(specs[i]); });
  for (const Out& s : out)
    if (s.frequency_hz.empty())
      throw SolverError(fmt::format("{} '{}' converged at no frequency; at {:.6g} Hz: {}", what, s.name,
                                    s.failed_hz.front(), s.failures.front()));
  return out;
}

// frf_<name> from its converged rows (point first, 1-based) and its failed points, each a row of
// NaN where the solution would be, in the order stepped, with the reasons as a text column
// "failure" when any failed: a frequency without a solution stays in the table, and a fit cannot
// interpolate over it (issue 68). `force`: the spec's force per point, empty when unknown.
ResultTable stepped_table(const std::string& name, const std::vector<std::string>& cols,
                          std::vector<std::vector<double>> rows, const std::vector<double>& spec_hz,
                          const std::vector<double>& force, const std::vector<double>& failed_hz,
                          const std::vector<std::string>& failures) {
  std::vector<std::string> reasons(rows.size());
  std::vector<bool> used(spec_hz.size(), false);
  for (const std::vector<double>& r : rows)
    if (const auto i = static_cast<size_t>(r[0]) - 1; i < used.size()) used[i] = true;
  for (size_t j = 0; j < failed_hz.size(); ++j) {
    size_t i = 0;
    while (i < spec_hz.size() && (used[i] || spec_hz[i] != failed_hz[j])) ++i;
    if (i == spec_hz.size()) continue;  // not a point of the spec: nothing to place
    used[i] = true;
    std::vector<double> row(cols.size(), NAN);
    row[0] = static_cast<double>(i + 1);
    row[1] = spec_hz[i];
    if (!force.empty()) row[2] = force[i];
    rows.push_back(std::move(row));
    reasons.push_back(failures[j]);
  }
  std::vector<size_t> order(rows.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return rows[a][0] < rows[b][0]; });
  std::vector<std::vector<double>> sorted;
  std::vector<std::string> sorted_reasons;
  for (size_t k : order) {
    sorted.push_back(std::move(rows[k]));
    sorted_reasons.push_back(std::move(reasons[k]));
  }
  ResultTable t = table_from_rows(name, cols, sorted);
  if (!failed_hz.empty()) t.add_text_column("failure", std::move(sorted_reasons));
  return t;
}

template <class Spec>
const Spec* named(const std::vector<Spec>& specs, const std::string& name) {
  for (const Spec& s : specs)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace

void add_stepped_sine_tables(const PreparedHbm& p, const HbmSpec& spec, const std::vector<HbmSteppedSine>& sines,
                             ResultTables& tables) {
  if (sines.empty()) return;
  using Eigen::Index;
  std::vector<std::vector<double>> cost_rows;
  std::vector<std::string> names, first_failures;
  for (size_t k = 0; k < sines.size(); ++k) {
    const HbmSteppedSine& s = sines[k];
    std::vector<std::string> cols = {"point", "frequency_hz", "force_n"};
    for (const char* q : {"_amp_m", "_phase_deg", "_max_m"})
      for (const std::string& r : p.response_names) cols.push_back(r + q);
    cols.insert(cols.end(), {"residual_n", "iterations"});
    for (size_t j = 0; j < s.amplitude_dlog.size(); ++j)
      for (const char* q : {"_amp_m_dlog_", "_phase_deg_dlog_"})
        for (const std::string& r : p.response_names) cols.push_back(r + q + spec.sensitivities[j].label);
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < s.frequency_hz.size(); ++i) {
      const Index row = static_cast<Index>(i);
      std::vector<double> values = {static_cast<double>(s.point[i] + 1), s.frequency_hz[i], s.force[i]};
      for (const Eigen::MatrixXd* m : {&s.amplitude, &s.phase_deg, &s.excursion})
        for (Index r = 0; r < m->cols(); ++r) values.push_back((*m)(row, r));
      values.insert(values.end(), {s.residual[i], static_cast<double>(s.iterations[i])});
      for (size_t j = 0; j < s.amplitude_dlog.size(); ++j)
        for (const Eigen::MatrixXd* d : {&s.amplitude_dlog[j], &s.phase_dlog_deg[j]})
          for (Index r = 0; r < d->cols(); ++r) values.push_back((*d)(row, r));
      rows.push_back(std::move(values));
    }
    const std::string name = "frf_" + s.name;
    const SteppedSineSpec* sine = named(spec.stepped_sines, s.name);
    tables.emplace(name, stepped_table(name, cols, std::move(rows), sine ? sine->frequency_hz : std::vector<double>{},
                                       sine ? sine->force : std::vector<double>{}, s.failed_hz, s.failures));
    const size_t points = s.frequency_hz.size() + s.failed_hz.size();
    cost_rows.push_back({static_cast<double>(k + 1), static_cast<double>(points),
                         static_cast<double>(s.failed_hz.size()), static_cast<double>(s.total_iterations),
                         static_cast<double>(s.harmonics), static_cast<double>(s.samples), s.seconds});
    names.push_back(s.name);
    first_failures.push_back(
        s.failed_hz.empty() ? "" : fmt::format("{:.6g} Hz: {}", s.failed_hz.front(), s.failures.front()));
  }
  ResultTable cost = table_from_rows(
      "stepped_sine_cost", {"sine", "points", "failed", "iterations", "harmonics", "samples", "seconds"}, cost_rows);
  cost.add_text_column("name", names);
  cost.add_text_column("first_failure", first_failures);
  tables.emplace("stepped_sine_cost", std::move(cost));
}

void add_response_control_tables(const PreparedHbm& p, const HbmSpec& spec, const std::vector<HbmControlled>& controls,
                                 ResultTables& tables) {
  if (controls.empty()) return;
  using Eigen::Index;
  std::vector<std::vector<double>> summary;
  std::vector<std::string> names, dofs, quantities, first_failures;
  const char* quantity[] = {"displacement [m]", "velocity [m/s]", "acceleration [m/s^2]"};
  for (size_t k = 0; k < controls.size(); ++k) {
    const HbmControlled& s = controls[k];
    const ResponseControlSpec& c = spec.response_controls[k];
    std::vector<std::string> cols = {"point", "frequency_hz", "force_n", "force_phase_deg", "held_m"};
    for (const char* q : {"_amp_m", "_phase_deg", "_max_m"})
      for (const std::string& r : p.response_names) cols.push_back(r + q);
    cols.insert(cols.end(), {"residual_n", "iterations"});
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < s.frequency_hz.size(); ++i) {
      const Index row = static_cast<Index>(i);
      std::vector<double> values = {static_cast<double>(s.point[i] + 1), s.frequency_hz[i], s.force[i],
                                    s.force_phase_deg[i], s.held_m[i]};
      for (const Eigen::MatrixXd* m : {&s.amplitude, &s.phase_deg, &s.excursion})
        for (Index r = 0; r < m->cols(); ++r) values.push_back((*m)(row, r));
      values.insert(values.end(), {s.residual[i], static_cast<double>(s.iterations[i])});
      rows.push_back(std::move(values));
    }
    const std::string name = "frf_" + s.name;
    tables.emplace(name, stepped_table(name, cols, std::move(rows), c.frequency_hz, {}, s.failed_hz, s.failures));
    summary.push_back({static_cast<double>(k + 1), c.amplitude, static_cast<double>(c.derivative), s.min_force,
                       s.min_frequency_hz, s.min_phase_deg, s.min_interior ? 1.0 : 0.0,
                       static_cast<double>(s.frequency_hz.size() + s.failed_hz.size()),
                       static_cast<double>(s.failed_hz.size()), static_cast<double>(s.total_iterations),
                       static_cast<double>(s.harmonics), static_cast<double>(s.samples), s.seconds});
    names.push_back(s.name);
    dofs.push_back(p.response_names[c.response]);
    quantities.push_back(quantity[c.derivative]);
    first_failures.push_back(
        s.failed_hz.empty() ? "" : fmt::format("{:.6g} Hz: {}", s.failed_hz.front(), s.failures.front()));
  }
  ResultTable t =
      table_from_rows("response_control",
                      {"control", "amplitude", "derivative", "min_force_n", "min_frequency_hz", "min_phase_deg",
                       "min_interior", "points", "failed", "iterations", "harmonics", "samples", "seconds"},
                      summary);
  t.add_text_column("name", names);
  t.add_text_column("dof", dofs);
  t.add_text_column("held", quantities);
  t.add_text_column("first_failure", first_failures);
  tables.emplace("response_control", std::move(t));
}

void run_stepped_sines(const PreparedHbm& p, const HbmSpec& spec, const HbmProgress& progress,
                       std::vector<HbmSteppedSine>& sines, std::vector<HbmControlled>& controls, ResultTables& tables) {
  sines = run_stepped<HbmSteppedSine>(spec.stepped_sines, spec.threads, "stepped sine",
                                      [&](const auto& s) { return run_stepped_sine(p, spec, s, progress); });
  add_stepped_sine_tables(p, spec, sines, tables);
  controls = run_stepped<HbmControlled>(spec.response_controls, spec.threads, "response control",
                                        [&](const auto& c) { return run_response_control(p, spec, c, progress); });
  add_response_control_tables(p, spec, controls, tables);
}

}  // namespace bb
