// The page of `bladebench compare-models`: every model form calibrated on the same data, ranked
// (identify/model_comparison.hpp), with each one's calibration report in a folder of its own and
// plots of every model's predictions over each held-out curve.
#pragma once
#include <filesystem>
#include <vector>

#include "identify/calibration_outcome.hpp"
#include "identify/model_comparison.hpp"

namespace bb {

// Writes out_dir/report.md (and its HTML twin) and out_dir/ranking.csv; the calibrations
// themselves are written by the caller under out_dir/<name>/.
void write_model_comparison(const std::vector<ModelScore>& scores, const std::vector<const CalibrationOutcome*>& outcomes,
                            const std::filesystem::path& out_dir, bool plots);

}  // namespace bb
