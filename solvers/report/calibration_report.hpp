// Files written by `bladebench calibrate`: identification.csv, convergence.csv, starts.csv,
// fitted_points.csv, calibrated.toml (the case with the identified values, when the fit converged;
// else restart.toml, the values where it stopped), report.md and, for measured curves, plots of
// the fitted curves over the data.
#pragma once
#include <filesystem>

#include "identify/calibration_outcome.hpp"

namespace bb {

void write_calibration_outputs(const CalibrationOutcome& outcome, const std::filesystem::path& case_file,
                               double wall_seconds, const std::filesystem::path& out_dir, bool plots = true);

}  // namespace bb
