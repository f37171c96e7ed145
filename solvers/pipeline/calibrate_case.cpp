#include "pipeline/calibrate_case.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include "analysis/hbm_analysis.hpp"
#include "analysis/run_analysis.hpp"
#include "cases/case_parameter.hpp"
#include "cases/case_settings.hpp"
#include "cases/case_spec.hpp"
#include "cases/parse_calibration.hpp"
#include "checks/checks.hpp"
#include "common/errors.hpp"
#include "identify/phase_check.hpp"
#include "identify/posterior_bands.hpp"
#include "identify/prediction_bands.hpp"
#include "model/build_model.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// The parsed case and what each fitted value sets in it.
struct CalibratedCase {
  CaseSpec spec;
  std::vector<CaseParameter> parameters;  // in CalibrationSpec::parameters order
};

CalibratedCase with_parameters(CaseSpec spec, const CalibrationSpec& cal) {
  CalibratedCase c{std::move(spec), {}};
  for (const CalibrationParameter& p : cal.parameters) c.parameters.push_back(parse_parameter_path(p.path));
  return c;
}

// The case with the given values; InputError when a value makes it invalid or the case lacks one.
CaseSpec with_values(const CalibratedCase& base, const std::vector<double>& values) {
  CaseSpec spec = base.spec;
  for (size_t i = 0; i < values.size(); ++i) {
    try {
      set_parameter_value(spec, base.parameters[i], values[i]);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("{}: calibration path {}", base.spec.file.string(), e.what()));
    }
  }
  return spec;
}

// The paths of the parameters the model differentiates.
std::vector<std::string> differentiated_paths(const CalibrationSpec& cal, const std::vector<bool>& differentiated) {
  std::vector<std::string> paths;
  for (size_t j = 0; j < cal.parameters.size(); ++j)
    if (differentiated[j]) paths.push_back(cal.parameters[j].path);
  return paths;
}

// A point's gradient over the differentiated parameters spread over all of them, NaN for the
// others (their columns are central differences); empty stays empty (no sensitivities).
void spread_gradient(FitPoint& p, const std::vector<bool>& differentiated) {
  if (p.gradient.empty()) return;
  std::vector<double> all(differentiated.size(), NAN);
  for (size_t j = 0, k = 0; j < all.size(); ++j)
    if (differentiated[j]) all[j] = p.gradient.at(k++);
  p.gradient = std::move(all);
}

// The fitted points of the case with the given parameter values, and the tables of its curves;
// with `differentiated`, every point carries d r / d log p from the tables' sensitivity columns
// for those parameters (NaN for the others).
std::vector<FitPoint> fitted_points(const CalibratedCase& base, const CalibrationSpec& cal,
                                    const std::vector<double>& values, const WorkLimits& limits,
                                    const ModelCacheSettings* cache, ResultTables* curves = nullptr,
                                    const std::vector<bool>* differentiated = nullptr) {
  const CaseSpec spec = with_values(base, values);
  const AnalysisResults results = run_analysis(spec.analysis, build_model(spec.model), {}, limits, cache);
  const std::vector<std::string> paths =
      differentiated ? differentiated_paths(cal, *differentiated) : std::vector<std::string>{};
  std::vector<FitPoint> points;
  for (const CheckSpec& c : spec.checks) {
    if (std::find(cal.fit_checks.begin(), cal.fit_checks.end(), c.name) == cal.fit_checks.end()) continue;
    const std::vector<CheckEntry> entries = evaluate_check(c, results.tables);  // names a missing table first
    const auto e = check_points(entries, cal, &results.tables.at(c.result), paths);
    points.insert(points.end(), e.begin(), e.end());
  }
  for (const CalibrationData& d : cal.data) {
    const auto e = data_points(d, results.tables, paths);
    points.insert(points.end(), e.begin(), e.end());
    if (curves) curves->insert_or_assign(d.table, results.tables.at(d.table));
  }
  if (differentiated)
    for (FitPoint& p : points) spread_gradient(p, *differentiated);
  // Stated priors: r = (p - value) / sigma, d r / d log p = p / sigma.
  for (size_t j = 0; j < cal.parameters.size(); ++j) {
    const auto& prior = cal.parameters[j].prior;
    if (!prior) continue;
    std::vector<double> gradient;
    if (differentiated) gradient.assign(cal.parameters.size(), 0.0), gradient[j] = values[j] / prior->sigma;
    points.push_back({"priors", cal.parameters[j].path, "prior", static_cast<double>(j + 1), prior->value, values[j],
                      prior->sigma, false, std::move(gradient)});
  }
  return points;
}

