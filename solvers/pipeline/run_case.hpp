// One case through the pipeline: case file -> model -> analysis -> results -> checks -> report.
#pragma once
#include <filesystem>
#include <optional>

#include "report/run_record.hpp"

namespace bb {

struct RunOptions {
  std::optional<std::filesystem::path> out_dir;  // default reports/<case-name>
  bool study = false;                            // also run the case's [study]
  bool plots = true;
};

struct RunOutcome {
  RunRecord record;
  std::filesystem::path out_dir;
};

// Never throws for bad input or solver failure: the record carries the status and message,
// and summary.json is written last, so a half-written folder never reads as a success.
RunOutcome run_case(const std::filesystem::path& case_file, const RunOptions& options);

}  // namespace bb
