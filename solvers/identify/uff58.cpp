#include "identify/uff58.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/stepped_order.hpp"
#include "common/user_text.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// Characters [from, from + width) of a fixed-format record, trimmed (empty past the line's end).
std::string field(const std::string& line, size_t from, size_t width) {
  return from < line.size() ? std::string(trim(std::string_view(line).substr(from, width))) : std::string();
}

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

std::optional<double> number(const std::string& s) {
  std::string t = s;
  std::replace(t.begin(), t.end(), 'D', 'E');  // Fortran double-precision exponents
  double v = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<long> integer(const std::string& s) {
  long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

struct Axis {
  long type = 0;
  std::string label, units;
};

}  // namespace

bool is_universal_file(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".uff" || ext == ".unv";
}

std::vector<Uff58Function> read_uff58(const fs::path& file) {
  if (file_problem(file) == "it is a directory") throw InputError(fmt::format("{}: is a folder, not a Universal File", file.string()));
  require_readable_file(file);
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open", file.string()));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  std::vector<Uff58Function> out;
  size_t i = 0;
  int dataset = 0;
  while (i + 1 < lines.size()) {
    if (trim(lines[i]) != "-1") {
      ++i;
      continue;
    }
    const std::string_view kind = trim(lines[i + 1]);
    const size_t start = i;
    // The dataset's end: the next "-1" line.
    size_t end = i + 2;
    while (end < lines.size() && trim(lines[end]) != "-1") ++end;
    if (kind != "58" && kind != "58b") {
      i = end + 1;
      continue;
    }
    ++dataset;
    const auto fail = [&](size_t at, int record, const std::string& what) {
      return InputError(printable(fmt::format("{}:{}: dataset 58 #{} (from line {}), record {}: {}", file.string(),
                                              at + 1, dataset, start + 1, record, what)));
    };
    if (kind == "58b") throw fail(i + 1, 0, "binary dataset 58b is not read; export ASCII dataset 58");
    if (end >= lines.size()) throw fail(end - 1, 12, "the dataset has no closing '-1' line");
    const size_t r1 = i + 2;  // record 1
    if (end < r1 + 12) throw fail(end, static_cast<int>(end - r1) + 1, "the dataset ends before record 12");
    Uff58Function f;
    f.line = static_cast<int>(start + 1);
    for (int r = 0; r < 5; ++r) f.id_lines.emplace_back(trim(lines[r1 + static_cast<size_t>(r)]));
    // Record 6: Format(2(I5,I10),2(1X,10A1,I10,I4)).
    const std::string& r6 = lines[r1 + 5];
    const auto r6_int = [&](size_t from, size_t width, const char* what) {
      const auto v = integer(field(r6, from, width));
      if (!v) throw fail(r1 + 5, 6, fmt::format("{} '{}' is not an integer", what, field(r6, from, width)));
      return *v;
    };
    f.function_type = static_cast<int>(r6_int(0, 5, "function type"));
    f.response_node = r6_int(41, 10, "response node");
    f.response_direction = static_cast<int>(r6_int(51, 4, "response direction"));
    f.reference_node = r6_int(66, 10, "reference node");
    f.reference_direction = static_cast<int>(r6_int(76, 4, "reference direction"));
    // Record 7: Format(3I10,3E13.5).
    const auto r7 = tokens(lines[r1 + 6]);
    if (r7.size() < 5) throw fail(r1 + 6, 7, fmt::format("{} fields where 6 are expected", r7.size()));
    const auto data_type = integer(r7[0]), count = integer(r7[1]), spacing = integer(r7[2]);
    const auto first = number(r7[3]), step = number(r7[4]);
    if (!data_type || (*data_type != 2 && *data_type != 4 && *data_type != 5 && *data_type != 6))
      throw fail(r1 + 6, 7, fmt::format("ordinate data type '{}' is not 2, 4 (real) or 5, 6 (complex)", r7[0]));
    if (!count || *count < 1 || *count > 10000000)
      throw fail(r1 + 6, 7, fmt::format("number of values '{}' is not in [1, 1e7]", r7[1]));
    if (!spacing || (*spacing != 0 && *spacing != 1))
      throw fail(r1 + 6, 7, fmt::format("abscissa spacing '{}' is not 0 (uneven) or 1 (even)", r7[2]));
    if (!first || !step) throw fail(r1 + 6, 7, "abscissa minimum or increment is not a finite number");
    // Records 8-11: Format(I10,3I5,2(1X,20A1)).
    std::array<Axis, 3> axes;
    for (int a = 0; a < 3; ++a) {
      const std::string& r = lines[r1 + 7 + static_cast<size_t>(a)];
      const auto type = integer(field(r, 0, 10));
      if (!type) throw fail(r1 + 7 + static_cast<size_t>(a), 8 + a, "specific data type is not an integer");
      axes[static_cast<size_t>(a)] = {*type, field(r, 26, 20), field(r, 47, 20)};
    }
    // Record 12: the values, blank-separated, until the closing "-1".
    const bool complex = *data_type >= 5, even = *spacing == 1;
    const size_t per_point = (complex ? 2 : 1) + (even ? 0 : 1);
    std::vector<double> numbers;
    std::vector<size_t> number_line;
    for (size_t l = r1 + 11; l < end; ++l)
      for (const std::string& t : tokens(lines[l])) {
        const auto v = number(t);
        if (!v) throw fail(l, 12, fmt::format("value '{}' is not a finite number", t));
        numbers.push_back(*v);
        number_line.push_back(l);
      }
    const size_t expected = static_cast<size_t>(*count) * per_point;
    if (numbers.size() != expected)
      throw fail(r1 + 11, 12,
                 fmt::format("{} numbers where record 7 announces {} {} values ({} numbers)", numbers.size(), *count,
                             complex ? "complex" : "real", expected));
    for (long p = 0; p < *count; ++p) {
      const size_t k = static_cast<size_t>(p) * per_point;
      f.abscissa.push_back(even ? *first + static_cast<double>(p) * *step : numbers[k]);
      const size_t v = even ? k : k + 1;
      f.values.emplace_back(numbers[v], complex ? numbers[v + 1] : 0.0);
    }
    // Units from the records: the unit labels, else the specific data types in SI.
    const auto unit_of = [&](const Axis& a, int record, size_t at) -> std::optional<Unit> {
      if (!a.units.empty() && a.units != "NONE") {
        if (auto u = parse_unit(a.units)) return u;
        throw fail(at, record, fmt::format("unit label '{}' is not a known unit", a.units));
      }
      switch (a.type) {
        case 18:
          return parse_unit("Hz");
        case 8:
          return parse_unit("m");
        case 9:
        case 13:
          return parse_unit("N");
        case 11:
          return parse_unit("m/s");
        case 12:
          return parse_unit("m/s^2");
        default:
          return std::nullopt;
      }
    };
    const auto abscissa = unit_of(axes[0], 8, r1 + 7);
    if (!abscissa || abscissa->dimension != Dimension::frequency)
      throw fail(r1 + 7, 8,
                 fmt::format("the abscissa is not a frequency (specific data type {}, unit label '{}')", axes[0].type,
                             axes[0].units));
    const auto numerator = unit_of(axes[1], 9, r1 + 8);
    const auto denominator = unit_of(axes[2], 10, r1 + 9);
    const bool force_record = numerator && numerator->dimension == Dimension::force && !denominator;
    if (!force_record &&
        (!numerator || (numerator->dimension != Dimension::length && numerator->dimension != Dimension::velocity &&
                        numerator->dimension != Dimension::acceleration)))
      throw fail(r1 + 8, 9,
                 fmt::format("the ordinate is not a displacement, velocity, acceleration or force (specific data type "
                             "{}, unit label '{}')",
                             axes[1].type, axes[1].units));
    if (denominator && denominator->dimension != Dimension::force)
      throw fail(r1 + 9, 10,
                 fmt::format("the denominator is not a force (specific data type {}, unit label '{}')", axes[2].type,
                             axes[2].units));
    f.abscissa_unit = *abscissa;
    const Dimension per_force = numerator->dimension == Dimension::velocity       ? Dimension::mobility
                                : numerator->dimension == Dimension::acceleration ? Dimension::accelerance
                                                                                  : Dimension::compliance;
    f.ordinate_unit = denominator ? Unit{numerator->symbol + "/" + denominator->symbol, per_force,
                                         numerator->to_si / denominator->to_si}
                                  : *numerator;
    out.push_back(std::move(f));
    i = end + 1;
  }
  if (out.empty()) throw InputError(fmt::format("{}: no dataset 58 (a measured function) in the file", file.string()));
  return out;
}

MeasuredData read_uff58_frf(const fs::path& file) { return uff58_frf(read_uff58(file).front(), file, 1); }

MeasuredData uff58_frf(const Uff58Function& f, const fs::path& file, int index) {
  if (f.ordinate_unit.dimension == Dimension::force)
    throw InputError(
        fmt::format("{}:{}: dataset 58 #{} is a force record (the reference channel): name it "
                    "force_dataset and the response record dataset",
                    file.string(), f.line, index));
  const Eigen::Index n = static_cast<Eigen::Index>(f.values.size());
  MeasuredData d;
  d.file = file;
  d.kind = DataKind::frf;
  Eigen::VectorXd frequency(n), amplitude(n), phase(n);
  bool complex = false;
  const std::optional<SteppedBreak> order = first_unstepped(f.abscissa);  // one stepped sine, up or down
  for (Eigen::Index i = 0; i < n; ++i) {
    const size_t k = static_cast<size_t>(i);
    frequency[i] = f.abscissa[k] * f.abscissa_unit.to_si;
    amplitude[i] = std::abs(f.values[k]) * f.ordinate_unit.to_si;
    phase[i] = std::arg(f.values[k]);
    complex = complex || f.values[k].imag() != 0.0;
    d.lines.push_back(f.line);
    const auto where = [&] {
      return fmt::format("{}:{}: dataset 58 #{}, record 12, value {}", file.string(), f.line, index, i + 1);
    };
    if (!(amplitude[i] > 0.0)) throw InputError(fmt::format("{}: the amplitude is zero", where()));
    if (order && k == order->index)
      throw InputError(
          fmt::format("{}: frequency {} Hz is not {} the previous value's {} Hz (values follow one "
                      "stepped sine, up or down, without repeated frequencies)",
                      where(), frequency[i], order->down ? "below" : "above", frequency[i - 1]));
  }
  d.columns["frequency"] = frequency;
  d.units["frequency"] = f.abscissa_unit;
  d.columns["amplitude"] = amplitude;
  d.units["amplitude"] = f.ordinate_unit;
  if (complex) {
    d.columns["phase"] = phase;
    d.units["phase"] = *parse_unit("rad");
  }
  amplitude_to_displacement(d);
  return d;
}

MeasuredData uff58_response_with_force(const Uff58Function& response, int response_index, const Uff58Function& force,
                                       int force_index, const fs::path& file) {
  const auto where = [&](const Uff58Function& f, int index) {
    return fmt::format("{}:{}: dataset 58 #{}", file.string(), f.line, index);
  };
  if (force.ordinate_unit.dimension != Dimension::force)
    throw InputError(fmt::format("{}: the force record's ordinate is {}, not a force", where(force, force_index),
                                 force.ordinate_unit.symbol));
  const Dimension d = response.ordinate_unit.dimension;
  if (d != Dimension::length && d != Dimension::velocity && d != Dimension::acceleration)
    throw InputError(
        fmt::format("{}: the response record's ordinate is {}: with a force record it must be a "
                    "displacement, velocity or acceleration, not a ratio to the force",
                    where(response, response_index), response.ordinate_unit.symbol));
  if (force.values.size() != response.values.size())
    throw InputError(
        fmt::format("{}: {} values, but the response record (dataset 58 #{}) has {}: the two records "
                    "of one stepped sine have a value at each frequency",
                    where(force, force_index), force.values.size(), response_index, response.values.size()));
  // The response as an frf of its own unit, then each point's force and the phase to it.
  MeasuredData data = uff58_frf(response, file, response_index);
  const Eigen::Index n = data.rows();
  Eigen::VectorXd force_amplitude(n), force_phase(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const size_t k = static_cast<size_t>(i);
    const double f_force = force.abscissa[k] * force.abscissa_unit.to_si;
    if (std::abs(f_force - data.column("frequency")[i]) > 1e-9 * data.column("frequency")[i])
      throw InputError(fmt::format("{}, record 12, value {}: frequency {} Hz, but the response record has {} Hz there",
                                   where(force, force_index), i + 1, f_force, data.column("frequency")[i]));
    force_amplitude[i] = std::abs(force.values[k]) * force.ordinate_unit.to_si;
    force_phase[i] = std::arg(force.values[k]);
    if (!(force_amplitude[i] > 0.0))
      throw InputError(fmt::format("{}, record 12, value {}: the force is zero", where(force, force_index), i + 1));
  }
  data.columns["force"] = force_amplitude;
  data.units["force"] = *parse_unit("N");
  data.columns["force_phase"] = force_phase;
  data.units["force_phase"] = *parse_unit("rad");
  if (!data.has("phase")) data.columns["phase"] = Eigen::VectorXd::Zero(n), data.units["phase"] = *parse_unit("rad");
  phase_to_force(data);
  return data;
}

namespace {

// One dataset 58 of complex double values at uneven abscissa: record 6's function type, and the
// ordinate's specific data type, length exponent, force exponent, label and unit (record 9), over
// a force (record 10) when `per_force`.
struct Uff58Record {
  int function_type = 4;
  long response_node = 1, reference_node = 1;
  int ordinate_type = 8, length_exponent = 1, force_exponent = 0;
  const char* label = "Displacement";
  const char* unit = "m";
  bool per_force = false;
};

void write_record(std::ofstream& out, const std::string& title, const Uff58Record& r, const Eigen::VectorXd& f,
                  const std::vector<std::complex<double>>& values) {
  const auto axis = [](int type, int length, int force, const char* label, const char* units) {
    return fmt::format("{:10d}{:5d}{:5d}{:5d} {:<20} {:<20}\n", type, length, force, 0, label, units);
  };
  out << "    -1\n    58\n";
  out << fmt::format("{}\n", title.substr(0, 80)) << "bladebench\nNONE\nNONE\nNONE\n";
  out << fmt::format("{:5d}{:10d}{:5d}{:10d} {:<10}{:10d}{:4d} {:<10}{:10d}{:4d}\n", r.function_type, 1, 1, 0, "NONE",
                     r.response_node, 1, "NONE", r.reference_node, 1);
  out << fmt::format("{:10d}{:10d}{:10d}{:13.5E}{:13.5E}{:13.5E}\n", 6, f.size(), 0, 0.0, 0.0, 0.0);
  out << axis(18, 0, 0, "Frequency", "Hz");
  out << axis(r.ordinate_type, r.length_exponent, r.force_exponent, r.label, r.unit);
  out << (r.per_force ? axis(13, 0, 1, "Force", "N") : axis(0, 0, 0, "NONE", "NONE"));
  out << axis(0, 0, 0, "NONE", "NONE");
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    const std::complex<double> v = values[static_cast<size_t>(i)];
    out << fmt::format("{:13.5E}{:20.12E}{:20.12E}\n", f[i], v.real(), v.imag());
  }
  out << "    -1\n";
}

}  // namespace

