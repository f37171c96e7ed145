// Accuracy vs cost of Craig-Bampton models (the trade users make): number of fixed-interface
// modes and master set vs the error of the first natural frequencies and of the FRF peaks, vs
// reduction time and time per frequency, all against the full mesh of the case.
#pragma once
#include "analysis/frf_spec.hpp"
#include "cache/model_cache_settings.hpp"
#include "model/model.hpp"
#include "results/table.hpp"
#include "study/study_progress.hpp"
#include "study/study_spec.hpp"

namespace bb {

// One row per master set x mode count: key "variant"; columns master_points, modes, rom_dofs,
// max_freq_error, rms_freq_error (first compare_modes, by index), peak_freq_error,
// peak_amp_error (first peak of each response, the worst), reduction_s, solve_us_per_frequency;
// text column master_set.
// `progress` hears of the start and the end only: the variants share one sweep.
ResultTable run_rom_study(const FrfSpec& spec, const RomStudySpec& study, const Model& model,
                          const StudyProgress& progress = {}, const ModelCacheSettings* cache = nullptr);

}  // namespace bb
