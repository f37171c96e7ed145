// The report of a nonlinear_modal analysis: its facts (model, curves) and plots (the backbone with
// the points read from measured curves; each response-controlled curve's force).
#pragma once
#include <filesystem>

#include "analysis/nonlinear_modal_analysis.hpp"
#include "report/run_record.hpp"

namespace bb {

void describe(const NonlinearModalSpec& spec, const NonlinearModalOutcome& o, RunRecord& run);
// `tables`: the run's (the outcome's own were moved there).
void plot_nonlinear_modal(const NonlinearModalSpec& spec, const NonlinearModalOutcome& o, const ResultTables& tables,
                          const std::filesystem::path& out, RunRecord& run);

}  // namespace bb
