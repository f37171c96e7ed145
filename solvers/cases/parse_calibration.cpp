#include "cases/parse_calibration.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "cases/case_parameter.hpp"
#include "cases/case_spec.hpp"
#include "cases/read_measured_file.hpp"
#include "checks/checks.hpp"
#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/toml_reader.hpp"
#include "common/user_text.hpp"

namespace bb {

toml::node* node_at_path(toml::table& root, const std::string& path) {
  // Dotted keys; an integer segment indexes an array of tables ("analysis.contact.0.kt").
  toml::node* node = &root;
  size_t begin = 0;
  while (true) {
    const size_t dot = path.find('.', begin);
    const std::string key = path.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin);
    if (toml::table* t = node->as_table()) {
      node = t->get(key);
    } else if (toml::array* a = node->as_array()) {
      const bool digits = !key.empty() && key.find_first_not_of("0123456789") == std::string::npos;
      node = digits && std::stoul(key) < a->size() ? a->get(std::stoul(key)) : nullptr;
    } else {
      node = nullptr;
    }
    if (!node || dot == std::string::npos) return node;
    begin = dot + 1;
  }
}

namespace {

// The data columns a block may map to result columns, per kind; the first ones are required.
struct KindColumns {
  std::vector<std::string> required, optional;
};
KindColumns kind_columns(DataKind kind) {
  switch (kind) {
    case DataKind::peaks:
      return {{"force"}, {"frequency", "amplitude"}};
    case DataKind::frf:
      return {{"frequency"}, {"amplitude", "phase", "force"}};
    case DataKind::hysteresis:
      return {{"relative_displacement", "tangential_force"}, {}};
    case DataKind::acceleration_history:  // a base motion's input, not a calibration kind
      break;
  }
  return {};
}

CalibrationData parse_data_block(const toml::table& t, const std::string& path,
                                 const std::filesystem::path& case_file) {
  TomlReader r(t, path, case_file);
  CalibrationData d;
  d.at = r.location();
  const std::string kind = r.choice("kind", {"peaks", "frf", "hysteresis"});
  const DataKind k = kind == "peaks" ? DataKind::peaks : kind == "frf" ? DataKind::frf : DataKind::hysteresis;
  const std::filesystem::path file = r.input_file("file", case_file.parent_path());
  const MeasuredFile measured = read_measured_file(r, file, k);
  d.data = measured.data;
  const std::optional<long> dataset = measured.dataset;
  const std::string stem = printable(file.stem().string());
  d.name = r.optional_label("name").value_or(dataset ? fmt::format("{} #{}", stem, *dataset) : stem);
  d.table = r.string("table");
  const KindColumns allowed = kind_columns(k);
  for (const auto& [key, value] : r.table("columns")) {
    const std::string column(key.str());
    const bool known = std::count(allowed.required.begin(), allowed.required.end(), column) +
                       std::count(allowed.optional.begin(), allowed.optional.end(), column);
    if (!known)
      r.fail("columns", fmt::format("'{}' is not a column of {} data (they are: {}{}{})", column, kind,
                                    fmt::join(allowed.required, ", "), allowed.optional.empty() ? "" : ", ",
                                    fmt::join(allowed.optional, ", ")));
    const std::optional<std::string> result = value.value<std::string>();
    if (!result || result->empty()) r.fail("columns", fmt::format("'{}' needs the name of a result column", column));
    if (!d.data.has(column))
      r.fail("columns", fmt::format("'{}' is mapped but {} has no such column", column, file.string()));
    const Unit& unit = d.data.units.at(column);
    const std::optional<Dimension> dim = column_dimension(*result);
    if (dim && *dim != unit.dimension)
      r.fail("columns",
             fmt::format("{}'s column '{}' is in {} ({}) but result column '{}' holds a {}: the units do not match",
                         file.string(), column, unit.symbol, dimension_name(unit.dimension), *result,
                         dimension_name(*dim)));
    d.columns[column] = *result;
  }
  for (const std::string& c : allowed.required)
    if (!d.columns.count(c)) r.fail("columns", fmt::format("{} data need a result column for '{}'", kind, c));
  // Each point was measured at its own force: the fit must compare it with a point solved at that force.
  if (k == DataKind::frf && d.data.has("force") && !d.columns.count("force"))
    r.fail("columns",
           fmt::format("{} gives the force of each point: map 'force' to the force column of the stepped sine that "
                       "reads this file (e.g. force = \"force_n\" with table = \"frf_<name>\"), so each point is "
                       "compared with a solve at its own force",
                       file.string()));
  // Phases alone count one residual per point; an amplitude column the file does not have cannot
  // be mapped (above), so no placeholder amplitude doubles the count.
  if (k == DataKind::frf && !d.columns.count("amplitude") && !d.columns.count("phase"))
    r.fail("columns", "frf data need a result column for 'amplitude', 'phase' or both");
  if (k == DataKind::peaks && !d.columns.count("frequency") && !d.columns.count("amplitude"))
    r.fail("columns", "peaks data need 'frequency', 'amplitude' or both");
  if (r.has("amplitude_uncertainty")) d.amplitude_uncertainty = r.positive("amplitude_uncertainty");
  if (r.has("frequency_uncertainty")) d.frequency_uncertainty = r.positive("frequency_uncertainty");
  if (r.has("phase_uncertainty_deg"))
    d.phase_uncertainty = r.positive("phase_uncertainty_deg") * std::numbers::pi / 180.0;
  if (r.has("force_uncertainty")) d.force_uncertainty = r.positive("force_uncertainty");
  r.finish();
  return d;
}

// A measured loop probes the computed one at its displacements: a loop that never moves has no
// branches to probe, and a contact_loop rig imposes u in [-U, U], so a displacement beyond U
// (by more than 0.1 %) was clamped to the loop's end without a word.
void check_hysteresis_probes(const TomlReader& r, const CalibrationData& d, const CaseSpec& spec) {
  if (d.data.kind != DataKind::hysteresis) return;
  const Eigen::VectorXd& u = d.data.column("relative_displacement");
  if (u.maxCoeff() == u.minCoeff())
    r.fail("file", fmt::format("{}: the relative displacement is {:g} m on every row: a hysteresis loop needs a "
                               "motion to probe",
                               d.data.where(0), u[0]));
  const auto* rig = std::get_if<ContactLoopSpec>(&spec.analysis);
  if (!rig) return;
  for (Eigen::Index i = 0; i < u.size(); ++i)
    if (std::abs(u[i]) > 1.001 * rig->tangential_amplitude)
      r.fail("file", fmt::format("{}: relative displacement {:g} m lies outside the imposed motion's range +-{:g} m "
                                 "(analysis.tangential_amplitude_m): the computed loop has no force there",
                                 d.data.where(i), u[i], rig->tangential_amplitude));
}

// A measured peak outside the swept band cannot be met by any computed one (a band of 150-200 Hz
// against peaks measured at 214-225 Hz ran a fit to the band's edge and exited 0).
void check_peaks_in_band(const TomlReader& r, const CalibrationData& d, const CaseSpec& spec) {
  if (d.data.kind != DataKind::peaks || !d.columns.count("frequency")) return;
  const HbmSweepSpec* sweep = nullptr;
  if (const auto* h = std::get_if<HbmSpec>(&spec.analysis)) sweep = &h->sweep;
  if (const auto* t = std::get_if<TimeSpec>(&spec.analysis)) sweep = &t->system.sweep;
  if (!sweep) return;
  const Eigen::VectorXd& f = d.data.column("frequency");
  for (Eigen::Index i = 0; i < f.size(); ++i)
    if (f[i] < sweep->f_min || f[i] > sweep->f_max)
      r.fail("file", fmt::format("{}: peak frequency {:g} Hz lies outside the swept band [{:g}, {:g}] Hz "
                                 "(analysis.frequency_hz): no computed peak can meet it",
                                 d.data.where(i), f[i], sweep->f_min, sweep->f_max));
}

// [calibration.sampler]: walkers even and at least twice the parameters (the stretch move moves one
// half of the ensemble along lines to the other).
CalibrationSpec::Sampler parse_sampler(const toml::table& t, const std::string& path, const std::filesystem::path& file,
                                       const CalibrationSpec& c) {
  TomlReader s(t, path, file);
  CalibrationSpec::Sampler out;
  const long parameters = static_cast<long>(c.parameters.size());
  if (const auto w = s.optional_integer("walkers", 0, 100000)) {
    if (*w < 2 * parameters || *w % 2 != 0)
      s.fail("walkers", fmt::format("the ensemble needs an even number of walkers, at least twice the {} parameters "
                                    "({}), found {}",
                                    parameters, 2 * parameters, *w));
    out.walkers = static_cast<int>(*w);
  }
  if (const auto n = s.optional_integer("steps", 10, 1000000)) out.steps = static_cast<int>(*n);
  if (const auto n = s.optional_integer("burn_in", 0, 1000000)) {
    if (*n >= out.steps) s.fail("burn_in", fmt::format("must be below steps ({}), found {}", out.steps, *n));
    out.burn_in = static_cast<int>(*n);
  }
  if (const auto n = s.optional_integer("predictions", 10, 100000)) out.predictions = static_cast<int>(*n);
  if (const auto n = s.optional_integer("seed", 0, 4294967295L)) out.seed = static_cast<unsigned>(*n);
  s.finish();
  return out;
}

}  // namespace

