// Accuracy vs cost of the stepped-sine time integration (thesis eq 3.42: the step as a fraction of
// the period; eq 3.41: how long to integrate): steps per period x steady-state tolerance, each
// variant against the finest one, with its cost.
#pragma once
#include "analysis/time_analysis.hpp"
#include "cache/model_cache_settings.hpp"
#include "results/table.hpp"
#include "study/study_progress.hpp"
#include "study/study_spec.hpp"

namespace bb {

// One row per variant: key "variant" (1-based); columns steps_per_period, steady_tolerance, then
// per peak kind <k>_hz_error, <k>_amp_error (first level, relative to the finest variant),
// max_amp_error (first response over the grid), steps, mean_cycles, not_steady, seconds.
ResultTable run_time_step_study(const Model& model, const TimeSpec& spec, const TimeStepStudySpec& study,
                                const StudyProgress& progress = {}, const ModelCacheSettings* cache = nullptr);

}  // namespace bb
