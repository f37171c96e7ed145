// Accuracy vs cost of the model levels of a rotating scene (issue: "model only what a scene
// requires"): each level's steady deflection, largest motion and first rotating frequency against
// the finest level (the floating frame with stiffening on every free DOF), with its cost.
#pragma once
#include "analysis/rotating_spec.hpp"
#include "common/work_limits.hpp"
#include "model/model.hpp"
#include "results/table.hpp"
#include "study/study_progress.hpp"
#include "study/study_spec.hpp"

namespace bb {

// One row per level, key "level": unknowns, seconds, mean_error, motion_error, frequency_error
// (relative to the finest level; NaN where the level has no such quantity or diverged), diverged;
// text column "model". The compared quantities are those of the first history set: its largest mean
// displacement component, its largest |u| over the run, and the frequency of the first rotating mode
// (measured on the run's histories; the static level's from the rotating eigenproblem).
// Each time run is held to `limits` (the run's --max-work / --max-memory).
ResultTable run_rotating_fidelity_study(const Model& model, const RotatingSpec& spec,
                                        const RotatingFidelityStudySpec& study, const StudyProgress& progress = {},
                                        const WorkLimits& limits = {});

}  // namespace bb