// The case asking its hbm analysis for the sensitivities to every parameter, when analytic
// derivatives can serve the whole fit: frf data (derivatives = "auto" or "analytic"), or also peaks
// data and checks ("analytic"; a check on a table without sensitivity columns is found at the
// start), and the analysis differentiates at least one parameter (the others' columns are central
// differences, each named with why). Otherwise the reason why not.
struct AnalyticCase {
  CalibratedCase model;
  std::vector<bool> differentiated;  // per parameter
  std::vector<std::string> numeric;  // "'path': why" of each parameter that is not
};

// The nonlinear modal model differentiates its own knots and mass exactly; false when no parameter is one.
bool nonlinear_modal_sensitivities(NonlinearModalSpec& modal, AnalyticCase& out) {
  const std::vector<std::string> own = nonlinear_modal_parameter_paths(modal);
  for (const CaseParameter& p : out.model.parameters) {
    const bool d = std::find(own.begin(), own.end(), p.path) != own.end();
    out.differentiated.push_back(d);
    if (d)
      modal.sensitivities.push_back(p.path);
    else
      out.numeric.push_back(fmt::format("'{}': not a parameter of the nonlinear modal model", p.path));
  }
  return !modal.sensitivities.empty();
}

std::variant<AnalyticCase, std::string> analytic_case(const CalibratedCase& base, const CalibrationSpec& cal) {
  if (cal.derivatives == "numeric") return std::string("derivatives = \"numeric\"");
  const bool peaks = cal.derivatives == "analytic";
  if (!peaks && !cal.fit_checks.empty())
    return std::string("fitted checks take central differences unless derivatives = \"analytic\"");
  bool curves = false;
  for (const CalibrationData& d : cal.data) {
    if (d.data.kind == DataKind::hysteresis) return fmt::format("data '{}' is a hysteresis loop", d.name);
    if (!peaks && d.data.kind != DataKind::frf)
      return fmt::format(
          "data '{}' is not frf data (peaks take central differences unless derivatives = "
          "\"analytic\")",
          d.name);
    curves = curves || d.data.kind == DataKind::frf;
  }
  AnalyticCase out{base, {}, {}};
  if (auto* modal = std::get_if<NonlinearModalSpec>(&out.model.spec.analysis))
    return nonlinear_modal_sensitivities(*modal, out) ? std::variant<AnalyticCase, std::string>(out)
                                                      : fmt::format(
                                                            "the analysis has no sensitivities for these "
                                                            "parameters ({})",
                                                            fmt::join(out.numeric, "; "));
  HbmSpec* hbm = std::get_if<HbmSpec>(&out.model.spec.analysis);
  if (!hbm) return std::string("the analysis is not hbm");
  hbm->path_sensitivities = curves;  // peaks alone need no curve's derivatives
  for (const CaseParameter& p : base.parameters) {
    const std::optional<HbmParameter> h = hbm_parameter(p);
    std::optional<std::string> why = h ? unsupported_sensitivity(*hbm, *h) : std::string("not differentiated");
    out.differentiated.push_back(!why);
    if (why) {
      out.numeric.push_back(fmt::format("'{}': {}", p.path, *why));
      continue;
    }
    const auto same = [&](const HbmParameter& q) { return q.label == h->label; };
    if (std::none_of(hbm->sensitivities.begin(), hbm->sensitivities.end(), same)) hbm->sensitivities.push_back(*h);
  }
  if (std::none_of(out.differentiated.begin(), out.differentiated.end(), [](bool d) { return d; }))
    return fmt::format("the analysis has no sensitivities for these parameters ({})", fmt::join(out.numeric, "; "));
  return out;
}

