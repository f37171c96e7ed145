// Synthetic measurements: a computed curve (a result table of a case run at known parameter
// values) written as a measured-data CSV (identify/measured_data.hpp) with Gaussian noise and a few
// outliers, for round-trip tests of the identification and for planning a rig test.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "identify/measured_data.hpp"
#include "results/table.hpp"

namespace bb {

struct SyntheticColumn {
  std::string data;    // data column name, e.g. "amplitude"
  std::string result;  // result column, e.g. "A.x_amp_m" (SI, or degrees for _deg)
  std::string unit;    // unit written in the header, e.g. "um"
};

struct SyntheticOptions {
  DataKind kind = DataKind::frf;
  std::vector<SyntheticColumn> columns;  // every column the kind requires
  double noise = 0.02;           // relative sigma of amplitudes (per point) and forces (of the loop's largest |force|)
  double frequency_noise = 0.0;  // relative sigma of peak frequencies
  double force_noise = 0.0;      // relative sigma of an frf file's force column (per point)
  double phase_noise = 0.0;      // sigma of phases [rad]
  int outliers = 0;              // rows whose amplitude or force is scaled by outlier_factor
  double outlier_factor = 1.3;
  unsigned seed = 1;
  int every = 1;           // keep every n-th row of the table
  std::string provenance;  // written as '#' comment lines
};

// Writes `file` with sigma columns stating the noise used (so a fit weights the points by it).
// An amplitude written in a velocity or acceleration unit (m/s, m/s^2, g, ...) from a displacement
// column is what that transducer would read: multiplied by w or w^2 at each row's frequency_hz,
// its phase column moved by +90 or +180 degrees. The force column of frf data (a stepped sine's
// force_n, taken by a fit as the excitation) gets noise only with force_noise (a response-controlled
// curve's force is the measurement).
// Throws InputError when a column is missing from the table or a unit is unknown or of the wrong
// dimension for its column.
void write_synthetic_data(const ResultTable& table, const SyntheticOptions& options, const std::filesystem::path& file);

}  // namespace bb
