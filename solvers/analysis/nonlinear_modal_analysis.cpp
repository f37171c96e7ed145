#include "analysis/nonlinear_modal_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "forced/multi_mode_synthesis.hpp"
#include "frf/sweep.hpp"

namespace bb {

std::vector<std::string> nonlinear_modal_parameter_paths(const NonlinearModalSpec& spec) {
  std::vector<std::string> paths;
  for (size_t k = 0; k < spec.modes.size(); ++k) {
    const NonlinearMode& mode = spec.modes[k];
    const std::string prefix = spec.mode_array ? fmt::format("analysis.mode.{}.", k) : "analysis.";
    for (size_t i = 0; i < mode.frequency_hz.knots(); ++i)
      paths.push_back(fmt::format("{}backbone.frequency_hz.{}", prefix, i));
    for (size_t i = 0; i < mode.damping_ratio.knots(); ++i)
      paths.push_back(fmt::format("{}backbone.damping_ratio.{}", prefix, i));
    paths.push_back(prefix + "mass");
  }
  return paths;
}

std::vector<double> nonlinear_modal_parameter_values(const NonlinearModalSpec& spec) {
  std::vector<double> values;
  for (const NonlinearMode& mode : spec.modes) {
    values.insert(values.end(), mode.frequency_hz.values().begin(), mode.frequency_hz.values().end());
    values.insert(values.end(), mode.damping_ratio.values().begin(), mode.damping_ratio.values().end());
    values.push_back(mode.mass);
  }
  return values;
}

namespace {

// Index into the model's parameters of each asked sensitivity, and the parameter's value (p in p d/dp).
struct Differentiated {
  std::vector<Eigen::Index> index;
  std::vector<double> value;
  const std::vector<std::string>* paths = nullptr;
};

Differentiated differentiated(const NonlinearModalSpec& spec) {
  const std::vector<std::string> all = nonlinear_modal_parameter_paths(spec);
  const std::vector<double> values = nonlinear_modal_parameter_values(spec);
  Differentiated d;
  d.paths = &spec.sensitivities;
  for (const std::string& p : spec.sensitivities) {
    const auto it = std::find(all.begin(), all.end(), p);
    if (it == all.end())
      throw InputError(fmt::format("{}: the nonlinear modal model has no parameter '{}'", spec.at.where(), p));
    const auto k = static_cast<size_t>(it - all.begin());
    d.index.push_back(static_cast<Eigen::Index>(k));
    d.value.push_back(values[k]);
  }
  return d;
}

// One mode's f(a) and z(a) on a log grid a decade around its knots: "backbone" for one mode,
// "backbone_<k>" for each of several.
void add_backbone_table(const NonlinearMode& mode, const std::string& name, ResultTables& tables) {
  const auto& a = mode.frequency_hz.amplitudes();
  const auto& b = mode.damping_ratio.amplitudes();
  const double lo = std::min(a.front(), b.front()) / 10.0, hi = std::max(a.back(), b.back()) * 10.0;
  constexpr int kPoints = 81;
  std::vector<std::vector<double>> rows;
  for (int k = 0; k < kPoints; ++k) {
    const double amp = lo * std::pow(hi / lo, static_cast<double>(k) / (kPoints - 1));
    rows.push_back({static_cast<double>(k + 1), amp, mode.frequency_hz(amp), mode.damping_ratio(amp)});
  }
  tables.emplace(name, table_from_rows(name, {"point", "amplitude_m", "frequency_hz", "damping_ratio"}, rows));
}

// The columns <dof>_amp_m_mode<k> of several modes' own amplitudes (none for one mode).
void add_mode_columns(std::vector<std::string>& cols, const NonlinearModalSpec& spec) {
  if (spec.modes.size() < 2) return;
  for (size_t k = 0; k < spec.modes.size(); ++k) cols.push_back(fmt::format("{}_amp_m_mode{}", spec.dof, k));
}

void append_mode_amplitudes(std::vector<double>& row, const MultiModePoint& p) {
  if (p.mode_amplitude.size() < 2) return;
  row.insert(row.end(), p.mode_amplitude.begin(), p.mode_amplitude.end());
}

std::vector<std::string> with_sensitivities(std::vector<std::string> cols, const std::vector<std::string>& quantities,
                                            const Differentiated& d) {
  for (const std::string& p : *d.paths)
    for (const std::string& q : quantities) cols.push_back(q + "_dlog_" + p);
  return cols;
}

void append_sensitivities(std::vector<double>& row, const std::vector<const Eigen::VectorXd*>& derivatives,
                          const std::vector<double>& scales, const Differentiated& d) {
  for (size_t j = 0; j < d.index.size(); ++j)
    for (size_t q = 0; q < derivatives.size(); ++q)
      row.push_back(d.value[j] * (*derivatives[q])[d.index[j]] * scales[q]);
}

void add_stepped_sine(const NonlinearModalSpec& spec, const SteppedSineSpec& sine, const Differentiated& d,
                      ResultTables& tables) {
  const std::string amp = spec.dof + "_amp_m", phase = spec.dof + "_phase_deg";
  std::vector<std::string> cols = {"point", "frequency_hz", "force_n", amp, phase, "stable"};
  add_mode_columns(cols, spec);
  cols = with_sensitivities(std::move(cols), {amp, phase}, d);
  std::vector<std::vector<double>> rows;
  std::vector<double> previous;  // each mode's own amplitude at the point before
  const std::vector<BackboneBounds> bounds = multi_mode_bounds(spec.modes);  // the same for every point
  for (size_t i = 0; i < sine.frequency_hz.size(); ++i) {
    const MultiModePoint p = multi_mode_stepped(spec.modes, sine.force[i], sine.frequency_hz[i], previous, bounds);
    previous = p.mode_amplitude;
    std::vector<double> row = {static_cast<double>(i + 1), sine.frequency_hz[i], sine.force[i], p.amplitude,
                               p.phase * kDegPerRad,       p.stable ? 1.0 : 0.0};
    append_mode_amplitudes(row, p);
    append_sensitivities(row, {&p.d_amplitude, &p.d_phase}, {1.0, kDegPerRad}, d);
    rows.push_back(std::move(row));
  }
  tables.emplace("frf_" + sine.name, table_from_rows("frf_" + sine.name, cols, rows));
}

struct ControlMinimum {
  double force = NAN, frequency_hz = NAN, phase_deg = NAN;
  bool interior = false;
};

// The smallest force refined between the neighbours of the smallest point (frf/sweep.hpp's golden
// section on the negated force, as the hbm's response control refines its own).
ControlMinimum smallest_force(const NonlinearModalSpec& spec, const ResponseControlSpec& c,
                              const std::vector<double>& force, const std::vector<BackboneBounds>& bounds) {
  const auto k = static_cast<size_t>(std::min_element(force.begin(), force.end()) - force.begin());
  const auto at = [&](double f) { return multi_mode_held(spec.modes, c.held_displacement(kTwoPi * f), f, bounds); };
  ControlMinimum m{force[k], c.frequency_hz[k], at(c.frequency_hz[k]).phase * kDegPerRad, false};
  if (k == 0 || k + 1 >= force.size()) return m;
  const GoldenSearch search =
      golden_section_maximum([&](double f) { return std::optional<double>(-at(f).force); },
                             std::min(c.frequency_hz[k - 1], c.frequency_hz[k + 1]),
                             std::max(c.frequency_hz[k - 1], c.frequency_hz[k + 1]), 200, 1e-10);
  const double f = 0.5 * (search.a + search.b);
  const MultiModePoint p = at(f);
  if (p.force < m.force) m = {p.force, f, p.phase * kDegPerRad, true};
  return m;
}

ControlMinimum add_response_control(const NonlinearModalSpec& spec, const ResponseControlSpec& c,
                                    const Differentiated& d, ResultTables& tables) {
  const std::string amp = spec.dof + "_amp_m", phase = spec.dof + "_phase_deg";
  std::vector<std::string> cols = {"point", "frequency_hz", "force_n", "force_phase_deg", "held_m", amp, phase};
  add_mode_columns(cols, spec);
  cols = with_sensitivities(std::move(cols), {"force_n", phase}, d);
  std::vector<std::vector<double>> rows;
  std::vector<double> force;
  const std::vector<BackboneBounds> bounds = multi_mode_bounds(spec.modes);
  for (size_t i = 0; i < c.frequency_hz.size(); ++i) {
    const double held = c.held_displacement(kTwoPi * c.frequency_hz[i]);
    const MultiModePoint p = multi_mode_held(spec.modes, held, c.frequency_hz[i], bounds);
    std::vector<double> row = {
        static_cast<double>(i + 1), c.frequency_hz[i], p.force, -p.phase * kDegPerRad, held, p.amplitude,
        p.phase * kDegPerRad};
    append_mode_amplitudes(row, p);
    append_sensitivities(row, {&p.d_force, &p.d_phase}, {1.0, kDegPerRad}, d);
    rows.push_back(std::move(row));
    force.push_back(p.force);
  }
  tables.emplace("frf_" + c.name, table_from_rows("frf_" + c.name, cols, rows));
  return smallest_force(spec, c, force, bounds);
}

void add_response_control_summary(const NonlinearModalSpec& spec, const std::vector<ControlMinimum>& minima,
                                  ResultTables& tables) {
  if (minima.empty()) return;
  const char* quantity[] = {"displacement [m]", "velocity [m/s]", "acceleration [m/s^2]"};
  std::vector<std::vector<double>> rows;
  std::vector<std::string> names, dofs, held;
  for (size_t k = 0; k < minima.size(); ++k) {
    const ResponseControlSpec& c = spec.response_controls[k];
    const ControlMinimum& m = minima[k];
    rows.push_back({static_cast<double>(k + 1), c.amplitude, static_cast<double>(c.derivative), m.force, m.frequency_hz,
                    m.phase_deg, m.interior ? 1.0 : 0.0, static_cast<double>(c.frequency_hz.size())});
    names.push_back(c.name), dofs.push_back(spec.dof), held.push_back(quantity[c.derivative]);
  }
  ResultTable t = table_from_rows("response_control",
                                  {"control", "amplitude", "derivative", "min_force_n", "min_frequency_hz",
                                   "min_phase_deg", "min_interior", "points"},
                                  rows);
  t.add_text_column("name", names);
  t.add_text_column("dof", dofs);
  t.add_text_column("held", held);
  tables.emplace("response_control", std::move(t));
}

void add_extracted(const NonlinearModalSpec& spec, NonlinearModalOutcome& out) {
  if (spec.extract.empty()) return;
  std::vector<std::vector<double>> rows;
  std::vector<std::string> names;
  for (size_t k = 0; k < spec.extract.size(); ++k) {
    const BackboneCurve& c = spec.extract[k];
    BackbonePoint p;
    try {
      p = extract_backbone_point(c.frequency_hz, c.amplitude_m, c.force_n);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("{}: {}: {}", c.at.where(), c.file, e.what()));
    }
    out.extracted.push_back(p);
    // Of several modes, the one whose backbone passes nearest the point's frequency.
    const auto miss = [&](const NonlinearMode& m) { return std::abs(m.frequency_hz(p.amplitude_m) - p.frequency_hz); };
    const NonlinearMode& m = *std::min_element(spec.modes.begin(), spec.modes.end(),
                                               [&](const auto& x, const auto& y) { return miss(x) < miss(y); });
    rows.push_back({static_cast<double>(k + 1), p.amplitude_m, p.frequency_hz, p.damping_ratio, p.mass_kg,
                    p.rms_relative, m.frequency_hz(p.amplitude_m), m.damping_ratio(p.amplitude_m)});
    names.push_back(c.name);
  }
  ResultTable t = table_from_rows("backbone_extracted",
                                  {"curve", "amplitude_m", "frequency_hz", "damping_ratio", "mass_kg", "rms_relative",
                                   "model_frequency_hz", "model_damping_ratio"},
                                  rows);
  t.add_text_column("name", names);
  out.tables.emplace("backbone_extracted", std::move(t));
}

}  // namespace

NonlinearModalOutcome run_nonlinear_modal(const NonlinearModalSpec& spec) {
  NonlinearModalOutcome out;
  const Differentiated d = differentiated(spec);
  for (size_t k = 0; k < spec.modes.size(); ++k)
    add_backbone_table(spec.modes[k], spec.modes.size() == 1 ? "backbone" : fmt::format("backbone_{}", k), out.tables);
  for (const SteppedSineSpec& s : spec.stepped_sines) add_stepped_sine(spec, s, d, out.tables);
  std::vector<ControlMinimum> minima;
  for (const ResponseControlSpec& c : spec.response_controls)
    minima.push_back(add_response_control(spec, c, d, out.tables));
  add_response_control_summary(spec, minima, out.tables);
  add_extracted(spec, out);
  return out;
}

}  // namespace bb
