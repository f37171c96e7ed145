// A complex matrix acting on a + ib, written as a real one on (a, b).
#pragma once
#include <Eigen/Sparse>

#include <complex>

namespace bb {

// [[Re A, -Im A], [Im A, Re A]]. Hermitian A gives a symmetric matrix whose every eigenvalue is
// A's, twice (z and i z); its inertia is twice A's.
Eigen::SparseMatrix<double> real_form(const Eigen::SparseMatrix<std::complex<double>>& a);

}  // namespace bb
