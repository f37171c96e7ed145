// Files an analysis writes besides its result tables: the reduced models it built, as sidecars that
// a later case can read back (reduction/reduced_model_io.hpp).
#pragma once
#include <filesystem>

#include "analysis/run_analysis.hpp"
#include "report/run_record.hpp"

namespace bb {

// Writes them under out/reduced_models/ and lists them in run.tables.
void write_analysis_files(const AnalysisSpec& spec, const AnalysisResults& results, const std::filesystem::path& out,
                          RunRecord& run);

}  // namespace bb
