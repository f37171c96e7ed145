// `bladebench validate`: every case under a folder, in this process or in child processes, and
// reports/index.md.
#pragma once
#include <optional>
#include <string>

#include "cache/model_cache_settings.hpp"
#include "common/work_limits.hpp"
#include "pipeline/run_case.hpp"

namespace bb::cli {

struct ValidateArgs {
  std::string dir = "cases", out = "reports";
  bool study = false, no_plots = false;
  bb::FidelityMode fidelity = bb::FidelityMode::fixed;
  int jobs = 1;
  bb::WorkLimits limits;
  std::optional<bb::ModelCacheSettings> cache;  // handed to every case's run (and child process)
};

int validate_command(const ValidateArgs& a);

}  // namespace bb::cli
