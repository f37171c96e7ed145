// Craig-Bampton reduction (fixed-interface component mode synthesis, thesis eqs 3.4-3.5):
// u = [I 0; Psi Phi] [u_m; q], Psi = -K_ss^-1 K_sm the static constraint modes, Phi the lowest
// fixed-interface modes of (K_ss, M_ss), mass-normalized.
#pragma once
#include <Eigen/Sparse>

#include <vector>

#include "cache/cache_use.hpp"
#include "linalg/modal_solver.hpp"
#include "linalg/spd_factor.hpp"
#include "reduction/reduced_model.hpp"

namespace bb {

struct CraigBamptonOptions {
  int n_modes = 10;                             // fixed-interface modes kept (may be 0: Guyan)
  FillOrdering ordering = FillOrdering::metis;  // for K_ss and the shift-invert factor
  double shift_frequency_hz = 1.0;              // see ModalOptions
  // slepc: the fixed-interface modes by SLEPc and the constraint modes by PETSc's MUMPS Cholesky.
  Eigensolver eigensolver = Eigensolver::spectra;
  // > 0: every fixed-interface mode below this [Hz] instead of n_modes (on SLEPc one slicing, whose
  // inertias give the count; else a Sturm count of K_ss - (2 pi f)^2 M_ss first).
  double modes_below_hz = 0.0;
};

struct CraigBamptonTiming {
  double constraint_modes_seconds = 0.0;  // factor K_ss, solve for Psi
  double fixed_interface_seconds = 0.0;   // eigenproblem of the clamped slaves
  double projection_seconds = 0.0;        // T^T K T, T^T M T
  // Set by cached_craig_bampton; when loaded, the three times above are those of the run that built it.
  CacheUse cache;
};

// `stiffness`, `mass`: over the free DOFs (both symmetric, full storage). `masters[i]` is a free-DOF
// index named `master_names[i]`; the reduced DOFs are the masters in the given order, then the
// modes. Throws InputError for repeated or out-of-range masters, more modes than slave DOFs, or a
// singular K_ss (slaves not held by the masters and constraints), SolverError when the
// eigensolver fails. Masters may be empty when n_modes > 0 (plain fixed-interface modal
// truncation). Keeping every slave mode (n_modes == slave count, a small model) uses a dense
// eigensolver, since Lanczos needs n_modes below the matrix size; the reduction is then exact.
ReducedModel craig_bampton(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                           const std::vector<int>& masters, const std::vector<ReducedDof>& master_names,
                           const CraigBamptonOptions& options, CraigBamptonTiming* timing = nullptr);

// The fixed-interface modes below `cut_frequency_hz` (> 0): the Sturm count of K_ss - (2 pi f)^2 M_ss,
// what a reduction that keeps every mode below the cut needs as n_modes. Throws InputError for
// invalid masters, SolverError when the count fails (f an eigenvalue to rounding).
int fixed_interface_count(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                          const std::vector<int>& masters, double cut_frequency_hz);

}  // namespace bb
