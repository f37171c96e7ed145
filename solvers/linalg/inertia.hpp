// Sylvester's law of inertia for K - sigma M: the number of eigenvalues of K x = lambda M x below
// sigma equals the number of negative pivots of an LDL^T factorization of K - sigma M (the Sturm
// sequence property). The modal solver uses it to prove that Lanczos found every mode below its cut.
#pragma once
#include <Eigen/Sparse>

#include <complex>
#include <string>

namespace bb {

struct InertiaCount {
  bool ok = false;     // false when a pivot is exactly zero (sigma is an eigenvalue) or memory ran out
  int negative = 0;    // eigenvalues below sigma
  int zero = 0;        // pivots that are exactly zero (only when !ok)
  double seconds = 0;  // cost of the factorization
  std::string message;
};

// Negative pivots of the LDL^T (MUMPS, multifrontal, 2x2 pivots) of K - sigma M; K and M symmetric,
// M positive semi-definite. Only the lower triangles are read.
InertiaCount eigenvalues_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                               double sigma);

// The same for a Hermitian pencil, through its real form of twice the size (whose every
// eigenvalue is there twice): not ok when that count is odd.
InertiaCount eigenvalues_below(const Eigen::SparseMatrix<std::complex<double>>& stiffness,
                               const Eigen::SparseMatrix<std::complex<double>>& mass, double sigma);

}  // namespace bb
