// What the [fidelity] section of a case asks for: the accuracy its results need, and the settings
// (fidelity axes) the harness may climb, cheapest first, to meet it (`run --fidelity auto`).
#pragma once
#include <string>
#include <vector>

#include "common/source_location.hpp"

namespace bb {

// The settings a fidelity axis can vary; each applies to the analyses named beside it.
enum class FidelitySetting {
  harmonics,         // analysis.harmonics (hbm)
  time_samples,      // analysis.time_samples (hbm): AFT samples per period
  reduced_modes,     // analysis.model.modes (hbm): fixed-interface modes of the Craig-Bampton model
  steps_per_period,  // analysis.steps_per_period (time)
  steady_tolerance,  // analysis.steady_tolerance (time): levels from loose to tight
  mesh_refinement,   // mesh.refinement: a factor on the divisions of the mesh (mapped_quad, hex_blocks, two_blade)
};

struct FidelityAxisSpec {
  std::string path;  // as written, e.g. "analysis.harmonics"
  FidelitySetting setting = FidelitySetting::harmonics;
  std::vector<double> levels;  // cheapest first
  SourceLocation at;
};

// How a run picks its settings: the case's own (fixed), the cheapest or the finest level of every
// axis, or the cheapest combination whose estimated error meets the target (automatic).
enum class FidelityMode { fixed, fast, automatic, reference };
inline constexpr FidelityMode kFidelityModes[] = {FidelityMode::fixed, FidelityMode::fast, FidelityMode::automatic,
                                                  FidelityMode::reference};

// The word `--fidelity` takes for `mode`, as reports show it.
constexpr const char* fidelity_mode_name(FidelityMode mode) {
  switch (mode) {
    case FidelityMode::fixed:
      return "fixed";
    case FidelityMode::fast:
      return "fast";
    case FidelityMode::automatic:
      return "auto";
    case FidelityMode::reference:
      return "reference";
  }
  return "fixed";
}

struct FidelitySpec {
  double target = 0.0;               // largest estimated relative error of the compared columns
  std::string result;                // the result table compared between levels
  std::vector<std::string> columns;  // its columns
  std::string key;                   // the column rows are paired by (e.g. frequency_hz); empty: the table's key
  std::vector<FidelityAxisSpec> axes;
  std::string note;
  SourceLocation at;
};

}  // namespace bb
