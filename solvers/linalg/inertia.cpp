#include "linalg/inertia.hpp"

#include <dmumps_c.h>
#include <fmt/format.h>

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/run_time_module.hpp"
#include "linalg/blas_threads.hpp"

namespace bb {
namespace {

// MUMPS's control arrays are documented 1-based (ICNTL(7) is icntl[6]).
constexpr int kUseCommWorld = -987654;
constexpr int kOrderingAutomatic = 7;

// The lower triangle of a real symmetric matrix in 1-based coordinates: a symmetric MUMPS input.
struct LowerTriangle {
  MUMPS_INT n = 0;
  std::vector<MUMPS_INT> rows, cols;
  std::vector<double> values;
  void reserve(Eigen::Index entries) {
    rows.reserve(static_cast<size_t>(entries));
    cols.reserve(rows.capacity());
    values.reserve(rows.capacity());
  }
  void add(Eigen::Index row, Eigen::Index col, double value) {
    rows.push_back(static_cast<MUMPS_INT>(row + 1));
    cols.push_back(static_cast<MUMPS_INT>(col + 1));
    values.push_back(value);
  }
};

// Negative pivots of the matrix whose lower triangle is given.
InertiaCount negative_pivots(LowerTriangle& a);

}  // namespace

InertiaCount eigenvalues_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                               double sigma) {
  Eigen::SparseMatrix<double> shifted = stiffness - sigma * mass;
  shifted.makeCompressed();
  LowerTriangle lower;
  lower.n = static_cast<MUMPS_INT>(shifted.rows());
  lower.reserve(shifted.nonZeros());
  for (int c = 0; c < shifted.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(shifted, c); it; ++it)
      if (it.row() >= c) lower.add(it.row(), c, it.value());
  return negative_pivots(lower);
}

InertiaCount eigenvalues_below(const Eigen::SparseMatrix<std::complex<double>>& stiffness,
                               const Eigen::SparseMatrix<std::complex<double>>& mass, double sigma) {
  Eigen::SparseMatrix<std::complex<double>> shifted = stiffness - sigma * mass;
  shifted.makeCompressed();
  // The real form [[Re, -Im], [Im, Re]] (linalg/real_form.hpp) written straight into its lower
  // triangle: Re below the diagonal twice, Im whole in the lower-left block.
  const Eigen::Index n = shifted.rows();
  LowerTriangle lower;
  lower.n = static_cast<MUMPS_INT>(2 * n);
  lower.reserve(3 * shifted.nonZeros());
  for (Eigen::Index c = 0; c < shifted.outerSize(); ++c)
    for (Eigen::SparseMatrix<std::complex<double>>::InnerIterator it(shifted, c); it; ++it) {
      if (it.row() >= c) {
        lower.add(it.row(), c, it.value().real());
        lower.add(n + it.row(), n + c, it.value().real());
      }
      if (it.value().imag() != 0.0) lower.add(n + it.row(), c, it.value().imag());
    }
  InertiaCount twice = negative_pivots(lower);
  if (twice.ok && twice.negative % 2 != 0) {
    twice.ok = false;
    twice.message = fmt::format("the real form's count is odd ({}): an eigenvalue of the pair is split by rounding",
                                twice.negative);
  }
  twice.negative /= 2;
  return twice;
}

namespace {

// The sequential MUMPS is loaded at run time into a symbol scope of its own (RTLD_LOCAL), through
// the module that links it (linalg/mumps_module): the PETSc/SLEPc plugin links the MPI build of
// MUMPS, which defines the same symbols, and neither may resolve to the other.
using DmumpsC = void (*)(DMUMPS_STRUC_C*);
DmumpsC sequential_mumps() {
  static const DmumpsC entry = [] {
    using Entry = void* (*)();
    const auto entry_point =
        reinterpret_cast<Entry>(run_time_module_entry({BB_MUMPS_MODULE_BUILD, BB_MUMPS_MODULE_INSTALL},
                                                      "bladebench_dmumps_c", "bladebench's sequential MUMPS module"));
    return reinterpret_cast<DmumpsC>(entry_point());
  }();
  return entry;
}

InertiaCount negative_pivots(LowerTriangle& a) {
  const auto t0 = std::chrono::steady_clock::now();
  InertiaCount out;
  // The multifrontal LDL^T of a general symmetric matrix (SYM = 2, with 2x2 pivots): its inertia is
  // that of K - sigma M, and unlike CHOLMOD's simplicial LDL^T it runs on BLAS-3 fronts.
  // The sequential MUMPS keeps global state (its MPI stand-in, load bookkeeping): one instance at a
  // time in this process, whatever threads ask (calibration starts, force levels).
  use_one_thread_per_factorization();
  static std::mutex mumps;
  const std::lock_guard<std::mutex> one_at_a_time(mumps);
  const DmumpsC dmumps_c = sequential_mumps();
  DMUMPS_STRUC_C id{};
  id.comm_fortran = kUseCommWorld;
  id.par = 1;
  id.sym = 2;
  id.job = -1;
  dmumps_c(&id);
  id.icntl[0] = -1;  // no error, diagnostic or global messages
  id.icntl[1] = -1;
  id.icntl[2] = -1;
  id.icntl[3] = 0;
  id.icntl[6] = kOrderingAutomatic;
  id.icntl[23] = 1;  // detect null pivots: sigma on an eigenvalue
  id.n = a.n;
  id.nnz = static_cast<MUMPS_INT8>(a.values.size());
  id.irn = a.rows.data();
  id.jcn = a.cols.data();
  id.a = a.values.data();
  id.job = 4;  // analysis and factorization
  dmumps_c(&id);
  if (id.infog[0] < 0) {
    out.message = fmt::format("the LDL^T factorization of K - sigma M failed (MUMPS INFOG(1) = {}, INFOG(2) = {})",
                              id.infog[0], id.infog[1]);
  } else {
    out.negative = id.infog[11];  // INFOG(12): negative pivots
    out.zero = id.infog[27];      // INFOG(28): null pivots found
    out.ok = out.zero == 0;
    if (!out.ok) out.message = "a null pivot: the shift is an eigenvalue";
  }
  id.job = -2;
  dmumps_c(&id);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace
}  // namespace bb