// The case without the stepped sines only held-out curves read: the fit's runs need not compute
// what only the start and the identified values are compared with.
CalibratedCase without_held_out_curves(CalibratedCase c, const CalibrationSpec& cal) {
  HbmSpec* hbm = std::get_if<HbmSpec>(&c.spec.analysis);
  auto* modal = std::get_if<NonlinearModalSpec>(&c.spec.analysis);
  if (!hbm && !modal) return c;
  const auto only_held_out = [&](const std::string& name) {
    const std::string table = "frf_" + name;
    bool held = false;
    for (const CalibrationData& d : cal.data)
      if (d.table == table) {
        if (!d.held_out) return false;
        held = true;
      }
    for (const CheckSpec& k : c.spec.checks)
      if (k.result == table) return false;
    return held;
  };
  const auto drop = [&](auto& sines, auto& controls) {
    std::erase_if(sines, [&](const SteppedSineSpec& s) { return only_held_out(s.name); });
    std::erase_if(controls, [&](const ResponseControlSpec& s) { return only_held_out(s.name); });
  };
  if (hbm) drop(hbm->stepped_sines, hbm->response_controls);
  if (modal) drop(modal->stepped_sines, modal->response_controls);
  return c;
}

// Replaces the number at `path` of a case table (for the calibrated copy of the case file).
void set_number(toml::table& root, const std::string& path, double value) {
  toml::node* n = node_at_path(root, path);
  if (n && !n->is_number()) throw InputError(fmt::format("calibration path '{}' is not a number in the case", path));
  if (toml::value<double>* f = n ? n->as_floating_point() : nullptr) {
    *f = value;
    return;
  }
  // An integer, or a key left at its default (e.g. an Iwan beta of 0): a float in its parent.
  const size_t dot = path.rfind('.');
  const std::string leaf = path.substr(dot == std::string::npos ? 0 : dot + 1);
  toml::node* parent = dot == std::string::npos ? &root : node_at_path(root, path.substr(0, dot));
  if (parent && parent->is_table()) {
    parent->as_table()->insert_or_assign(leaf, value);
  } else if (toml::array* a = parent ? parent->as_array() : nullptr; a && n) {
    a->replace(a->begin() + static_cast<std::ptrdiff_t>(std::stoul(leaf)), value);
  } else {
    throw InputError(fmt::format("calibration path '{}' is not a number in the case", path));
  }
}

// The cross-check's tables with band columns: each parameter moved both ways by 1e-4 in the fit's
// own variable (of itself on a log scale, of its range on a linear one, where it may be zero), the
// covariance carried through.
template <class Run>
void cross_check_bands(const CalibratedCase& cross, const Run& tables_at, CalibrationOutcome& out) {
  const Eigen::MatrixXd covariance = parameter_covariance(out);
  if (covariance.size() == 0) {
    out.warnings.push_back("the cross-check's tables have no band columns: the fit has no covariance");
    return;
  }
  std::vector<ResultTables> minus, plus;
  std::vector<double> step;
  try {
    for (size_t j = 0; j < out.values.size(); ++j) {
      step.push_back(1e-4 * out.spec.parameters[j].value_per_fit(out.values[j]));
      for (const double sign : {-1.0, 1.0}) {
        std::vector<double> v = out.values;
        v[j] += sign * step.back();
        (sign < 0.0 ? minus : plus).push_back(tables_at(with_values(cross, v)));
      }
    }
  } catch (const std::exception& e) {  // no solution there (SolverError), or a value off its domain (InputError)
    out.warnings.push_back(fmt::format(
        "the cross-check's tables have no band columns: a run 1e-4 from the identified values failed: {}", e.what()));
    return;
  }
  out.cross_check_tables = with_band_columns(out.cross_check_tables, minus, plus, step, covariance);
}

