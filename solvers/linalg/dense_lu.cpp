#include "linalg/dense_lu.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "linalg/blas_threads.hpp"

extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info);
void dlacn2_(const int* n, double* v, double* x, int* isgn, double* est, int* kase, int* isave);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a, const int* lda,
            double* x, const int* incx);
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
  // dgecon's estimate of |A^-1|_1 (Hager / Higham, LAPACK's dlacn2) with the triangular solves by
  // the BLAS's dtrsv instead of dlatrs, whose overflow guards cost a third of a Newton step at 135
  // unknowns (bench/README.md); an overflow shows up as a non-finite estimate, read as singular.
  const int n = static_cast<int>(n_), one = 1;
  std::vector<double> v(static_cast<size_t>(n)), x(static_cast<size_t>(n));
  std::vector<int> sign(static_cast<size_t>(n));
  int kase = 0;
  int save[3] = {0, 0, 0};
  double inverse_norm = 0.0;
  while (true) {
    dlacn2_(&n, v.data(), x.data(), sign.data(), &inverse_norm, &kase, save);
    if (kase == 0) break;
    if (kase == 1) {  // x = U^-1 L^-1 x
      dtrsv_("L", "N", "U", &n, lu_.data(), &n, x.data(), &one);
      dtrsv_("U", "N", "N", &n, lu_.data(), &n, x.data(), &one);
    } else {  // x = L^-T U^-T x
      dtrsv_("U", "T", "N", &n, lu_.data(), &n, x.data(), &one);
      dtrsv_("L", "T", "U", &n, lu_.data(), &n, x.data(), &one);
    }
  }
  if (!std::isfinite(inverse_norm) || !(inverse_norm > 0.0)) return rcond_ = 0.0;
  return rcond_ = (1.0 / inverse_norm) / norm1_;
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
