// Measured curves from CSV with units in the header (see measured_data.hpp for the format).
#include "identify/measured_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/input_number.hpp"
#include "common/stepped_order.hpp"
#include "identify/uff58.hpp"

namespace bb {
namespace {

// An angle in (-pi, pi], as arg() gives it.
double wrapped_phase(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

namespace fs = std::filesystem;
using enum Dimension;

struct ColumnSpec {
  const char* name;
  std::vector<Dimension> dims;  // accepted dimensions
  bool required = false;
  bool positive = false;
  const char* sigma_of = nullptr;  // a sigma takes the dimension of this column
};

// An amplitude's dimensions: displacement or compliance as the model computes them, or what a
// velocity or acceleration transducer gives.
std::vector<Dimension> response_dims() { return {length, compliance, velocity, acceleration, mobility, accelerance}; }

// The time derivative a response dimension holds, and the displacement dimension it stands for.
std::pair<int, Dimension> response_derivative(Dimension d) {
  switch (d) {
    case velocity:
      return {1, length};
    case acceleration:
      return {2, length};
    case mobility:
      return {1, compliance};
    case accelerance:
      return {2, compliance};
    default:
      return {0, d};
  }
}

const std::vector<ColumnSpec>& column_specs(DataKind kind) {
  static const std::vector<ColumnSpec> peaks = {
      {"force", {force}, true},
      {"frequency", {frequency, dimensionless}, true},
      {"amplitude", response_dims(), true, true},
      {"amplitude_sigma", response_dims(), false, true, "amplitude"},
      {"frequency_sigma", {frequency, dimensionless}, false, true, "frequency"}};
  static const std::vector<ColumnSpec> frf = {{"frequency", {frequency, dimensionless}, true},
                                              {"amplitude", response_dims(), false, true},
                                              {"phase", {angle}},
                                              {"force", {force}, false, true},
                                              {"force_phase", {angle}},
                                              {"amplitude_sigma", response_dims(), false, true, "amplitude"},
                                              {"phase_sigma", {angle}, false, true, "phase"},
                                              {"force_sigma", {force}, false, true, "force"}};
  static const std::vector<ColumnSpec> hysteresis = {{"relative_displacement", {length}, true},
                                                     {"tangential_force", {force}, true},
                                                     {"force_sigma", {force}, false, true, "tangential_force"}};
  static const std::vector<ColumnSpec> history = {{"time", {Dimension::time}, true},
                                                  {"acceleration", {acceleration}, true}};
  switch (kind) {
    case DataKind::peaks:
      return peaks;
    case DataKind::frf:
      return frf;
    case DataKind::hysteresis:
      return hysteresis;
    case DataKind::acceleration_history:
      return history;
  }
  return frf;
}

// Appends the number in `cell` to `values`, or says what is wrong with it (empty when nothing).
// from_chars is locale-independent: a "," decimal-comma locale must not change what a file means.
std::string cell_problem(std::string_view cell, bool positive, std::vector<double>& values) {
  if (cell.empty()) return "empty cell";
  std::string_view text = cell;
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  double v = 0.0;
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (err == std::errc::result_out_of_range) return fmt::format("'{}' is out of range", cell);
  if (err != std::errc() || end != text.data() + text.size()) return fmt::format("'{}' is not a number", cell);
  if (!std::isfinite(v)) return fmt::format("'{}' is not a finite number", cell);
  if (const std::string problem = number_problem(v); !problem.empty()) return problem;
  if (positive && !(v > 0.0)) return fmt::format("'{}' must be positive", cell);
  values.push_back(v);
  return {};
}

std::string dims_text(const std::vector<Dimension>& dims) {
  std::string text = dimension_name(dims[0]);
  for (size_t i = 1; i < dims.size(); ++i)
    text += fmt::format("{}{}", i + 1 == dims.size() ? " or " : ", ", dimension_name(dims[i]));
  return text;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

struct Column {
  const ColumnSpec* spec;
  std::string name;
  Unit unit;
  std::vector<double> written;  // values as written, for messages in the file's own unit
};

constexpr double kStandardGravity = 9.80665;  // m/s^2 (CGPM 1901)

struct KnownUnit {
  std::string_view symbol;
  Dimension dimension;
  double to_si;
};

// Grouped by dimension: the message of an unknown unit lists them in this order.
constexpr KnownUnit kKnownUnits[] = {{"m", length, 1.0},
                                     {"mm", length, 1e-3},
                                     {"um", length, 1e-6},
                                     {"nm", length, 1e-9},
                                     {"N", force, 1.0},
                                     {"kN", force, 1e3},
                                     {"mN", force, 1e-3},
                                     {"Hz", frequency, 1.0},
                                     {"kHz", frequency, 1e3},
                                     {"rad/s", frequency, 1.0 / (2.0 * std::numbers::pi)},
                                     {"rpm", frequency, 1.0 / 60.0},
                                     {"deg", angle, std::numbers::pi / 180.0},
                                     {"rad", angle, 1.0},
                                     {"m/N", compliance, 1.0},
                                     {"mm/N", compliance, 1e-3},
                                     {"um/N", compliance, 1e-6},
                                     {"nm/N", compliance, 1e-9},
                                     {"N/m", stiffness, 1.0},
                                     {"N/mm", stiffness, 1e3},
                                     {"N/um", stiffness, 1e6},
                                     {"s", time, 1.0},
                                     {"ms", time, 1e-3},
                                     {"-", dimensionless, 1.0},
                                     {"1", dimensionless, 1.0},
                                     {"m/s", velocity, 1.0},
                                     {"mm/s", velocity, 1e-3},
                                     {"um/s", velocity, 1e-6},
                                     {"m/s^2", acceleration, 1.0},
                                     {"mm/s^2", acceleration, 1e-3},
                                     {"g", acceleration, kStandardGravity},
                                     {"m/s/N", mobility, 1.0},
                                     {"mm/s/N", mobility, 1e-3},
                                     {"m/s^2/N", accelerance, 1.0},
                                     {"g/N", accelerance, kStandardGravity}};

}  // namespace

std::string known_unit_symbols() {
  std::string text(kKnownUnits[0].symbol);
  for (size_t i = 1; i < std::size(kKnownUnits); ++i) {
    const bool same_dimension = kKnownUnits[i].dimension == kKnownUnits[i - 1].dimension;
    text += fmt::format("{}{}", same_dimension ? " " : ", ", kKnownUnits[i].symbol);
  }
  return text + " (u also as the micro sign)";
}

const char* dimension_name(Dimension d) {
  switch (d) {
    case length:
      return "length";
    case force:
      return "force";
    case frequency:
      return "frequency";
    case angle:
      return "angle";
    case compliance:
      return "compliance";
    case stiffness:
      return "stiffness";
    case time:
      return "time";
    case dimensionless:
      return "dimensionless";
    case velocity:
      return "velocity";
    case acceleration:
      return "acceleration";
    case mobility:
      return "mobility";
    case accelerance:
      return "accelerance";
  }
  return "?";
}

const char* data_kind_name(DataKind k) {
  switch (k) {
    case DataKind::peaks:
      return "peaks";
    case DataKind::frf:
      return "frf";
    case DataKind::hysteresis:
      return "hysteresis";
    case DataKind::acceleration_history:
      return "acceleration_history";
  }
  return "?";
}

std::optional<Unit> parse_unit(std::string_view symbol) {
  // The micro sign (U+00B5) and the Greek mu (U+03BC) look alike; both mean "u".
  std::string_view micro_rest;
  for (const std::string_view micro : {"\xC2\xB5", "\xCE\xBC"})
    if (symbol.starts_with(micro)) micro_rest = symbol.substr(micro.size());
  for (const KnownUnit& k : kKnownUnits)
    if (micro_rest.empty() ? k.symbol == symbol : k.symbol.starts_with('u') && k.symbol.substr(1) == micro_rest)
      return Unit{std::string(symbol), k.dimension, k.to_si};
  return std::nullopt;
}

std::optional<Dimension> column_dimension(std::string_view column) {
  // Longest suffixes first: "_n_per_m" also ends in "_m", "_m_per_n" in "_n".
  static constexpr std::pair<std::string_view, Dimension> suffixes[] = {
      {"_n_per_m", stiffness}, {"_per_n", compliance}, {"_hz", frequency}, {"_deg", angle},
      {"_rad", angle},         {"_m", length},         {"_n", force},      {"_s", time}};
  for (const auto& [suffix, dim] : suffixes)
    if (column.ends_with(suffix)) return dim;
  return std::nullopt;
}

double column_to_si(std::string_view column) { return column.ends_with("_deg") ? std::numbers::pi / 180.0 : 1.0; }

const Eigen::VectorXd& MeasuredData::column(const std::string& name) const {
  const auto it = columns.find(name);
  if (it == columns.end()) throw std::out_of_range(fmt::format("{}: no column '{}'", file.string(), name));
  return it->second;
}

std::string MeasuredData::where(Eigen::Index row) const {
  return fmt::format("{}:{}", file.string(), lines.at(static_cast<size_t>(row)));
}

MeasuredData read_measured_data(const fs::path& file, DataKind kind, const MeasuredReadOptions& options) {
  const std::string fname = file.string();
  if (is_universal_file(file)) {
    if (kind != DataKind::frf)
      throw InputError(
          fmt::format("{}: a Universal File (dataset 58) holds an FRF; give kind = \"frf\" or a CSV file "
                      "for {} data",
                      fname, data_kind_name(kind)));
    return read_uff58_frf(file);
  }
  const auto fail = [&](unsigned line, const std::string& what) {
    return InputError(fmt::format("{}:{}: {}", fname, line, what));
  };
  LineSource in(file);
  const auto next = [&] { return in.next_content(); };

  const auto& specs = column_specs(kind);
  const auto header = next();
  if (!header) throw InputError(fmt::format("{}: no header line (the file is empty or only comments)", fname));
  const unsigned header_line = in.line_number();
  std::vector<Column> cols;
  std::vector<std::string> names;
  for (std::string_view cell : split_csv(*header)) {
    const auto open = cell.find('[');
    const std::string name(trim(cell.substr(0, open)));
    if (name.empty()) throw fail(header_line, fmt::format("header cell '{}' has no column name", cell));
    if (open == std::string_view::npos || !cell.ends_with(']'))
      throw fail(header_line,
                 fmt::format("column '{}' has no '[unit]' ('{}'); write it as '{} [<unit>]'", name, cell, name));
    const std::string_view symbol = trim(cell.substr(open + 1, cell.size() - open - 2));
    const ColumnSpec* spec = nullptr;
    for (const auto& s : specs)
      if (name == s.name) spec = &s;
    if (!spec) {
      std::vector<std::string> known;
      for (const auto& s : specs) known.emplace_back(s.name);
      throw fail(header_line,
                 fmt::format("unknown column '{}'; a {} file has: {}", name, data_kind_name(kind), join_names(known)));
    }
    for (const auto& c : cols)
      if (c.name == name) throw fail(header_line, fmt::format("column '{}' appears twice", name));
    const auto unit = parse_unit(symbol);
    if (!unit)
      throw fail(header_line,
                 fmt::format("column '{}': unknown unit '{}' (known: {})", name, symbol, known_unit_symbols()));
    if (std::find(spec->dims.begin(), spec->dims.end(), unit->dimension) == spec->dims.end())
      throw fail(header_line, fmt::format("column '{}' has unit '{}' ({}); it needs a {} unit", name, symbol,
                                          dimension_name(unit->dimension), dims_text(spec->dims)));
    cols.push_back({spec, name, *unit, {}});
    names.push_back(name);
  }
  const auto find = [&](std::string_view name) -> const Column* {
    for (const auto& c : cols)
      if (c.name == name) return &c;
    return nullptr;
  };
  for (const auto& s : specs)
    if (s.required && !find(s.name))
      throw fail(header_line, fmt::format("missing column '{} [<{} unit>]'; the file has: {}", s.name,
                                          dims_text(s.dims), join_names(names)));
  if (kind == DataKind::frf && !find("amplitude") && !find("phase"))
    throw fail(header_line, fmt::format("missing column 'amplitude [<{} unit>]' (or 'phase [<angle unit>]' for a "
                                        "curve of phases alone); the file has: {}",
                                        dims_text(response_dims()), join_names(names)));
  const bool ratios = find("frequency") && find("frequency")->unit.dimension == dimensionless;
  if (ratios && !options.natural_frequency_hz)
    throw fail(header_line,
               fmt::format("column 'frequency' holds ratios ('{}'): give the natural frequency they are ratios to "
                           "(natural_frequency_hz in the case block that names the file)",
                           find("frequency")->unit.symbol));
  for (const auto& c : cols) {
    if (!c.spec->sigma_of) continue;
    const Column* of = find(c.spec->sigma_of);
    if (!of) throw fail(header_line, fmt::format("column '{}' needs the column '{}'", c.name, c.spec->sigma_of));
    if (of->unit.dimension != c.unit.dimension)
      throw fail(header_line, fmt::format("column '{}' has unit '{}' ({}); it needs a {} unit, like column '{}'",
                                          c.name, c.unit.symbol, dimension_name(c.unit.dimension),
                                          dimension_name(of->unit.dimension), of->name));
  }

  MeasuredData data{file, kind, {}, {}, {}};
  while (const auto line = next()) {
    const unsigned at = in.line_number();
    const auto cells = split_csv(*line);
    if (cells.size() != cols.size())
      throw fail(at, fmt::format("{} cells where the header (line {}) has {}: {}", cells.size(), header_line,
                                 cols.size(), join_names(names)));
    for (size_t j = 0; j < cols.size(); ++j) {
      const std::string why = cell_problem(cells[j], cols[j].spec->positive, cols[j].written);
      if (!why.empty()) throw fail(at, fmt::format("column '{}': {}", cols[j].name, why));
    }
    data.lines.push_back(static_cast<int>(at));
  }

  const size_t n = data.lines.size();
  const size_t min_rows = kind == DataKind::hysteresis ? 8 : kind == DataKind::acceleration_history ? 2 : 1;
  if (n < min_rows)
    throw fail(header_line, fmt::format("{} data rows; a {} file needs at least {}{}", n, data_kind_name(kind),
                                        min_rows, kind == DataKind::hysteresis ? " (one loop, in time order)" : ""));
  const auto line_of = [&](size_t r) { return static_cast<unsigned>(data.lines[r]); };
  if (kind == DataKind::frf) {
    // One stepped sine: up (increasing) or down (decreasing), as the rig stepped it.
    const Column& f = *find("frequency");
    if (const auto b = first_unstepped(f.written)) {
      const size_t r = b->index;
      throw fail(line_of(r), fmt::format("frequency {} {} is not {} the previous row's {} {} (rows must follow one "
                                         "stepped sine, up or down, without repeated frequencies)",
                                         f.written[r], f.unit.symbol, b->down ? "below" : "above", f.written[r - 1],
                                         f.unit.symbol));
    }
    if (find("force_phase") && !find("force"))
      throw fail(header_line, "column 'force_phase' needs the column 'force' (the force it is the phase of)");
    if (find("force_phase") && !find("phase"))
      throw fail(header_line,
                 "column 'force_phase' needs the column 'phase' (the response phase it is the reference of)");
  }
  if (kind == DataKind::peaks) {
    const Column& f = *find("force");
    for (size_t r = 1; r < n; ++r)
      for (size_t q = 0; q < r; ++q)
        if (f.written[r] == f.written[q])
          throw fail(line_of(r), fmt::format("column 'force': level {} {} repeats the level of line {} (one row per "
                                             "force level)",
                                             f.written[r], f.unit.symbol, line_of(q)));
  }

  for (auto& c : cols) {
    data.columns[c.name] =
        Eigen::Map<const Eigen::VectorXd>(c.written.data(), static_cast<Eigen::Index>(n)) * c.unit.to_si;
    data.units[c.name] = c.unit;
  }
  if (ratios) {
    for (const char* name : {"frequency", "frequency_sigma"}) {
      if (!data.has(name)) continue;
      data.columns[name] *= *options.natural_frequency_hz;
      data.units[name].dimension = frequency;
    }
    data.frequency_ratio = true;
  }
  if (kind != DataKind::hysteresis) amplitude_to_displacement(data);
  if (data.has("force_phase")) phase_to_force(data);
  return data;
}

void phase_to_displacement(MeasuredData& data, int derivative) {
  data.derivative = derivative;
  if (data.has("phase"))
    for (double& phase : data.columns["phase"]) phase = wrapped_phase(phase - derivative * 0.5 * std::numbers::pi);
}

void phase_to_force(MeasuredData& data) {
  const Eigen::VectorXd& force_phase = data.columns.at("force_phase");
  Eigen::VectorXd& phase = data.columns.at("phase");
  for (Eigen::Index r = 0; r < phase.size(); ++r) phase[r] = wrapped_phase(phase[r] - force_phase[r]);
}

void amplitude_to_displacement(MeasuredData& data) {
  if (!data.has("amplitude")) return;  // phases alone: the case says what they are of
  const auto [k, displacement] = response_derivative(data.units.at("amplitude").dimension);
  data.derivative = k;
  if (k == 0) return;
  const Eigen::ArrayXd w = 2.0 * std::numbers::pi * data.column("frequency").array();
  for (const char* name : {"amplitude", "amplitude_sigma"}) {
    if (!data.has(name)) continue;
    data.columns[name] = (data.columns[name].array() / w.pow(k)).matrix();
    data.units[name].dimension = displacement;
  }
  phase_to_displacement(data, k);
}

}  // namespace bb
