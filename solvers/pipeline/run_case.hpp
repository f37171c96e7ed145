// One case through the pipeline: case file -> model -> analysis -> results -> checks -> report.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cache/model_cache_settings.hpp"
#include "common/work_limits.hpp"
#include "report/run_record.hpp"
#include "study/fidelity_spec.hpp"

namespace bb {

struct RunOptions {
  std::optional<std::filesystem::path> out_dir;  // default reports/<case-name>
  bool study = false;                            // also run the case's [study]
  bool plots = true;
  bool vtk = false;  // ParaView files, as [case] vtk = true
  FidelityMode fidelity = FidelityMode::fixed;   // fixed: the case's own settings; else its [fidelity] axes
  WorkLimits limits = {};                        // every analysis of the run is estimated against these first
  std::optional<ModelCacheSettings> cache = {};  // modes and reductions stored and reused there (none: not cached)
  std::vector<std::string> settings = {};  // "dotted.key=VALUE" replacing the case file's (cases/case_settings.hpp)
  std::vector<std::string> removals = {};  // "dotted.key" removed from the case file's
};

struct RunOutcome {
  RunRecord record;
  std::filesystem::path out_dir;
  bool written = false;  // the report folder is in place (false: the folder could not be written)
};

// Never throws for bad input or solver failure: the record carries the status and message. The
// report is written to a temporary folder beside out_dir and moved into place complete (report/
// output_folder.hpp), so a failed or interrupted run never leaves a half-written report; a bad
// input still gets its report (status bad_input) when the folder can be written.
RunOutcome run_case(const std::filesystem::path& case_file, const RunOptions& options);

}  // namespace bb
