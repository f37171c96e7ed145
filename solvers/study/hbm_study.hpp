// Accuracy vs cost of the harmonic balance in the number of harmonics H (the thesis uses H = 1):
// the peaks of chosen force levels at each H against the largest H, with the time of each sweep.
#pragma once
#include "analysis/hbm_analysis.hpp"
#include "results/table.hpp"
#include "study/study_progress.hpp"
#include "study/study_spec.hpp"

namespace bb {

// One row per H x level: key "variant" (100 H + level index); columns harmonics, fe_n, then per
// peak kind (ip, oop, or peak) <k>_hz, <k>_amp_m, <k>_hz_error, <k>_amp_error (relative, against
// the largest H of the same level), and unknowns, newton_iterations, failed_points, seconds.
ResultTable run_hbm_harmonics_study(const HbmSpec& spec, const PreparedHbm& prepared,
                                    const HbmHarmonicsStudySpec& study, const StudyProgress& progress = {});

}  // namespace bb