// The same parameter paths in an independent model (e.g. Newmark instead of the harmonic balance).
void cross_check(const CalibrationSpec& cal, const WorkLimits& limits, const ModelCacheSettings* cache,
                 CalibrationOutcome& out) {
  const auto t0 = std::chrono::steady_clock::now();
  const CalibratedCase cross = with_parameters(parse_case_file(cal.cross_check), cal);
  const CaseSpec spec = with_values(cross, out.values);
  const auto tables_at = [&](const CaseSpec& s) {
    return run_analysis(s.analysis, build_model(s.model), {}, limits, cache).tables;
  };
  try {
    out.cross_check_tables = tables_at(spec);
    for (const CheckSpec& c : spec.checks) {
      const auto e = evaluate_check(c, out.cross_check_tables);
      out.cross_check.insert(out.cross_check.end(), e.begin(), e.end());
    }
  } catch (const SolverError& e) {  // the identification stands: say why its check has no verdict
    out.cross_check_failure = e.what();
  }
  if (cal.cross_check_bands && out.cross_check_failure.empty()) cross_check_bands(cross, tables_at, out);
  out.cross_check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!out.cross_check_failure.empty())
    out.warnings.push_back(fmt::format("the cross-check {} found no solution with the identified values: {}",
                                       cal.cross_check.string(), out.cross_check_failure));
  else if (!out.cross_check_passed())
    out.warnings.push_back(
        fmt::format("the cross-check {} fails with the identified values", cal.cross_check.string()));
}

// Every [calibration] parameter of `table` set to its value in `file` (an earlier fit's output).
// The paths are read raw: a malformed section is parse_calibration's to report.
void restart_values(toml::table& table, const fs::path& file) {
  toml::table earlier = read_case_table(file);
  const toml::array* parameters = table.at_path("calibration.parameters").as_array();
  if (!parameters) return;
  for (const toml::node& p : *parameters) {
    const std::optional<std::string> path = p.is_table() ? (*p.as_table())["path"].value<std::string>() : std::nullopt;
    if (!path) continue;
    const toml::node* value = node_at_path(earlier, *path);
    if (!value || !value->is_number())
      throw InputError(
          fmt::format("--restart-from {}: no number at the calibration path '{}' (not a case "
                      "calibrated from this one?)",
                      file.string(), *path));
    set_number(table, *path, value->value_or(0.0));
  }
}

}  // namespace

bool CalibrationOutcome::cross_check_passed() const {
  return cross_check_failure.empty() &&
         std::all_of(cross_check.begin(), cross_check.end(), [](const CheckEntry& e) { return e.pass; });
}

