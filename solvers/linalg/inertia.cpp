#include "linalg/inertia.hpp"

#include <cholmod.h>

#include <chrono>

namespace bb {

InertiaCount eigenvalues_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                               double sigma, FillOrdering ordering) {
  const auto t0 = std::chrono::steady_clock::now();
  InertiaCount out;
  Eigen::SparseMatrix<double> shifted = stiffness - sigma * mass;
  shifted.makeCompressed();
  cholmod_common common{};
  cholmod_start(&common);
  common.print = 0;
  common.error_handler = nullptr;
  // LDL^T needs the simplicial factorization (supernodal is LL^T only); no pivoting, which is
  // what the inertia count needs and what keeps the sparsity of the Cholesky analysis.
  common.supernodal = CHOLMOD_SIMPLICIAL;
  common.final_ll = 0;
  common.nmethods = 1;
  common.method[0].ordering = ordering == FillOrdering::amd ? CHOLMOD_AMD : CHOLMOD_METIS;
  cholmod_sparse view{};
  view.nrow = static_cast<size_t>(shifted.rows());
  view.ncol = static_cast<size_t>(shifted.cols());
  view.nzmax = static_cast<size_t>(shifted.nonZeros());
  view.p = shifted.outerIndexPtr();
  view.i = shifted.innerIndexPtr();
  view.x = shifted.valuePtr();
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  cholmod_factor* factor = cholmod_analyze(&view, &common);
  if (factor) cholmod_factorize(&view, factor, &common);
  if (!factor || common.status == CHOLMOD_OUT_OF_MEMORY || common.status < 0) {
    out.message = "the LDL^T factorization of K - sigma M failed (out of memory?)";
  } else if (factor->is_super || factor->is_ll) {
    out.message = "CHOLMOD did not return a simplicial LDL^T factor";
  } else {
    // Simplicial LDL^T: D(j, j) is the first entry of column j of L.
    const auto* p = static_cast<const int*>(factor->p);
    const auto* x = static_cast<const double*>(factor->x);
    for (size_t j = 0; j < factor->n; ++j) {
      const double d = x[p[j]];
      out.negative += d < 0.0 ? 1 : 0;
      out.zero += d == 0.0 ? 1 : 0;
    }
    out.ok = factor->minor == factor->n && out.zero == 0;
    if (!out.ok) out.message = "a zero pivot: the shift is an eigenvalue";
  }
  if (factor) cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace bb
