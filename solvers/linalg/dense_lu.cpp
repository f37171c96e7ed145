#include "linalg/dense_lu.hpp"

#include <limits>
#include <stdexcept>

#include "linalg/blas_threads.hpp"

extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm, double* rcond,
             double* work, int* iwork, int* info);
}

namespace bb {

namespace {

bool lapack_usable() {
  static const bool usable = [] {
    use_one_thread_per_factorization();
    return blas_allows_concurrent_calls();
  }();
  return usable;
}

}  // namespace

DenseLU::DenseLU(const Eigen::MatrixXd& a) : n_(a.rows()) {
  if (a.rows() != a.cols()) throw std::invalid_argument("DenseLU: the matrix must be square");
  if (n_ == 0) return;
  if (n_ > std::numeric_limits<int>::max() / n_) throw std::invalid_argument("DenseLU: the matrix is too large");
  by_lapack_ = lapack_usable();
  if (!by_lapack_) {
    eigen_.compute(a);
    return;
  }
  norm1_ = a.cwiseAbs().colwise().sum().maxCoeff();  // for dgecon
  const int n = static_cast<int>(n_);
  lu_ = a;
  pivots_.resize(static_cast<size_t>(n));
  int info = 0;
  dgetrf_(&n, &n, lu_.data(), &n, pivots_.data(), &info);
  if (info < 0) throw std::logic_error("DenseLU: dgetrf rejected its arguments");
  singular_ = info > 0;  // an exactly zero pivot
}

double DenseLU::rcond() const {
  if (rcond_ >= 0.0) return rcond_;
  if (n_ == 0) return rcond_ = 1.0;
  if (!by_lapack_) return rcond_ = eigen_.rcond();
  if (singular_ || !(norm1_ > 0.0)) return rcond_ = 0.0;
  const int n = static_cast<int>(n_);
  std::vector<double> work(4 * static_cast<size_t>(n));
  std::vector<int> iwork(static_cast<size_t>(n));
  int info = 0;
  double r = 0.0;
  dgecon_("1", &n, lu_.data(), &n, &norm1_, &r, work.data(), iwork.data(), &info);
  if (info != 0) throw std::logic_error("DenseLU: dgecon rejected its arguments");
  return rcond_ = r;
}

Eigen::VectorXd DenseLU::solve(const Eigen::VectorXd& b) const {
  if (b.size() != n_) throw std::invalid_argument("DenseLU: right-hand side of the wrong size");
  if (n_ == 0) return b;  // neither decomposition was made
  if (!by_lapack_) return eigen_.solve(b);
  if (singular_) return Eigen::VectorXd::Constant(n_, std::numeric_limits<double>::quiet_NaN());
  Eigen::VectorXd x = b;
  const int n = static_cast<int>(n_), one = 1;
  int info = 0;
  dgetrs_("N", &n, &one, lu_.data(), &n, pivots_.data(), x.data(), &n, &info);
  if (info != 0) throw std::logic_error("DenseLU: dgetrs rejected its arguments");
  return x;
}

}  // namespace bb
