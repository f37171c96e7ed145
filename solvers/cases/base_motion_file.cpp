#include "cases/base_motion_file.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <complex>
#include <string>

#include "common/constants.hpp"
#include "common/csv_reader.hpp"
#include "identify/measured_data.hpp"

namespace bb {
namespace {

constexpr double kNoiseFloor = 1e-3;  // harmonics below it relative to the first are left out
constexpr double kSpacingTolerance = 1e-6;
constexpr size_t kMaxSamples = 10'000'000;  // 80 MB of samples: far beyond a synchronously averaged period

struct Column {
  std::string name;
  Unit unit;
};

Column header_cell(const LineSource& in, std::string_view cell) {
  const auto open = cell.find('['), close = cell.rfind(']');
  if (open == std::string_view::npos || close == std::string_view::npos || close < open)
    in.fail(fmt::format("header cell '{}' must be 'name [unit]': time [s], acceleration [m/s^2]", cell));
  const std::string name(trim(cell.substr(0, open)));
  const std::string symbol(trim(cell.substr(open + 1, close - open - 1)));
  const std::optional<Unit> unit = parse_unit(symbol);
  if (!unit) in.fail(fmt::format("column '{}': unknown unit '{}' ({})", name, symbol, known_unit_symbols()));
  const Dimension wanted = name == "time" ? Dimension::time : Dimension::acceleration;
  if (name != "time" && name != "acceleration")
    in.fail(fmt::format("unknown column '{}': a base motion's period has the columns time and acceleration", name));
  if (unit->dimension != wanted)
    in.fail(fmt::format("column '{}' needs a unit of {}, found '{}' ({})", name, dimension_name(wanted), symbol,
                        dimension_name(unit->dimension)));
  return {name, *unit};
}

double cell_value(const LineSource& in, std::string_view cell, const Column& c) {
  double v = 0.0;
  const auto [end, err] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (err != std::errc() || end != cell.data() + cell.size() || !std::isfinite(v))
    in.fail(fmt::format("column '{}': '{}' is not a finite number", c.name, cell));
  return v * c.unit.to_si;
}

}  // namespace

std::vector<BaseHarmonic> base_harmonics_from_file(TomlReader& block, const std::filesystem::path& file, int periods,
                                                   int highest_order, double& first_amplitude) {
  require_readable_file(file);
  LineSource in(file);
  const std::optional<std::string_view> head = in.next_content();
  if (!head) in.fail("no header: write time [s],acceleration [m/s^2]");
  std::vector<Column> columns;
  for (std::string_view cell : split_csv(*head)) columns.push_back(header_cell(in, cell));
  if (columns.size() != 2 || columns[0].name == columns[1].name)
    in.fail("the header must name the columns time and acceleration, once each");
  const size_t t_col = columns[0].name == "time" ? 0 : 1;
  std::vector<double> time, acceleration;
  std::vector<unsigned> lines;
  while (const std::optional<std::string_view> line = in.next_content()) {
    const std::vector<std::string_view> cells = split_csv(*line);
    if (cells.size() != 2) in.fail(fmt::format("{} cells for 2 columns", cells.size()));
    if (time.size() >= kMaxSamples) in.fail(fmt::format("more than {} samples", kMaxSamples));
    time.push_back(cell_value(in, cells[t_col], columns[t_col]));
    acceleration.push_back(cell_value(in, cells[1 - t_col], columns[1 - t_col]));
    lines.push_back(in.line_number());
  }
  const size_t n = time.size();
  const size_t needed = 2 * static_cast<size_t>(periods) * static_cast<size_t>(highest_order) + 1;
  if (n < needed)
    block.fail("file", fmt::format("{}: {} samples resolve no harmonic {} over {} period(s): give at least {}",
                                   file.string(), n, highest_order, periods, needed));
  const double dt = (time.back() - time.front()) / static_cast<double>(n - 1);
  if (!(dt > 0.0)) block.fail("file", fmt::format("{}: times must increase", file.string()));
  for (size_t j = 1; j < n; ++j)
    if (std::abs(time[j] - time[j - 1] - dt) > kSpacingTolerance * dt)
      block.fail("file", fmt::format("{}:{}: times must be uniformly spaced (step {:.9g} s, found {:.9g} s)",
                                     file.string(), lines[j], dt, time[j] - time[j - 1]));
  // Harmonic h of the period is DFT bin h * periods.
  const auto bin = [&](int h) {
    std::complex<double> c = 0.0;
    const double k = static_cast<double>(h) * periods;
    for (size_t j = 0; j < n; ++j)
      c += acceleration[j] * std::polar(1.0, -kTwoPi * k * static_cast<double>(j) / static_cast<double>(n));
    return 2.0 * c / static_cast<double>(n);
  };
  const std::complex<double> first = bin(1);
  double peak = 0.0;
  for (double a : acceleration) peak = std::max(peak, std::abs(a));
  if (!(std::abs(first) > kNoiseFloor * peak))
    block.fail("file", fmt::format("{}: its first harmonic ({:.3g} m/s^2) is lost in the signal (peak {:.3g} m/s^2): "
                                   "is `periods` the number of periods the file holds?",
                                   file.string(), std::abs(first), peak));
  first_amplitude = std::abs(first);
  std::vector<BaseHarmonic> out{BaseHarmonic{}};
  for (int h = 2; h <= highest_order; ++h) {
    const std::complex<double> c = bin(h);
    const double ratio = std::abs(c) / std::abs(first);
    if (ratio < kNoiseFloor) continue;
    double phase = std::remainder(std::arg(c) - h * std::arg(first), kTwoPi);
    out.push_back({h, ratio, phase * kDegPerRad});
  }
  return out;
}

}  // namespace bb
