#include "linalg/inertia.hpp"

#include <dmumps_c.h>
#include <fmt/format.h>

#include <chrono>
#include <mutex>
#include <vector>

namespace bb {
namespace {

// MUMPS's control arrays are documented 1-based (ICNTL(7) is icntl[6]).
constexpr int kUseCommWorld = -987654;
constexpr int kOrderingAutomatic = 7;

}  // namespace

InertiaCount eigenvalues_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                               double sigma) {
  const auto t0 = std::chrono::steady_clock::now();
  InertiaCount out;
  Eigen::SparseMatrix<double> shifted = stiffness - sigma * mass;
  shifted.makeCompressed();
  // Lower triangle in 1-based coordinates, the input of a symmetric MUMPS factorization.
  std::vector<MUMPS_INT> rows, cols;
  std::vector<double> values;
  rows.reserve(static_cast<size_t>(shifted.nonZeros()));
  cols.reserve(rows.capacity());
  values.reserve(rows.capacity());
  for (int c = 0; c < shifted.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(shifted, c); it; ++it)
      if (it.row() >= c) {
        rows.push_back(static_cast<MUMPS_INT>(it.row() + 1));
        cols.push_back(static_cast<MUMPS_INT>(c + 1));
        values.push_back(it.value());
      }
  // The multifrontal LDL^T of a general symmetric matrix (SYM = 2, with 2x2 pivots): its inertia is
  // that of K - sigma M, and unlike CHOLMOD's simplicial LDL^T it runs on BLAS-3 fronts.
  // The sequential MUMPS keeps global state (its MPI stand-in, load bookkeeping): one instance at a
  // time in this process, whatever threads ask (calibration starts, force levels).
  static std::mutex mumps;
  const std::lock_guard<std::mutex> one_at_a_time(mumps);
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
  id.n = static_cast<MUMPS_INT>(shifted.rows());
  id.nnz = static_cast<MUMPS_INT8>(values.size());
  id.irn = rows.data();
  id.jcn = cols.data();
  id.a = values.data();
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

}  // namespace bb
