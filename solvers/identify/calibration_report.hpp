// Files written by `bladebench calibrate`: identification.csv, convergence.csv,
// calibrated.toml (the case with the identified values) and report.md.
#pragma once
#include <filesystem>

#include "identify/calibrate_case.hpp"

namespace bb {

void write_calibration_outputs(const CalibrationOutcome& outcome, const std::filesystem::path& case_file,
                               double wall_seconds, const std::filesystem::path& out_dir);

}  // namespace bb
