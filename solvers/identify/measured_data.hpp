// Measured (or reference) curves to fit, read from CSV files whose header states each column's
// unit: `frequency [Hz],amplitude [um/N],phase [deg]`. Values are converted to SI on reading.
// Lines starting with '#' are comments (provenance: rig, date, how the data were produced); blank
// lines are skipped. Line numbers in messages count every physical line of the file (1-based).
//
// Data kinds and their columns (any order; unknown columns are refused, so a typo is caught):
//   peaks       force [force], frequency [frequency], amplitude [length or compliance],
//               optional amplitude_sigma, frequency_sigma (same dimension as their column).
//               One row per force level; levels must be distinct.
//   frf         frequency [frequency], amplitude [length or compliance] and/or phase [angle],
//               amplitude_sigma, phase_sigma, force [force] (the force amplitude each point was
//               measured at: a force-controlled rig's drifts; a response-controlled rig's is the
//               measurement, with force_sigma) and force_phase [angle] (the force's
//               phase on the response's clock; the phase is then read as the response's phase to
//               the force). One stepped sine: frequencies strictly increasing (up) or strictly
//               decreasing (down).
//   hysteresis  relative_displacement [length], tangential_force [force], optional force_sigma
//               [force]. Rows in time order over the loop; at least 8 rows.
//   acceleration_history  time [time], acceleration [acceleration]: a signal in time order, e.g.
//               a shaker table's accelerometer over whole periods (cases/base_motion_file.hpp);
//               at least 2 rows.
// The amplitude of frf and peaks data (and its sigma) may also be a velocity or an acceleration
// (or either per newton): each row is converted through its own harmonic, |x| = |v| / w = |a| / w^2
// with w = 2 pi f, and the phase moved by -90 or -180 degrees (v = i w x, a = -w^2 x for
// x e^{i w t}; wrapped to (-180, 180]), so the data hold displacement (or compliance) as the model
// computes it. MeasuredData::derivative says which.
// A frf file of phases alone (no amplitude column) keeps them as written: what they are the phase
// of (displacement, velocity or acceleration) is the case's to say (phase_to_displacement).
// Frequencies may be ratios to a natural frequency (unit "-" or "1"; frequency_sigma alike): the
// reader then needs MeasuredReadOptions::natural_frequency_hz and holds them in Hz.
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

// velocity, acceleration, mobility (velocity per force) and accelerance (acceleration per force):
// a rig's response as its transducer measured it; read into the displacement they imply (below).
enum class Dimension {
  length,
  force,
  frequency,
  angle,
  compliance,
  stiffness,
  time,
  dimensionless,
  velocity,
  acceleration,
  mobility,
  accelerance
};

const char* dimension_name(Dimension d);  // "length", "force", ...

struct Unit {
  std::string symbol;  // as written, e.g. "um/N"
  Dimension dimension = Dimension::dimensionless;
  double to_si = 1.0;  // SI value = written value * to_si (deg -> rad, Hz stays Hz, rad/s -> Hz)
};

// Known symbols: m mm um µm nm | N kN mN | Hz kHz rad/s rpm | deg rad | m/N mm/N um/N µm/N nm/N |
// N/m N/mm N/um | s ms | - 1 | m/s mm/s um/s | m/s^2 mm/s^2 g | m/s/N mm/s/N | m/s^2/N g/N (µ as
// the micro sign or the Greek mu; g the standard 9.80665 m/s^2). Frequencies are kept in Hz (rad/s
// and rpm are converted to Hz), angles in radians. std::nullopt for an unknown symbol.
std::optional<Unit> parse_unit(std::string_view symbol);
// The symbols parse_unit knows, grouped by dimension, for messages.
std::string known_unit_symbols();

// Dimension of a result-table column from its name's unit suffix, the project's convention:
// _hz frequency, _m length, _n force, _deg and _rad angle, _per_n and _m_per_n compliance,
// _n_per_m stiffness, _s time. std::nullopt when the name carries no known suffix.
// Note: a _deg column holds degrees, so its SI factor is pi/180 (column_to_si gives it).
std::optional<Dimension> column_dimension(std::string_view column);
double column_to_si(std::string_view column);  // 1 except pi/180 for _deg

enum class DataKind { peaks, frf, hysteresis, acceleration_history };

const char* data_kind_name(DataKind k);  // "peaks", "frf", "hysteresis", "acceleration_history"

struct MeasuredData {
  std::filesystem::path file;
  DataKind kind = DataKind::frf;
  std::map<std::string, Eigen::VectorXd> columns;  // SI values by column name (without the unit)
  std::map<std::string, Unit> units;               // as written in the header
  std::vector<int> lines;                          // file line (1-based) of each row, for messages
  // The time derivative the file's amplitude held (0 displacement, 1 velocity, 2 acceleration),
  // converted on reading; units keeps the symbol as written, with the displacement's dimension.
  int derivative = 0;
  // The frequency column was written as ratios to MeasuredReadOptions::natural_frequency_hz.
  bool frequency_ratio = false;

  Eigen::Index rows() const { return static_cast<Eigen::Index>(lines.size()); }
  bool has(const std::string& column) const { return columns.count(column) > 0; }
  const Eigen::VectorXd& column(const std::string& name) const;  // throws std::out_of_range
  std::string where(Eigen::Index row) const;                     // "file:line"
};

// Reads and validates a file of the given kind. Throws InputError naming the file and line (and
// the column) on: a missing file, a header cell without "[unit]", an unknown unit, a unit of the
// wrong dimension, an unknown, duplicated or missing required column, a row with too few or too
// many cells, an empty, non-numeric, NaN or infinite cell, a non-positive amplitude or sigma,
// frequencies neither strictly increasing nor strictly decreasing (frf), force_phase without force
// and phase (frf), repeated force levels (peaks), too few rows.
struct MeasuredReadOptions {
  // The natural frequency [Hz] a frequency column of ratios is relative to; a file of ratios
  // without it is refused.
  std::optional<double> natural_frequency_hz;
};
MeasuredData read_measured_data(const std::filesystem::path& file, DataKind kind,
                                const MeasuredReadOptions& options = {});

// A velocity or acceleration amplitude (by units["amplitude"]) and its sigma divided by w^k row by
// row, the phase moved by -k 90 degrees, the unit's dimension set to the displacement's; sets
// `derivative`. Nothing for a displacement. The CSV and Universal File readers call it.
void amplitude_to_displacement(MeasuredData& data);
// The phase of a frf file of phases alone, given as the phase of the `derivative`-th time
// derivative (0 displacement, 1 velocity, 2 acceleration), moved by -derivative 90 degrees to the
// displacement's; sets `derivative`.
void phase_to_displacement(MeasuredData& data, int derivative);

// The column phase made the response's phase to the force: phase - force_phase, wrapped to
// (-pi, pi], as the model computes it. The CSV reader (a force_phase column) and the Universal
// File reader (a force record) call it.
void phase_to_force(MeasuredData& data);

}  // namespace bb
