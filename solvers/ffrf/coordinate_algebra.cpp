#include "ffrf/coordinate_algebra.hpp"

#include <cmath>
#include <stdexcept>

namespace bb::ffrf {

CoordinateMatrix::CoordinateMatrix(SparseMatrix m) : dense_(false), s_(std::move(m)) { s_.makeCompressed(); }

CoordinateMatrix::CoordinateMatrix(Eigen::MatrixXd m) : dense_(true), d_(std::move(m)) {}

Eigen::VectorXd CoordinateMatrix::operator*(const Eigen::VectorXd& x) const {
  if (dense_) return d_ * x;
  return s_ * x;
}

double CoordinateMatrix::form(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const { return x.dot((*this) * y); }

Eigen::MatrixXd CoordinateMatrix::to_dense() const { return dense_ ? d_ : Eigen::MatrixXd(s_); }

namespace {

void check_operands(const std::vector<Term>& terms) {
  if (terms.empty()) throw std::logic_error("combine: no terms");
  const CoordinateMatrix& first = *terms.front().matrix;
  for (const Term& t : terms) {
    const CoordinateMatrix& m = *t.matrix;
    if (m.is_dense() != first.is_dense() || m.size() != first.size())
      throw std::logic_error("combine: operands of different kinds or sizes");
    if (!m.is_dense() && m.sparse().nonZeros() != first.sparse().nonZeros())
      throw std::logic_error("combine: sparse operands must share one pattern");
  }
}

}  // namespace

void combine_into(const std::vector<Term>& terms, CoordinateMatrix& out) {
  check_operands(terms);
  const CoordinateMatrix& first = *terms.front().matrix;
  if (first.is_dense()) {
    Eigen::MatrixXd sum = terms.front().coefficient * first.dense();
    for (size_t i = 1; i < terms.size(); ++i) sum.noalias() += terms[i].coefficient * terms[i].matrix->dense();
    out = CoordinateMatrix(std::move(sum));
    return;
  }
  if (out.is_dense() || out.size() != first.size() || out.sparse().nonZeros() != first.sparse().nonZeros())
    out = CoordinateMatrix(SparseMatrix(first.sparse()));
  // Same pattern: combine the value arrays (the pattern of `out` is that of every operand).
  Eigen::Map<Eigen::VectorXd> v = out.sparse_values();
  v.setZero();
  for (const Term& t : terms)
    v += t.coefficient * Eigen::Map<const Eigen::VectorXd>(t.matrix->sparse().valuePtr(), v.size());
}

CoordinateMatrix combine(const std::vector<Term>& terms) {
  CoordinateMatrix out;
  combine_into(terms, out);
  return out;
}

bool CoordinateSolver::factorize(const CoordinateMatrix& a) {
  ++count_;
  message_.clear();
  if (a.is_dense()) {
    dense_ = true;
    lu_.compute(a.dense());
    // PartialPivLU does not report singularity: check the pivots against the matrix scale.
    const double scale = a.dense().cwiseAbs().maxCoeff();
    const double pivot = lu_.matrixLU().diagonal().cwiseAbs().minCoeff();
    if (!(pivot > 1e-14 * scale) || !std::isfinite(pivot)) {
      message_ = "singular matrix (smallest LU pivot " + std::to_string(pivot) + ")";
      return false;
    }
    return true;
  }
  dense_ = false;
  if (!sparse_lu_ || !analyzed_) {
    sparse_lu_ = std::make_shared<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>();
    sparse_lu_->analyzePattern(a.sparse());
    analyzed_ = true;
  }
  sparse_lu_->factorize(a.sparse());
  if (sparse_lu_->info() != Eigen::Success) {
    message_ = "sparse LU failed: " + sparse_lu_->lastErrorMessage();
    return false;
  }
  return true;
}

Eigen::VectorXd CoordinateSolver::solve(const Eigen::VectorXd& b) const {
  if (dense_) return lu_.solve(b);
  return sparse_lu_->solve(b);
}

}  // namespace bb::ffrf
