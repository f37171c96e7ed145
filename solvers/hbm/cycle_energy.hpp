// Energy per cycle at a harmonic-balance solution (hbm/fixed_frequency.hpp): the check that the
// converged harmonics balance input and dissipation. Units: SI.
#pragma once
#include "hbm/condensed_balance.hpp"
#include "hbm/fixed_frequency.hpp"

namespace bb::hbm {

// Excitation work = viscous + friction (+ normal, which is zero up to the AFT sampling for the
// elastic normal law). Uses the recovered harmonics of all DOFs. [J]
struct CycleEnergy {
  double excitation = 0.0;  // integral of f . dq over one period
  double viscous = 0.0;     // integral of q'^T C q' dt
  double friction = 0.0;    // sum_k integral of T_k du_k
  double normal = 0.0;      // sum_k integral of N_k dv_k
};
CycleEnergy cycle_energy(const HarmonicBalance& system, const HbmSolution& solution);

}  // namespace bb::hbm
