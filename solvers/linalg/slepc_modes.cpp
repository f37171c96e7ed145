#include "linalg/slepc_modes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <numeric>
#include <optional>
#include <vector>

#include "common/errors.hpp"
#include "distributed/distributed.hpp"
#include "distributed/plugin.hpp"
#include "linalg/modal_cut.hpp"
#include "linalg/modal_residual.hpp"

namespace bb {
namespace {

// The upper triangle row by row: column c of a symmetric matrix stored whole (or its lower
// triangle) holds row c of the upper triangle in its entries r >= c.
struct UpperRows {
  std::vector<int64_t> start, column;
  std::vector<double> value;
  bb_upper_csr view() const {
    return {static_cast<int64_t>(start.size()) - 1, start.data(), column.data(), value.data()};
  }
};

UpperRows upper_rows(const Eigen::SparseMatrix<double>& a) {
  UpperRows u;
  u.start.reserve(static_cast<size_t>(a.cols()) + 1);
  u.start.push_back(0);
  for (int c = 0; c < a.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it)
      if (it.row() >= c) {
        u.column.push_back(it.row());
        u.value.push_back(it.value());
      }
    u.start.push_back(static_cast<int64_t>(u.column.size()));
  }
  return u;
}

const bb_plugin& slepc() { return distributed::plugin("eigensolver = \"slepc\""); }

// A failure on one rank while the others wait in a collective call would hang them: under mpirun
// the failing rank says why and stops every rank (exit 3).
void stop_on_failure(int status, const std::string& what, const char* message) {
  if (status == 0) return;
  const std::string text = fmt::format("{}: {}", what, message);
  if (distributed::shared_solves() && distributed::size() > 1) {
    std::fprintf(stderr, "error: MPI rank %d of %d: %s\n", distributed::rank(), distributed::size(), text.c_str());
    std::fflush(stderr);
    distributed::abort_all(exit_solver_failed);
  }
  throw SolverError(text);
}

// BLADEBENCH_FAULT_RANK=r fails the solve on rank r before it starts (the abort path's test).
bool fault_injected() {
  const char* r = std::getenv("BLADEBENCH_FAULT_RANK");
  return r && *r && std::atoi(r) == distributed::rank();
}

struct Result {
  bb_modes_result raw{};
  ~Result() {
    if (raw.eigenvalues || raw.vectors || raw.shift_values || raw.inertias) slepc().free_result(&raw);
  }
};

void run(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
         const bb_modes_request& request, Result& out, const std::string& what) {
  const UpperRows k = upper_rows(stiffness), m = upper_rows(mass);
  const bb_upper_csr kv = k.view(), mv = m.view();
  if (request.world) distributed::count_shared_work();
  char message[1024] = "fault injected by BLADEBENCH_FAULT_RANK";
  const int status = fault_injected() ? 1 : slepc().modes(&kv, &mv, &request, &out.raw, message, sizeof message);
  stop_on_failure(status, what, message);
  // For bench/: each SLEPc call's time and the shifts it factorized (BLADEBENCH_SLEPC_TRACE=1).
  if (std::getenv("BLADEBENCH_SLEPC_TRACE") && distributed::is_root())
    std::fprintf(stderr, "slepc: %s: %d eigenpairs, %d shifts, %d iterations, %.3f s\n", what.c_str(), out.raw.count,
                 out.raw.shifts, out.raw.iterations, out.raw.seconds);
}

bb_modes_request request_for(const ModalOptions& options) {
  bb_modes_request r{};
  r.world = distributed::shared_solves() ? 1 : 0;
  r.lower = -std::pow(2 * std::numbers::pi * options.shift_frequency_hz, 2);
  r.tolerance = options.tolerance;
  r.max_iterations = options.max_iterations;
  r.out_of_core = options.out_of_core ? 1 : 0;
  return r;
}

// Mass-normalized, the largest entry of each shape positive: the same shapes on any number of ranks.
ModalSolution solution_of(const bb_modes_result& r, const Eigen::SparseMatrix<double>& mass,
                          const Eigen::SparseMatrix<double>* stiffness) {
  std::vector<int> order(static_cast<size_t>(r.count));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return r.eigenvalues[a] < r.eigenvalues[b]; });
  ModalSolution sol;
  sol.eigenvalues.resize(r.count);
  sol.shapes.resize(static_cast<Eigen::Index>(r.n), r.count);
  for (int j = 0; j < r.count; ++j) {
    const int i = order[static_cast<size_t>(j)];
    sol.eigenvalues[j] = r.eigenvalues[i];
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(r.vectors + static_cast<int64_t>(i) * r.n, r.n);
    x /= std::sqrt(x.dot(mass * x));
    // The Rayleigh quotient of the shape as returned: an error in the shape enters it only squared.
    if (stiffness) sol.eigenvalues[j] = rayleigh_quotient(*stiffness, mass, x);
    Eigen::Index top = 0;
    x.cwiseAbs().maxCoeff(&top);
    if (x[top] < 0) x = -x;
    sol.shapes.col(j) = x;
  }
  sort_by_eigenvalue(sol);
  sol.iterations = r.iterations;
  sol.converged_modes = r.count;
  return sol;
}

