// Sparse Cholesky (CHOLMOD, supernodal where it pays) of a symmetric positive definite matrix.
// The one factorization helper of the project: static solves and shift-invert both use it.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <memory>
#include <optional>
#include <string>

namespace bb {

struct FactorStatus {
  bool ok = false;
  double rcond = 0.0;       // CHOLMOD's estimate: (min |L_ii| / max |L_ii|)^2
  int weakest_column = -1;  // original column of the failed or smallest pivot, when !ok
  std::string message;      // why it failed
};

// Fill-reducing ordering. CHOLMOD's own default tries AMD and then METIS and keeps the better;
// on 2D meshes that second analysis costs ~5 s at 1M DOFs and AMD wins anyway (bench/README.md).
// For 3D solids nested dissection (METIS) fills less than AMD (Table VI model: eigensolve 36 s -> 31 s).
enum class FillOrdering { amd, metis, best_of_both };

// AMD for plane meshes, METIS for solids.
inline FillOrdering ordering_for_dimension(int dim) { return dim == 3 ? FillOrdering::metis : FillOrdering::amd; }

class SpdFactorization {
 public:
  // Pivot ratio below which the matrix counts as singular (a mechanism or rigid-body motion).
  static constexpr double kSingularRcond = 1e-14;

  explicit SpdFactorization(FillOrdering ordering = FillOrdering::amd);
  ~SpdFactorization();
  SpdFactorization(SpdFactorization&&) noexcept;
  SpdFactorization& operator=(SpdFactorization&&) noexcept;
  SpdFactorization(const SpdFactorization&) = delete;
  SpdFactorization& operator=(const SpdFactorization&) = delete;

  // Only the lower triangle of `a` is read. The status tells whether solve() may be called.
  FactorStatus factorize(const Eigen::SparseMatrix<double>& a);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;
  int rows() const { return rows_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int rows_ = 0;
};

}  // namespace bb
