// Identification of numeric case values (dimensions, stiffnesses, damping ...) by weighted
// nonlinear least squares (identify/least_squares_fit.hpp; the Jacobian from the model's own
// sensitivities where an hbm analysis gives them, else central differences) against the reference
// data of chosen checks and measured curves, with an optional cross-check of the identified values
// by an independent model. Each evaluation edits the parsed case (cases/case_parameter.hpp) and
// reruns its model and analysis.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "cache/model_cache_settings.hpp"
#include "common/work_limits.hpp"
#include "identify/calibration_outcome.hpp"
#include "identify/least_squares_fit.hpp"

namespace bb {

// Where a fit starts other than at the case file's values: `settings` as `run --set`
// (dotted.key=VALUE), then every [calibration] parameter's value read from `restart_from` (the
// calibrated.toml or restart.toml of an earlier fit), to continue that fit.
struct CalibrationStartEdits {
  std::vector<std::string> settings;
  std::filesystem::path restart_from;
};

// Throws InputError for a malformed case, [calibration] or data file; a failed fit is reported in
// the outcome. `progress` receives every trust-region iteration (none when empty); every evaluation
// of the model (and the cross-check) is held to `limits` before it runs, and takes its modes and
// reductions through the model cache in `cache`, when given.
CalibrationOutcome calibrate_case(const std::filesystem::path& case_file, const FitProgress& progress = {},
                                  const WorkLimits& limits = {}, const ModelCacheSettings* cache = nullptr,
                                  const CalibrationStartEdits& edits = {});

}  // namespace bb