void write_uff58_frf(const MeasuredData& data, const fs::path& file, const std::string& title) {
  if (data.kind != DataKind::frf || !data.has("frequency") || !data.has("amplitude"))
    throw InputError(fmt::format("{}: a Universal File holds an FRF: frequency and amplitude", file.string()));
  const bool compliance = data.units.at("amplitude").dimension == Dimension::compliance;
  const bool with_force = data.has("force");
  if (compliance && with_force)
    throw InputError(
        fmt::format("{}: an FRF per newton with a force per point: write the response instead", file.string()));
  const Eigen::VectorXd& f = data.column("frequency");
  const Eigen::VectorXd& a = data.column("amplitude");
  const Eigen::VectorXd phase = data.has("phase") ? data.column("phase") : Eigen::VectorXd::Zero(f.size());
  const Eigen::VectorXd force_phase =
      data.has("force_phase") ? data.column("force_phase") : Eigen::VectorXd::Zero(f.size());
  std::ofstream out(file);
  if (!out) throw InputError(fmt::format("{}: cannot write", file.string()));
  std::vector<std::complex<double>> response, force;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    response.push_back(std::polar(a[i], phase[i] + force_phase[i]));
    if (with_force) force.push_back(std::polar(data.column("force")[i], force_phase[i]));
  }
  if (with_force) {  // a rig's two channels: the force (reference) record, then the response record
    write_record(out, title + " (force)", {12, 2, 2, 13, 0, 1, "Force", "N", false}, f, force);
    write_record(out, title + " (response)", {12, 1, 2, 8, 1, 0, "Displacement", "m", false}, f, response);
  } else {
    write_record(out, title, {compliance ? 4 : 1, 1, 1, 8, 1, 0, "Displacement", "m", compliance}, f, response);
  }
  if (!out) throw InputError(fmt::format("{}: write failed", file.string()));
}

}  // namespace bb