double uncertainty_of(const CalibrationSpec& c, const std::string& name) {
  const auto it = c.check_uncertainties.find(name);
  return it == c.check_uncertainties.end() ? c.relative_uncertainty : it->second;
}

std::optional<CalibrationSpec> parse_calibration(const toml::table& root, const std::filesystem::path& file,
                                                 const CaseSpec& spec) {
  const toml::node* section = root.get("calibration");
  if (!section) return std::nullopt;
  if (!section->is_table()) throw InputError(fmt::format("{}: [calibration] must be a table", file.string()));
  TomlReader r(*section->as_table(), "calibration", file);
  CalibrationSpec c;
  c.at = r.location();
  int index = 0;
  for (const toml::node& n : r.array("parameters")) {
    if (!n.is_table()) r.fail("parameters", "write each parameter as { path = \"...\", lower = ..., upper = ... }");
    TomlReader p(*n.as_table(), fmt::format("calibration.parameters[{}]", index++), file);
    CalibrationParameter param;
    param.path = p.string("path");
    param.lower = p.number("lower");
    param.upper = p.number("upper");
    if (!std::isfinite(param.lower)) p.fail("lower", "must be finite");
    if (!std::isfinite(param.upper)) p.fail("upper", "must be finite");
    if (!(param.lower < param.upper)) p.fail("upper", "must exceed lower");
    // Log by default where it can be: relative steps whatever the unit.
    const std::string scale = p.choice("scale", {"log", "linear"}, param.lower > 0.0 ? "log" : "linear");
    param.scale = scale == "log" ? CalibrationParameter::Scale::log : CalibrationParameter::Scale::linear;
    if (param.scale == CalibrationParameter::Scale::log && !(param.lower > 0.0))
      p.fail("lower", fmt::format("a parameter fitted on a log scale needs lower > 0, found {}; give scale = "
                                  "\"linear\" for one that may be zero or negative",
                                  param.lower));
    try {
      param.start = parameter_value(spec, parse_parameter_path(param.path));
    } catch (const std::invalid_argument& e) {
      p.fail("path", e.what());
    }
    if (param.start < param.lower || param.start > param.upper)
      p.fail("path", fmt::format("the case value {} of '{}' lies outside [{}, {}]", param.start, param.path,
                                 param.lower, param.upper));
    // A law's own parameter has a domain of its own (an Iwan exponent in (-1, 0]): both bounds
    // must lie in it, so that no step of the fit leaves it by the bounds' fault.
    if (const CaseParameter target = parse_parameter_path(param.path);
        std::holds_alternative<LawOwnValue>(target.target))
      for (const auto& [key, bound] : {std::pair{"lower", param.lower}, std::pair{"upper", param.upper}}) {
        CaseSpec probe = spec;
        try {
          set_parameter_value(probe, target, bound);
        } catch (const std::exception& e) {
          p.fail(key, fmt::format("the law cannot take this bound: {}", e.what()));
        }
      }
    if (const toml::table* prior = p.optional_table("prior")) {
      TomlReader q(*prior, p.path() + ".prior", file);
      const double value = q.number("value"), sigma = q.number("sigma");
      if (!(sigma > 0.0) || !std::isfinite(sigma))
        q.fail("sigma", fmt::format("the prior's width must be positive, found {}", sigma));
      if (!std::isfinite(value)) q.fail("value", "must be finite");
      q.finish();
      param.prior = CalibrationParameter::Prior{value, sigma};
    }
    p.finish();
    c.parameters.push_back(param);
  }
  if (c.parameters.empty()) r.fail("parameters", "needs at least one parameter");
  if (r.has("fit_checks")) c.fit_checks = r.string_array("fit_checks");
  if (r.has("data")) {
    int block = 0;
    for (const toml::node& n : r.array("data")) {
      if (!n.is_table()) r.fail("data", "write each data set as a [[calibration.data]] table");
      const std::string path = fmt::format("calibration.data[{}]", block++);
      c.data.push_back(parse_data_block(*n.as_table(), path, file));
      check_hysteresis_probes(TomlReader(*n.as_table(), path, file), c.data.back(), spec);
      check_peaks_in_band(TomlReader(*n.as_table(), path, file), c.data.back(), spec);
    }
  }
  if (c.fit_checks.empty() && c.data.empty())
    r.fail("fit_checks", "needs at least one check name or a [[calibration.data]] block");
  if (r.has("hold_out")) {  // cross-validation: curves predicted with the identified values, not fitted
    const std::vector<std::string> held = r.string_array("hold_out");
    if (held.empty()) r.fail("hold_out", "names no curve to predict (leave it out to fit every curve)");
    for (const std::string& name : held) {
      const auto it =
          std::find_if(c.data.begin(), c.data.end(), [&](const CalibrationData& d) { return d.name == name; });
      if (it == c.data.end()) r.fail("hold_out", fmt::format("no [[calibration.data]] named '{}'", name));
      if (it->held_out) r.fail("hold_out", fmt::format("'{}' is named twice", name));
      it->held_out = true;
    }
    if (c.fit_checks.empty() &&
        std::all_of(c.data.begin(), c.data.end(), [](const CalibrationData& d) { return d.held_out; }))
      r.fail("hold_out", "holds out every curve: none is left to fit");
  }
  for (const std::string& name : c.fit_checks) {
    const bool found =
        std::any_of(spec.checks.begin(), spec.checks.end(), [&](const CheckSpec& k) { return k.name == name; });
    if (!found) r.fail("fit_checks", fmt::format("no [[check]] named '{}'", name));
  }
  if (r.has("relative_uncertainty")) {
    c.relative_uncertainty = r.positive("relative_uncertainty");
  }
  if (const toml::table* per_check = r.optional_table("check_uncertainties")) {
    for (const auto& [key, value] : *per_check) {
      const std::string name(key.str());
      if (std::find(c.fit_checks.begin(), c.fit_checks.end(), name) == c.fit_checks.end())
        r.fail("check_uncertainties", fmt::format("'{}' is not one of fit_checks", name));
      const std::optional<double> sigma = toml_number(value);
      if (!sigma || !(*sigma > 0.0) || !number_problem(*sigma).empty())
        r.fail("check_uncertainties", fmt::format("'{}' needs a positive number", name));
      c.check_uncertainties[name] = *sigma;
    }
  }
  c.loss = r.choice("loss", {"none", "huber", "cauchy"}, "none");
  if (r.has("loss_scale")) c.loss_scale = r.positive("loss_scale");
  if (r.has("derivative_step")) {
    c.derivative_step = r.positive("derivative_step");
    if (c.derivative_step > 0.1)
      r.fail("derivative_step", "must be at most 0.1 (relative in log space; of the range on a linear scale)");
  }
  c.derivatives = r.choice("derivatives", {"auto", "analytic", "numeric"}, "auto");
  if (r.has("function_tolerance")) {
    c.function_tolerance = r.positive("function_tolerance");
    if (c.function_tolerance >= 0.1) r.fail("function_tolerance", "must be below 0.1 (relative change of the cost)");
  }
  if (const auto n = r.optional_integer("starts")) {
    if (*n < 1 || *n > 100) r.fail("starts", "must lie in [1, 100]");
    c.starts = static_cast<int>(*n);
  }
  if (const auto n = r.optional_integer("threads")) {
    if (*n < 1 || *n > 1024)
      r.fail("threads", "must lie in [1, 1024] (starts solved at once; omit it for one per core)");
    c.threads = static_cast<int>(*n);
  }
  if (const auto n = r.optional_integer("seed", 0, 4294967295L)) {
    c.seed = static_cast<unsigned>(*n);
  }
  if (r.has("cross_check_bands")) {
    c.cross_check_bands = r.boolean("cross_check_bands", false);
    if (!r.has("cross_check"))
      r.fail("cross_check_bands", "writes the cross-check's tables with bands: give cross_check too");
  }
  if (r.has("cross_check")) {
    c.cross_check = r.input_file("cross_check", file.parent_path());
    if (const std::string why = file_problem(c.cross_check); !why.empty())
      r.fail("cross_check", fmt::format("no case file {} ({})", c.cross_check.string(), why));
    std::error_code ec;
    if (std::filesystem::equivalent(c.cross_check, file, ec))
      r.fail("cross_check", "names this case itself; a cross-check is another case the identified values must predict");
  }
  if (const auto it = r.optional_integer("max_iterations")) {
    if (*it < 1) r.fail("max_iterations", "must be >= 1");
    c.max_iterations = static_cast<int>(*it);
  }
  if (const auto level = r.optional_number("band_level")) {
    if (!(*level > 0.0 && *level < 1.0))
      r.fail("band_level", fmt::format("a band's probability lies in (0, 1), found {}", *level));
    c.band_level = *level;
  }
  if (const toml::table* s = r.optional_table("sampler")) c.sampler = parse_sampler(*s, r.path() + ".sampler", file, c);
  r.finish();
  return c;
}