CalibrationOutcome calibrate_case(const fs::path& case_file, const FitProgress& progress, const WorkLimits& limits,
                                  const ModelCacheSettings* cache, const CalibrationStartEdits& edits) {
  const toml::table table = [&] {
    toml::table t = read_case_table(case_file);
    apply_settings(t, edits.settings);
    if (!edits.restart_from.empty()) restart_values(t, edits.restart_from);
    return t;
  }();
  CaseSpec spec = parse_case_table(table, case_file);
  const std::optional<CalibrationSpec> cal = parse_calibration(table, case_file, spec);
  if (!cal) throw InputError(fmt::format("{}: no [calibration] section", case_file.string()));
  require_linked_cases(case_file, spec, cal);  // as `run` does: the whole case is valid before any solve
  const CalibratedCase base = with_parameters(std::move(spec), *cal);
  std::vector<double> start;
  for (const CalibrationParameter& p : cal->parameters) start.push_back(p.start);
  const auto analytic_base = analytic_case(base, *cal);
  const AnalyticCase* sensitivity_base = std::get_if<AnalyticCase>(&analytic_base);
  const std::vector<bool>* differentiated = sensitivity_base ? &sensitivity_base->differentiated : nullptr;
  ResultTables curves_before;
  const std::vector<FitPoint> before = fitted_points(sensitivity_base ? sensitivity_base->model : base, *cal, start,
                                                     limits, cache, &curves_before, differentiated);
  for (const FitPoint& p : before)
    if (!(p.sigma > 0.0))
      throw InputError(
          fmt::format("{}: fitted entry '{}' has a zero reference or uncertainty", cal->at.where(), p.label));
  const std::vector<std::string> phase_warnings = check_measured_phases(*cal, before);  // exit 2 before any fit
  require_solved_points(before, *cal, curves_before);                                   // exit 3 before any fit
  std::string numeric_reason = sensitivity_base ? "" : std::get<std::string>(analytic_base);
  // A point whose table has no sensitivity columns makes the whole fit numeric; one without a
  // finite value at some parameters costs that evaluation central differences (least_squares_fit).
  if (sensitivity_base)
    for (const FitPoint& p : before)
      if (!p.held_out && p.gradient.size() != cal->parameters.size())
        numeric_reason = fmt::format("no sensitivities for '{}' of '{}'", p.label, p.set);
  const bool analytic = numeric_reason.empty();
  const CalibratedCase& model = analytic ? sensitivity_base->model : base;
  // A run whose Jacobian is not asked for (a trial step, a central difference) runs the case
  // without the sensitivities the analytic Jacobian added: the same values, none of their cost.
  // Held-out curves are predicted at the start and at the identified values, never fitted: the
  // fit's runs have neither their data blocks nor the stepped sines only they read.
  const CalibratedCase fit_model = without_held_out_curves(model, *cal), fit_base = without_held_out_curves(base, *cal);
  const CalibrationSpec fit_spec = [&] {
    CalibrationSpec f = *cal;
    std::erase_if(f.data, [](const CalibrationData& d) { return d.held_out; });
    return f;
  }();
  const FitEvaluator evaluate = [&](const std::vector<double>& values, bool gradients) {
    return fitted_points(gradients ? fit_model : fit_base, fit_spec, values, limits, cache, nullptr,
                         gradients ? differentiated : nullptr);
  };
  const auto fitted = std::count_if(before.begin(), before.end(), [](const FitPoint& p) { return !p.held_out; });
  std::vector<bool> numeric_columns;
  if (analytic)
    for (bool d : sensitivity_base->differentiated) numeric_columns.push_back(!d);
  CalibrationOutcome out =
      fit_parameters(*cal, evaluate, analytic, static_cast<int>(fitted), progress, numeric_columns);
  out.before = before;
  out.curves_before = std::move(curves_before);
  const std::string mixed = analytic && !sensitivity_base->numeric.empty()
                                ? fmt::format(", central differences (relative step {:g}) for the columns of {}",
                                              cal->derivative_step, fmt::join(sensitivity_base->numeric, "; "))
                                : std::string();
  const auto* modal = std::get_if<NonlinearModalSpec>(&base.spec.analysis);
  const char* how =
      !modal ? "analytic (implicit function theorem, hbm/sensitivity.hpp)"
      : modal->modes.size() == 1
          ? "analytic (the nonlinear modal model's own, forced/single_mode_synthesis.hpp)"
          : "analytic (the nonlinear modal model's own, each mode's summed, forced/multi_mode_synthesis.hpp)";
  out.derivatives = analytic ? fmt::format("{}{}{}", how, mixed,
                                           out.jacobian_fallbacks == 0
                                               ? ""
                                               : fmt::format("; {} Jacobians by central differences, relative step "
                                                             "{:g}, where a fitted point had no derivative",
                                                             out.jacobian_fallbacks, cal->derivative_step))
                             : fmt::format("central differences, relative step {:g} ({})", cal->derivative_step,
                                           cal->derivatives == "numeric" ? "as asked" : numeric_reason);
  if (out.one_sided_columns > 0)
    out.derivatives += fmt::format("; {} columns one-sided, where the model could not be run on the other side",
                                   out.one_sided_columns);
  // With the model's own sensitivities, every point at the identified values carries its band.
  out.after = fitted_points(analytic ? sensitivity_base->model : base, *cal, out.values, limits, cache,
                            &out.curves_after, analytic ? differentiated : nullptr);
  if (analytic) set_linearised_bands(out.after, out.values, parameter_covariance(out));
  if (cal->sampler) {
    out.posterior = sample_posterior(
        *cal, out, evaluate,
        [&](const std::vector<double>& values) { return fitted_points(base, *cal, values, limits, cache); }, out.after);
    if (!out.posterior->warning.empty()) out.warnings.push_back(out.posterior->warning);
  }
  out.calibrated = table;
  for (size_t i = 0; i < out.values.size(); ++i) set_number(out.calibrated, cal->parameters[i].path, out.values[i]);
  if (!cal->cross_check.empty()) cross_check(*cal, limits, cache, out);
  out.warnings.insert(out.warnings.end(), phase_warnings.begin(), phase_warnings.end());
  for (const std::string& setting : edits.settings)
    out.warnings.push_back(fmt::format("--set {}: the fit ran at this setting, not the file's", setting));
  if (!edits.restart_from.empty())
    out.warnings.push_back(
        fmt::format("--restart-from {}: the fit started from its values, not the file's", edits.restart_from.string()));
  return out;
}

}  // namespace bb
