// A measured base acceleration over whole periods of a steady excitation (a shaker table's
// accelerometer, synchronously averaged), read into the harmonics of a base motion: a CSV file of
// the measured-data reader's kind acceleration_history (identify/measured_data.hpp: header
// `time [s],acceleration [m/s^2]`, any time or acceleration unit it knows, e.g. ms, g), rows
// uniformly spaced, the last one a step before the end of `periods` periods (the DFT's
// convention: the first sample of the next period is not repeated).
#pragma once
#include <filesystem>
#include <vector>

#include "common/toml_reader.hpp"
#include "forced/base_motion_spec.hpp"

namespace bb {

// The harmonics 1..highest_order of the file's period relative to its first (ratio rho_h, phase
// psi_h with the first's phase taken as 0: the time origin is the analysis's) and the first's
// acceleration amplitude [m/s^2] (`first_amplitude`), those of ratio
// below 1e-3 left out (the noise floor of a measured period). InputError naming the file and line,
// or the key of `block`: a missing or unknown column or unit, a non-finite cell, fewer than
// 2 periods highest_order + 1 samples, times not uniformly spaced (relative 1e-6), a first
// harmonic lost in the signal (below 1e-3 of its peak: `periods` wrong).
std::vector<BaseHarmonic> base_harmonics_from_file(TomlReader& block, const std::filesystem::path& file, int periods,
                                                   int highest_order, double& first_amplitude);

}  // namespace bb
