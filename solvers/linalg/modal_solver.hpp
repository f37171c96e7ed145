// Lowest modes of K x = w^2 M x by Lanczos in shift-invert mode: Spectra for a real symmetric
// pencil, linalg/hermitian_lanczos.hpp for a complex Hermitian one (a cyclic sector's nodal
// diameters 0 < k < N/2), each proved complete by a Sturm count.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <complex>
#include <optional>

#include "linalg/spd_factor.hpp"

namespace bb {

// spectra: CHOLMOD shift-invert, Spectra's Lanczos and a MUMPS Sturm count, in this process.
// slepc: SLEPc's Krylov-Schur spectrum slicing with MUMPS Cholesky at each shift, over MPI ranks,
// whose own inertias prove the count (linalg/slepc_modes.hpp); a Hermitian pencil through its real
// form of twice the size.
enum class Eigensolver { spectra, slepc };

struct ModalOptions {
  int n_modes = 6;
  Eigensolver eigensolver = Eigensolver::spectra;
  // slepc: MUMPS writes its factors to disk (MUMPS_OOC_TMPDIR, else /tmp) and reads them back at
  // every solve, for a mesh whose factors do not fit in memory; the same modes, more time.
  bool out_of_core = false;
  // Shift sigma = -(2 pi f)^2 < 0 keeps K - sigma M positive definite for any K >= 0, so one
  // Cholesky factor serves, rigid-body modes included.
  double shift_frequency_hz = 1.0;
  int max_iterations = 1000;
  double tolerance = 1e-10;
  int subspace_size = 0;  // Lanczos vectors; 0 = max(2 n + 1, 20)
  FillOrdering ordering = FillOrdering::amd;
  // Lanczos can miss one member of a repeated eigenvalue (its start vector has no component in
  // that direction, up to rounding). The Sturm count of K - sigma M at the cut proves or refutes
  // completeness; a refuted run is repeated with more vectors until the count agrees.
  bool verify_count = true;
  // Eigenvalues within this relative distance of the n-th count as one cluster: a repeated
  // eigenvalue that straddles the requested count is returned whole.
  double cluster_tolerance = 1e-6;
  int max_reruns = 6;
};

template <class Scalar>
struct BasicModalSolution {
  Eigen::VectorXd eigenvalues;                                   // w^2 [rad^2/s^2], ascending
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> shapes;  // mass-normalized, one per column
  int iterations = 0;
  int converged_modes = 0;
  double max_residual = 0.0;  // max_k ||K x - w^2 M x|| / ((||K|| + w^2 ||M||) ||x||)
  // Completeness: eigenvalues below sturm_shift by the inertia of K - sturm_shift M (-1 = not
  // checked), Lanczos runs needed to find them all, and the cost of the counts.
  int sturm_count = -1;
  double sturm_shift = 0.0;  // [rad^2/s^2]
  int lanczos_runs = 0;
  double sturm_seconds = 0.0;
};
using ModalSolution = BasicModalSolution<double>;
using HermitianModalSolution = BasicModalSolution<std::complex<double>>;

// The lowest options.n_modes modes, or more when a repeated eigenvalue straddles the n-th (the whole
// cluster is returned). Throws SolverError when Lanczos does not converge, the shifted matrix cannot
// be factored, or the Sturm count still disagrees after max_reruns larger runs.
ModalSolution lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                           const ModalOptions& options);
// The same for Hermitian K and M (each eigenvalue once; the count from the real form).
HermitianModalSolution lowest_modes(const Eigen::SparseMatrix<std::complex<double>>& stiffness,
                                    const Eigen::SparseMatrix<std::complex<double>>& mass, const ModalOptions& options);

// What lowest_modes would return for `options` (the lowest n, a straddling cluster whole), taken
// from a solution of the same problem that holds more modes; nullopt when `sol` cannot prove them
// complete: fewer modes than asked, or a cut above the shift of its Sturm count.
std::optional<ModalSolution> leading_modes(const ModalSolution& sol, const ModalOptions& options);

}  // namespace bb
