// The nonlinear modes of an hbm analysis's model (hbm/nonlinear_modes.hpp) and the forced-response
// peaks they predict: at a resonance of one isolated nonlinear mode the force's work balances the
// mode's dissipation, kappa(a) omega(a) a = |psi(a)^H F| Fe (psi^H M psi = 1), which gives for each
// force level Fe the amplitude a of the peak and, from the backbone, its frequency and response.
#pragma once
#include <vector>

#include "forced/hbm_level.hpp"
#include "hbm/nonlinear_modes.hpp"
#include "results/table.hpp"

namespace bb {

struct HbmNonlinearModes {
  std::vector<hbm::NonlinearModeBranch> branches;  // one per linear mode of spec.nonlinear_modes
  double seconds = 0.0;
  ResultTables tables;  // nonlinear_modes and, with `peaks`, nonlinear_mode_peaks
};

// Traces spec.nonlinear_modes (nothing when unset): the table `nonlinear_modes` (the backbones)
// and, with `peaks`, `nonlinear_mode_peaks` (prediction against the peak of each of `levels`).
// Throws SolverError when a branch has no converged point; a branch that stops early keeps its
// points and a level beyond its reach gets NaN predictions (which a check reading them fails).
HbmNonlinearModes trace_nonlinear_modes(const PreparedHbm& p, const std::vector<HbmLevel>& levels, const HbmSpec& spec);

}  // namespace bb
