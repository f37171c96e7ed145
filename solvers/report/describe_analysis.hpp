// The facts of a run that the report lists: how the model was made, what the analysis did and what
// its solvers measured (sizes, iterations, residuals, times).
#pragma once
#include "analysis/run_analysis.hpp"
#include "model/model_spec.hpp"
#include "report/run_record.hpp"

namespace bb {

// `driven_contact`: the analysis has no model of its own (a contact driven by an imposed motion).
void describe_model(const ModelSpec& spec, bool driven_contact, const Model& model, RunRecord& run);

void describe_analysis(const AnalysisSpec& spec, const AnalysisResults& results, const Model& model, RunRecord& run);

}  // namespace bb
