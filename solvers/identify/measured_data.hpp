// Measured (or reference) curves to fit, read from CSV files whose header states each column's
// unit: `frequency [Hz],amplitude [um/N],phase [deg]`. Values are converted to SI on reading.
// Lines starting with '#' are comments (provenance: rig, date, how the data were produced); blank
// lines are skipped. Line numbers in messages count every physical line of the file (1-based).
//
// Data kinds and their columns (any order; unknown columns are refused, so a typo is caught):
//   peaks       force [force], frequency [frequency], amplitude [length or compliance],
//               optional amplitude_sigma, frequency_sigma (same dimension as their column).
//               One row per force level; levels must be distinct.
//   frf         frequency [frequency], amplitude [length or compliance], optional phase [angle],
//               amplitude_sigma, phase_sigma. Frequencies strictly increasing (no duplicates).
//   hysteresis  relative_displacement [length], tangential_force [force], optional force_sigma
//               [force]. Rows in time order over the loop; at least 8 rows.
// A sigma column needs its column (phase_sigma needs phase; force_sigma's is tangential_force) and
// must have the same dimension as it. peaks and frf need at least one row.
// Every cell must be a finite number; amplitudes and sigmas must be positive.
#pragma once
#include <Eigen/Dense>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bb {

enum class Dimension { length, force, frequency, angle, compliance, stiffness, time, dimensionless };

const char* dimension_name(Dimension d);  // "length", "force", ...

struct Unit {
  std::string symbol;  // as written, e.g. "um/N"
  Dimension dimension = Dimension::dimensionless;
  double to_si = 1.0;  // SI value = written value * to_si (deg -> rad, Hz stays Hz, rad/s -> Hz)
};

// Known symbols: m mm um µm nm | N kN mN | Hz kHz rad/s rpm | deg rad | m/N mm/N um/N µm/N nm/N |
// N/m N/mm N/um | s ms | - 1 (µ as the micro sign or the Greek mu). Frequencies are kept in Hz
// (rad/s and rpm are converted to Hz), angles in radians. std::nullopt for an unknown symbol.
std::optional<Unit> parse_unit(std::string_view symbol);

// Dimension of a result-table column from its name's unit suffix, the project's convention:
// _hz frequency, _m length, _n force, _deg and _rad angle, _per_n and _m_per_n compliance,
// _n_per_m stiffness, _s time. std::nullopt when the name carries no known suffix.
// Note: a _deg column holds degrees, so its SI factor is pi/180 (column_to_si gives it).
std::optional<Dimension> column_dimension(std::string_view column);
double column_to_si(std::string_view column);  // 1 except pi/180 for _deg

enum class DataKind { peaks, frf, hysteresis };

const char* data_kind_name(DataKind k);  // "peaks", "frf", "hysteresis"

struct MeasuredData {
  std::filesystem::path file;
  DataKind kind = DataKind::frf;
  std::map<std::string, Eigen::VectorXd> columns;  // SI values by column name (without the unit)
  std::map<std::string, Unit> units;               // as written in the header
  std::vector<int> lines;                          // file line (1-based) of each row, for messages

  Eigen::Index rows() const { return static_cast<Eigen::Index>(lines.size()); }
  bool has(const std::string& column) const { return columns.count(column) > 0; }
  const Eigen::VectorXd& column(const std::string& name) const;  // throws std::out_of_range
  std::string where(Eigen::Index row) const;                     // "file:line"
};

// Reads and validates a file of the given kind. Throws InputError naming the file and line (and
// the column) on: a missing file, a header cell without "[unit]", an unknown unit, a unit of the
// wrong dimension, an unknown, duplicated or missing required column, a row with too few or too
// many cells, an empty, non-numeric, NaN or infinite cell, a non-positive amplitude or sigma,
// unsorted or duplicated frequencies (frf), repeated force levels (peaks), too few rows.
MeasuredData read_measured_data(const std::filesystem::path& file, DataKind kind);

}  // namespace bb
