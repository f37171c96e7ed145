// Lowest eigenpairs of a complex Hermitian pencil K x = lambda M x (M positive definite) by
// shift-invert Krylov-Schur: the operator (K - sigma M)^{-1} M is self-adjoint in the M inner
// product, its largest eigenvalues 1 / (lambda - sigma) are the lowest lambda. Each eigenvalue is
// found once, where the real form of twice the size (Re, -Im; Im, Re) holds every one twice: the
// travelling waves of a nodal diameter 0 < k < N/2 cost half of their cosine/sine pairs.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <complex>

#include "linalg/spd_factor.hpp"

namespace bb {

struct HermitianLanczosOptions {
  int nev = 6;               // eigenpairs wanted
  int ncv = 20;              // basis vectors kept between restarts (> nev)
  double sigma = -1.0;       // shift below the wanted eigenvalues, so that K - sigma M > 0
  double tolerance = 1e-10;  // ||Op x - mu x||_M <= tolerance * mu for every wanted pair
  int max_restarts = 1000;
  FillOrdering ordering = FillOrdering::metis;
};

struct HermitianLanczosResult {
  Eigen::VectorXd eigenvalues;  // ascending, nev of them
  Eigen::MatrixXcd shapes;      // M-orthonormal
  int restarts = 0;
};

// Throws SolverError when K - sigma M cannot be factored or the pairs do not converge.
HermitianLanczosResult hermitian_lanczos(const Eigen::SparseMatrix<std::complex<double>>& stiffness,
                                         const Eigen::SparseMatrix<std::complex<double>>& mass,
                                         const HermitianLanczosOptions& options);

}  // namespace bb