namespace {

void require_linked_cases(const std::filesystem::path& file, const CaseSpec& spec,
                          const std::optional<CalibrationSpec>& calibration, std::set<std::filesystem::path>& seen) {
  require_check_references(spec.checks);
  std::vector<std::filesystem::path> linked;
  for (const CheckSpec& c : spec.checks)
    if (!c.reference_case.empty()) linked.push_back(c.reference_case);
  if (calibration && !calibration->cross_check.empty()) linked.push_back(calibration->cross_check);
  for (const std::filesystem::path& other : linked) {
    std::error_code ec;
    const std::filesystem::path id = std::filesystem::weakly_canonical(other, ec);
    if (!seen.insert(ec ? other : id).second) continue;  // read once, and no cycle
    try {
      const toml::table table = read_case_table(other);
      const CaseSpec other_spec = parse_case_table(table, other);
      require_linked_cases(other, other_spec, parse_calibration(table, other, other_spec), seen);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: the linked case {}: {}", file.string(), other.string(), e.what()));
    }
  }
}

}  // namespace

void require_linked_cases(const std::filesystem::path& file, const CaseSpec& spec,
                          const std::optional<CalibrationSpec>& calibration) {
  std::error_code ec;
  std::set<std::filesystem::path> seen{std::filesystem::weakly_canonical(file, ec)};
  require_linked_cases(file, spec, calibration, seen);
}

}  // namespace bb
