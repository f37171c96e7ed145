// The modal solve and SPD solves on PETSc/SLEPc (distributed/plugin_abi.h): Krylov-Schur spectrum
// slicing over [sigma, cut] with a MUMPS Cholesky at every shift. The count of the eigenvalues in
// the interval comes from the inertias of those factorizations, not from a factorization of its own.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <stdexcept>

#include "linalg/modal_solver.hpp"

namespace bb {

// lowest_modes() on SLEPc: the lowest n estimated by shift-invert, then every eigenvalue up to
// just above the n-th (a repeated one there whole) by slicing. sturm_count and sturm_shift are the
// slicing's; lanczos_runs = 2 (estimate, slice).
ModalSolution slepc_lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                 const ModalOptions& options);

// Every mode with eigenvalue below `cut` [rad^2/s^2] (a band's top), by one slicing.
ModalSolution slepc_modes_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                double cut, const ModalOptions& options);

// A singular or indefinite A given to slepc_solve_spd (what MUMPS's pivots say).
struct NotPositiveDefinite : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A^{-1} B for symmetric positive definite A by MUMPS Cholesky through PETSc; throws
// NotPositiveDefinite when A has a null or negative pivot, SolverError on any other failure.
Eigen::MatrixXd slepc_solve_spd(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& b);

}  // namespace bb
