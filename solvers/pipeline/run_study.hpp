// The case's [study] (accuracy vs cost), run after its analysis with --study: results into the
// run record, tables as CSV, plots.
#pragma once
#include <filesystem>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "report/run_record.hpp"

namespace bb {

// `progress` (may be empty) receives one line per finished variant: how many are done and the time
// left. The rotating study's runs are held to `limits` (the run's own); the studies' modes and
// reductions go through the model cache in `cache`, when given.
void run_study(const StudySpec& study, const CaseSpec& spec, const Model& model, const AnalysisResults& results,
               const std::filesystem::path& out, bool plots, RunRecord& run, const HbmProgress& progress = {},
               const WorkLimits& limits = {}, const ModelCacheSettings* cache = nullptr);

}  // namespace bb
