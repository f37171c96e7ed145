// The figures of a run, per analysis type: deformed meshes and mode shapes, FRFs, hysteresis loops,
// performance curves and contact states. Each is drawn by gnuplot into the output folder.
#pragma once
#include <filesystem>
#include <vector>

#include "analysis/run_analysis.hpp"
#include "checks/check_spec.hpp"
#include "report/run_record.hpp"

namespace bb {

// Appends the analysis's plots to run.plots. `checks`: a plot may draw a check's reference values.
void plot_analysis(const AnalysisSpec& spec, const AnalysisResults& results, const Model& model,
                   const std::vector<CheckSpec>& checks, const std::filesystem::path& out, RunRecord& run);

}  // namespace bb
