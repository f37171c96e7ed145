#include "linalg/spd_factor.hpp"

#include <cholmod.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "linalg/blas_threads.hpp"

namespace bb {

struct SpdFactorization::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  std::vector<int> outer, inner;  // the pattern `factor` was analyzed for
  explicit Impl(FillOrdering ordering) {
    cholmod_start(&common);
    common.print = 0;
    common.error_handler = nullptr;
    if (ordering != FillOrdering::best_of_both) {
      common.nmethods = 1;
      common.method[0].ordering = ordering == FillOrdering::amd ? CHOLMOD_AMD : CHOLMOD_METIS;
      common.postorder = 1;
    }
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

namespace {

cholmod_sparse view_lower(const Eigen::SparseMatrix<double>& a) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(a.rows());
  s.ncol = static_cast<size_t>(a.cols());
  s.nzmax = static_cast<size_t>(a.nonZeros());
  s.p = const_cast<int*>(a.outerIndexPtr());
  s.i = const_cast<int*>(a.innerIndexPtr());
  s.x = const_cast<double*>(a.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

// Column (original numbering) of the smallest pivot; only on the failure path.
int weakest_pivot_column(cholmod_factor* factor, cholmod_common* common) {
  cholmod_factor* copy = cholmod_copy_factor(factor, common);
  if (!copy) return -1;
  cholmod_change_factor(CHOLMOD_REAL, copy->is_ll, 0, 1, 1, copy, common);
  const auto* p = static_cast<const int*>(copy->p);
  const auto* x = static_cast<const double*>(copy->x);
  const auto* perm = static_cast<const int*>(copy->Perm);
  int best = -1;
  double smallest = INFINITY;
  const int n = static_cast<int>(copy->n);
  const int limit = copy->minor < copy->n ? static_cast<int>(copy->minor) : n;
  for (int k = 0; k < limit; ++k) {
    const double d = std::abs(x[p[k]]);
    if (d < smallest) {
      smallest = d;
      best = k;
    }
  }
  if (copy->minor < copy->n) best = static_cast<int>(copy->minor);
  const int column = best >= 0 && perm ? perm[best] : best;
  cholmod_free_factor(&copy, common);
  return column;
}

}  // namespace

SpdFactorization::SpdFactorization(FillOrdering ordering) : impl_(std::make_unique<Impl>(ordering)) {}
SpdFactorization::~SpdFactorization() = default;
SpdFactorization::SpdFactorization(SpdFactorization&&) noexcept = default;
SpdFactorization& SpdFactorization::operator=(SpdFactorization&&) noexcept = default;

FactorStatus SpdFactorization::factorize(const Eigen::SparseMatrix<double>& a) {
  FactorStatus status;
  if (a.rows() != a.cols()) throw std::invalid_argument("SpdFactorization: matrix is not square");
  if (!a.isCompressed()) throw std::invalid_argument("SpdFactorization: matrix is not compressed");
  rows_ = static_cast<int>(a.rows());
  if (rows_ == 0) {
    status.message = "the system has no free degree of freedom";
    return status;
  }
  cholmod_common* c = &impl_->common;
  cholmod_sparse view = view_lower(a);
  // The same pattern as the last matrix (a Newton iteration, a new load level): only the numbers change,
  // so the fill-reducing ordering and the symbolic factorization are kept.
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const bool same_pattern = impl_->factor && impl_->outer.size() == static_cast<size_t>(a.cols() + 1) &&
                            impl_->inner.size() == static_cast<size_t>(a.nonZeros()) &&
                            std::equal(impl_->outer.begin(), impl_->outer.end(), outer) &&
                            std::equal(impl_->inner.begin(), impl_->inner.end(), inner);
  use_one_thread_per_factorization();
  if (!same_pattern) {
    if (impl_->factor) cholmod_free_factor(&impl_->factor, c);
    impl_->factor = cholmod_analyze(&view, c);
    if (!impl_->factor) {
      status.message = fmt::format("CHOLMOD analysis failed (status {})", c->status);
      return status;
    }
    impl_->outer.assign(outer, outer + a.cols() + 1);
    impl_->inner.assign(inner, inner + a.nonZeros());
  }
  cholmod_factorize(&view, impl_->factor, c);
  if (c->status == CHOLMOD_OUT_OF_MEMORY) {
    status.message = "out of memory in the sparse Cholesky factorization";
    return status;
  }
  if (impl_->factor->minor < impl_->factor->n) {
    status.weakest_column = weakest_pivot_column(impl_->factor, c);
    status.message = "matrix is not positive definite (zero or negative pivot)";
    return status;
  }
  status.rcond = cholmod_rcond(impl_->factor, c);
  if (!(status.rcond >= kSingularRcond)) {
    status.weakest_column = weakest_pivot_column(impl_->factor, c);
    status.message =
        fmt::format("matrix is numerically singular (pivot ratio {:.3g} < {:.0e})", status.rcond, kSingularRcond);
    return status;
  }
  status.ok = true;
  return status;
}

Eigen::MatrixXd SpdFactorization::solve(const Eigen::MatrixXd& b) const {
  if (!impl_->factor || b.rows() != rows_)
    throw std::logic_error("SpdFactorization::solve without a valid factorization");
  cholmod_common* c = &impl_->common;
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(b.rows());
  rhs.ncol = static_cast<size_t>(b.cols());
  rhs.nzmax = rhs.nrow * rhs.ncol;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &rhs, c);
  if (!x) throw std::runtime_error("CHOLMOD solve failed");
  Eigen::MatrixXd out = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), b.rows(), b.cols());
  cholmod_free_dense(&x, c);
  return out;
}

Eigen::VectorXd SpdFactorization::solve(const Eigen::VectorXd& b) const { return solve(Eigen::MatrixXd(b)).col(0); }

}  // namespace bb
