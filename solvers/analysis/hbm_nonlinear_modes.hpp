// The nonlinear modes of an hbm analysis's model (hbm/nonlinear_modes.hpp) and the forced-response
// peaks they predict: at a resonance of one isolated nonlinear mode the force's work balances the
// mode's dissipation, kappa(a) omega(a) a = |psi(a)^H F| Fe (psi^H M psi = 1), which gives for each
// force level Fe the amplitude a of the peak and, from the backbone, its frequency and response.
#pragma once
#include "analysis/hbm_analysis.hpp"

namespace bb {

// Traces spec.nonlinear_modes (when set) and adds the tables `nonlinear_modes` (the backbones) and,
// with `peaks`, `nonlinear_mode_peaks` (prediction against the sweep's peak of each level). Throws
// SolverError when a branch has no converged point; a branch that stops early keeps its points and
// a level beyond its reach gets NaN predictions (which a check reading them fails).
void add_nonlinear_modes(HbmOutcome& o, const HbmSpec& spec);

}  // namespace bb
