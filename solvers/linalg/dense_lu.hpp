// The LU of a square dense matrix with partial pivoting, and its reciprocal condition number in
// the 1-norm: the Newton steps of the harmonic balance (135 unknowns on Table XI at H = 7, 243 at
// H = 13). LAPACK's blocked factorization (dgetrf, dgetrs; OpenBLAS here, dispatched to the
// running CPU) takes 0.45-0.8x the time of Eigen's compiled for the baseline x86-64; the condition
// estimate is dgecon's algorithm (dlacn2) with the BLAS's triangular solves (bench/README.md). Eigen serves where the BLAS must not be
// called from two threads at once (linalg/blas_threads.hpp).
#pragma once
#include <Eigen/Dense>

#include <vector>

namespace bb {

class DenseLU {
 public:
  DenseLU() = default;
  explicit DenseLU(const Eigen::MatrixXd& a);

  Eigen::Index rows() const { return n_; }
  // 1 / (|A|_1 |A^-1|_1), estimated; 0 for an exactly singular A.
  double rcond() const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  Eigen::Index n_ = 0;
  double norm1_ = 0.0;
  bool singular_ = false;
  mutable double rcond_ = -1.0;                 // estimated on first request
  Eigen::MatrixXd lu_;                          // LAPACK path: L and U in one matrix
  std::vector<int> pivots_;                     // LAPACK path: 1-based row interchanges
  Eigen::PartialPivLU<Eigen::MatrixXd> eigen_;  // where the BLAS is serial
  bool by_lapack_ = false;
};

}  // namespace bb
