// Matrices over the elastic coordinates of a body, and their factorization: sparse (nodal basis,
// every free DOF) or dense (modal basis). The FFRF solvers form many linear combinations
// c_M M + c_G G + c_K K + ... per run; sparse operands share one nodal pattern (ffrf/body_assembly),
// so a combination is a sum of value arrays and the LU's symbolic analysis is done once.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bb::ffrf {

using SparseMatrix = Eigen::SparseMatrix<double>;

class CoordinateMatrix {
 public:
  CoordinateMatrix() = default;
  explicit CoordinateMatrix(SparseMatrix m);
  explicit CoordinateMatrix(Eigen::MatrixXd m);

  bool is_dense() const { return dense_; }
  Eigen::Index size() const { return dense_ ? d_.rows() : s_.rows(); }
  const SparseMatrix& sparse() const { return s_; }
  const Eigen::MatrixXd& dense() const { return d_; }
  // Value array of a sparse matrix, to overwrite in place (the pattern stays).
  Eigen::Map<Eigen::VectorXd> sparse_values() { return {s_.valuePtr(), s_.nonZeros()}; }

  Eigen::VectorXd operator*(const Eigen::VectorXd& x) const;
  // x^T A y.
  double form(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const;
  // A as a dense matrix (for small state-space eigenproblems).
  Eigen::MatrixXd to_dense() const;

 private:
  bool dense_ = false;
  SparseMatrix s_;
  Eigen::MatrixXd d_;
};

// sum_i c_i A_i over operands of one kind (all dense, or all sparse on the same pattern).
struct Term {
  double coefficient;
  const CoordinateMatrix* matrix;
};
CoordinateMatrix combine(const std::vector<Term>& terms);
// In place, reusing out's storage (no allocation once out has the pattern).
void combine_into(const std::vector<Term>& terms, CoordinateMatrix& out);

// LU factorization of a square CoordinateMatrix: Eigen::SparseLU (COLAMD; the symbolic analysis of
// the first call is kept, so one solver serves matrices of one pattern only) or dense partial-pivoting LU. The
// effective matrices of the FFRF equations are not symmetric (the Coriolis and Euler terms are skew), so the project's
// Cholesky helper (linalg/spd_factor) does not apply here.
class CoordinateSolver {
 public:
  // Returns false (and sets message()) when the matrix is singular.
  bool factorize(const CoordinateMatrix& a);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  const std::string& message() const { return message_; }
  int factorizations() const { return count_; }

 private:
  bool dense_ = false;
  bool analyzed_ = false;
  int count_ = 0;
  std::string message_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  std::shared_ptr<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>> sparse_lu_;
};

}  // namespace bb::ffrf
