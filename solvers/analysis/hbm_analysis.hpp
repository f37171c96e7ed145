// Nonlinear forced response by harmonic balance (thesis sections 3.3.2.4-3.3.2.7), the analysis:
// every level of hbm_level.hpp, the nonlinear modes, and the tables. The linear
// model of the case (Craig-Bampton reduction, reduced model from files, or lumped matrices) with
// friction contacts and optionally a rigid underplatform damper, swept in frequency (a grid of
// Newton solves, or pseudo-arclength continuation) at each force level; peaks (in-phase / out-of-phase when asked),
// contact states and energy balance at each peak, the free and fully stuck linear limits.
#pragma once
#include <string>
#include <vector>

#include "forced/hbm_level.hpp"
#include "forced/hbm_response_control.hpp"
#include "forced/hbm_stepped_sine.hpp"
#include "hbm/nonlinear_modes.hpp"
#include "results/table.hpp"

namespace bb {

struct HbmOutcome {
  ResultTables tables;
  PreparedHbm prepared;
  std::vector<HbmLevel> levels;
  Eigen::VectorXd limit_frequency_hz;
  Eigen::MatrixXd free_response, stuck_response;  // frequencies x responses, per N of the first force
  double sweep_seconds = 0.0;
  std::vector<hbm::NonlinearModeBranch> nonlinear_modes;  // spec.nonlinear_modes: one per linear mode
  double nonlinear_mode_seconds = 0.0;
  std::vector<HbmSteppedSine> stepped_sines;     // spec.stepped_sines, in order
  std::vector<HbmControlled> response_controls;  // spec.response_controls, in order
};

// prepare + every level + tables: peaks, frf_<Fe>, contact_states, energy_balance, sweep_cost, aft_sampling,
// harmonic_selection, limits, limit_peaks, damper_static; then the stepped sines (frf_<name>,
// stepped_sine_cost) and the response controls (frf_<name>, response_control). Throws SolverError when a level or a
// stepped sine finds no solution at all or a peak's refinement does not converge: a peak is never reported at a failed
// solve. The reduction goes through the model cache in `cache`, when given (prepare_hbm).
HbmOutcome run_hbm(const Model& model, const HbmSpec& spec, const HbmProgress& progress = {},
                   const ModelCacheSettings* cache = nullptr);

}  // namespace bb
