// Lowest modes of K x = w^2 M x by Lanczos (Spectra) in shift-invert mode.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "linalg/spd_factor.hpp"

namespace bb {

struct ModalOptions {
  int n_modes = 6;
  // Shift sigma = -(2 pi f)^2 < 0 keeps K - sigma M positive definite for any K >= 0, so one
  // Cholesky factor serves, rigid-body modes included.
  double shift_frequency_hz = 1.0;
  int max_iterations = 1000;
  double tolerance = 1e-10;
  int subspace_size = 0;  // Lanczos vectors; 0 = max(2 n + 1, 20)
  FillOrdering ordering = FillOrdering::amd;
};

struct ModalSolution {
  Eigen::VectorXd eigenvalues;   // w^2 [rad^2/s^2], ascending
  Eigen::MatrixXd shapes;        // mass-normalized, one per column
  int iterations = 0;
  int converged_modes = 0;
  double max_residual = 0.0;     // max_k ||K x - w^2 M x|| / ((||K|| + w^2 ||M||) ||x||)
};

// Throws SolverError when Lanczos does not converge or the shifted matrix cannot be factored.
ModalSolution lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const ModalOptions& options);

}  // namespace bb