// Eigenvalues in [lower, upper] by the inertias at the interval's ends (the slicing's first and
// last shift), checked against what was returned.
ModalSolution sliced(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                     bb_modes_request request, const std::string& what) {
  Result r;
  run(stiffness, mass, request, r, what);
  if (r.raw.shifts < 2)
    throw SolverError(
        fmt::format("{}: the slicing reported {} shifts (the interval's two ends expected)", what, r.raw.shifts));
  const int below_upper = r.raw.inertias[r.raw.shifts - 1], below_lower = r.raw.inertias[0];
  const int count = below_upper - below_lower;
  if (count != r.raw.count)
    throw SolverError(
        fmt::format("{}: {} eigenvalues returned in [{:.6g}, {:.6g}] rad^2/s^2 but the inertias of "
                    "its ends count {}: a mode would be missing",
                    what, r.raw.count, request.lower, request.upper, count));
  ModalSolution sol = solution_of(r.raw, mass, &stiffness);
  sol.sturm_count = below_upper;
  sol.sturm_shift = request.upper;
  sol.sturm_seconds = 0.0;  // from the slicing's own factorizations
  sol.lanczos_runs = 1;
  return sol;
}

}  // namespace

ModalSolution slepc_modes_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                double cut, const ModalOptions& options) {
  bb_modes_request request = request_for(options);
  if (!(cut > request.lower))
    throw InputError(
        fmt::format("eigensolver = \"slepc\": the band's top ({:.6g} rad^2/s^2) must lie above the "
                    "shift ({:.6g})",
                    cut, request.lower));
  request.upper = cut;
  ModalSolution sol = sliced(stiffness, mass, request, "SLEPc spectrum slicing");
  sol.max_residual = max_backward_error(stiffness, mass, sol);
  return sol;
}

ModalSolution slepc_lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                 const ModalOptions& options) {
  const auto n = stiffness.rows();
  if (options.n_modes < 1) throw std::invalid_argument("n_modes must be >= 1");
  if (options.n_modes >= n)
    throw SolverError(fmt::format("asked for {} modes of a model with only {} free DOFs", options.n_modes, n));
  // The estimate's Ritz values lie above the eigenvalues they approximate, so an interval up to the
  // n-th of them (and a cluster's width more) holds at least n modes.
  bb_modes_request estimate = request_for(options);
  estimate.n_estimate = options.n_modes;
  // A Ritz value's error is about the square of its residual: 1e-6 places the cut to 1e-12.
  estimate.tolerance = std::max(options.tolerance, 1e-6);
  Result first;
  run(stiffness, mass, estimate, first, "SLEPc Krylov-Schur (the n-th eigenvalue)");
  const ModalSolution guess = solution_of(first.raw, mass, nullptr);
  const std::optional<double> cut = count_shift(guess.eigenvalues, options.n_modes, options.cluster_tolerance);
  if (!cut) {  // every mode found is rigid: nothing to separate, as the default eigensolver does
    ModalSolution sol = guess;
    sol.lanczos_runs = 1;
    sol.max_residual = max_backward_error(stiffness, mass, sol);
    return sol;
  }
  bb_modes_request slice = request_for(options);
  slice.upper = *cut;
  ModalSolution sol = sliced(stiffness, mass, slice, "SLEPc spectrum slicing");
  if (sol.eigenvalues.size() < options.n_modes)
    throw SolverError(fmt::format("SLEPc spectrum slicing found {} modes below {:.6g} Hz where {} were asked for",
                                  sol.eigenvalues.size(), std::sqrt(std::max(*cut, 0.0)) / (2 * std::numbers::pi),
                                  options.n_modes));
  // The estimate may have missed a member of a repeated eigenvalue, putting its n-th Ritz value on
  // the next mode: keep the n-th mode's cluster and no more. Every eigenvalue below the slicing's
  // top is in `sol`, so the kept ones are all those below the lower cut.
  const std::optional<double> kept_cut = count_shift(sol.eigenvalues, options.n_modes, options.cluster_tolerance);
  const auto kept =
      kept_cut ? static_cast<Eigen::Index>((sol.eigenvalues.array() <= *kept_cut).count()) : sol.eigenvalues.size();
  if (kept < sol.eigenvalues.size()) {
    sol.eigenvalues.conservativeResize(kept);
    sol.shapes.conservativeResize(Eigen::NoChange, kept);
    sol.converged_modes = static_cast<int>(kept);
    sol.sturm_count = static_cast<int>(kept);
    sol.sturm_shift = *kept_cut;
  }
  sol.iterations += guess.iterations;
  sol.lanczos_runs = 2;
  sol.max_residual = max_backward_error(stiffness, mass, sol);
  return sol;
}

Eigen::MatrixXd slepc_solve_spd(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& b) {
  const UpperRows u = upper_rows(a);
  const bb_upper_csr view = u.view();
  Eigen::MatrixXd x(b.rows(), b.cols());
  if (distributed::shared_solves()) distributed::count_shared_work();
  char message[1024] = {0};
  const int status = slepc().solve_spd(&view, b.data(), b.cols(), distributed::shared_solves() ? 1 : 0, x.data(),
                                       message, sizeof message);
  // MUMPS's pivot counts are global: every rank throws alike, none waits.
  if (status == BB_NOT_POSITIVE_DEFINITE) throw NotPositiveDefinite(message);
  stop_on_failure(status, "PETSc MUMPS Cholesky solve", message);
  return x;
}

}  // namespace bb
