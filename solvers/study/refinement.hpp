// Mesh-refinement study: a probe displacement vs DOFs vs time, against Timoshenko beam theory
// and against the Richardson extrapolation of the finite-element sequence itself.
#pragma once
#include <string>
#include <vector>

#include "model/model_spec.hpp"
#include "study/study_progress.hpp"
#include "study/study_spec.hpp"

namespace bb {

struct RefinementRow {
  int level = 1;
  int nx = 0, ny = 0;
  int n_free_dofs = 0;
  double probe = 0.0;           // mean displacement of the probe set [m]
  double error_vs_beam = 0.0;   // (probe - beam) / beam
  double error_vs_limit = 0.0;  // (probe - extrapolated) / extrapolated
  double observed_order = 0.0;  // from this and the two coarser levels; 0 where undefined
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;
};

struct RefinementResult {
  std::vector<RefinementRow> rows;
  double beam_deflection = 0.0;      // Timoshenko
  double bending_only = 0.0;         // Euler-Bernoulli
  double extrapolated = 0.0;         // Richardson limit from the three finest levels
  double extrapolation_order = 0.0;  // order used for it
};

RefinementResult run_refinement_study(const ModelSpec& spec, const RefinementStudySpec& study,
                                      const StudyProgress& progress = {});

}  // namespace bb
