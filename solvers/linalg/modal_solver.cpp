#include "linalg/modal_solver.hpp"

#include <Spectra/SymGEigsShiftSolver.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "common/errors.hpp"
#include "linalg/hermitian_lanczos.hpp"
#include "linalg/inertia.hpp"
#include "linalg/modal_cut.hpp"
#include "linalg/modal_residual.hpp"
#include "linalg/slepc_modes.hpp"
#include "linalg/spd_factor.hpp"

namespace bb {
namespace {

// y = (K - sigma M)^{-1} x through one Cholesky factor, the operator Spectra's shift-invert mode needs.
class ShiftInvertOp {
 public:
  using Scalar = double;
  ShiftInvertOp(const Eigen::SparseMatrix<double>& k, const Eigen::SparseMatrix<double>& m, FillOrdering ordering)
      : k_(k), m_(m), factor_(ordering) {}
  Eigen::Index rows() const { return k_.rows(); }
  Eigen::Index cols() const { return k_.cols(); }
  void set_shift(double sigma) {
    Eigen::SparseMatrix<double> shifted = k_ - sigma * m_;
    shifted.makeCompressed();
    const FactorStatus s = factor_.factorize(shifted);
    if (!s.ok)
      throw SolverError(fmt::format("modal shift-invert: K - sigma M with sigma = {:.6g}: {}", sigma, s.message));
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) =
        factor_.solve(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(x_in, rows())));
  }

 private:
  const Eigen::SparseMatrix<double>& k_;
  const Eigen::SparseMatrix<double>& m_;
  SpdFactorization factor_;
};

// y = M x with both triangles stored row by row: Lanczos takes three to five mass products per
// step (its M-inner products), and a self-adjoint view of one triangle scatters its writes.
class MassProduct {
 public:
  using Scalar = double;
  explicit MassProduct(const Eigen::SparseMatrix<double>& mass) : full_(mass) {}
  Eigen::Index rows() const { return full_.rows(); }
  Eigen::Index cols() const { return full_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<Eigen::VectorXd>(y_out, rows()).noalias() = full_ * Eigen::Map<const Eigen::VectorXd>(x_in, rows());
  }

 private:
  Eigen::SparseMatrix<double, Eigen::RowMajor> full_;
};

// One Lanczos run for the lowest `nev` modes with `ncv` vectors; shapes mass-normalized.
ModalSolution lanczos_run(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                          const ModalOptions& options, int nev, int ncv) {
  const double sigma = -std::pow(2 * std::numbers::pi * options.shift_frequency_hz, 2);
  ShiftInvertOp op(stiffness, mass, options.ordering);
  MassProduct bop(mass);
  Spectra::SymGEigsShiftSolver<ShiftInvertOp, MassProduct, Spectra::GEigsMode::ShiftInvert> eigs(op, bop, nev, ncv,
                                                                                                 sigma);
  eigs.init();
  const auto found = eigs.compute(Spectra::SortRule::LargestMagn, options.max_iterations, options.tolerance,
                                  Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful || found < nev) {
    throw SolverError(fmt::format("Lanczos found {} of {} modes in {} iterations (tolerance {:.1e})", found, nev,
                                  eigs.num_iterations(), options.tolerance));
  }
  ModalSolution sol;
  sol.eigenvalues = eigs.eigenvalues();
  sol.shapes = eigs.eigenvectors();
  sol.iterations = static_cast<int>(eigs.num_iterations());
  sol.converged_modes = static_cast<int>(found);
  for (Eigen::Index k = 0; k < sol.shapes.cols(); ++k)
    sol.shapes.col(k) /= std::sqrt(sol.shapes.col(k).dot(mass * sol.shapes.col(k)));
  return sol;
}

HermitianModalSolution lanczos_run(const Eigen::SparseMatrix<std::complex<double>>& stiffness,
                                   const Eigen::SparseMatrix<std::complex<double>>& mass, const ModalOptions& options,
                                   int nev, int ncv) {
  HermitianLanczosOptions o;
  o.nev = nev;
  o.ncv = ncv;
  o.sigma = -std::pow(2 * std::numbers::pi * options.shift_frequency_hz, 2);
  o.tolerance = options.tolerance;
  o.max_restarts = options.max_iterations;
  o.ordering = options.ordering;
  const HermitianLanczosResult r = hermitian_lanczos(stiffness, mass, o);
  HermitianModalSolution sol;
  sol.eigenvalues = r.eigenvalues;
  sol.shapes = r.shapes;
  sol.iterations = r.restarts + 1;
  sol.converged_modes = nev;
  return sol;
}

template <class Scalar>
BasicModalSolution<Scalar> first_modes(BasicModalSolution<Scalar> sol, int count) {
  sol.eigenvalues.conservativeResize(count);
  sol.shapes.conservativeResize(Eigen::NoChange, count);
  sol.converged_modes = count;
  return sol;
}

template <class Scalar>
BasicModalSolution<Scalar> complete_lowest_modes(const Eigen::SparseMatrix<Scalar>& stiffness,
                                                 const Eigen::SparseMatrix<Scalar>& mass, const ModalOptions& options) {
  const auto n = stiffness.rows();
  if (options.n_modes < 1) throw std::invalid_argument("n_modes must be >= 1");
  if (options.n_modes >= n) {
    throw SolverError(fmt::format("asked for {} modes of a model with only {} free DOFs", options.n_modes, n));
  }
  const int most = static_cast<int>(n) - 1;  // Spectra needs nev < n
  auto vectors = [&](int nev, int run) {
    const int base = options.subspace_size > 0 ? options.subspace_size : std::max(2 * nev + 1, 20);
    return static_cast<int>(std::min<Eigen::Index>(n, run == 0 ? base : std::max(base, 2 * nev + 1) + 10 * run));
  };
  int nev = options.n_modes;
  double sturm_seconds = 0.0;
  for (int run = 0;; ++run) {
    BasicModalSolution<Scalar> sol = lanczos_run(stiffness, mass, options, nev, vectors(nev, run));
    sol.lanczos_runs = run + 1;
    const std::optional<double> cut =
        options.verify_count ? count_shift(sol.eigenvalues, options.n_modes, options.cluster_tolerance) : std::nullopt;
    if (!cut) {
      sol = first_modes(std::move(sol), options.n_modes);
      sol.max_residual = max_backward_error(stiffness, mass, sol);
      return sol;
    }
    InertiaCount count = eigenvalues_below(stiffness, mass, *cut);
    double shift = *cut;
    if (!count.ok) {  // the shift hit an eigenvalue to the last bit: move it a little
      shift = *cut + options.cluster_tolerance * std::abs(*cut);
      count = eigenvalues_below(stiffness, mass, shift);
    }
    sturm_seconds += count.seconds;
    if (!count.ok)
      throw SolverError(fmt::format("modal completeness check at {:.6g} rad^2/s^2: {}", shift, count.message));
    const auto found = static_cast<int>((sol.eigenvalues.array() <= shift).count());
    if (found == count.negative || run == options.max_reruns || nev >= most) {
      if (found != count.negative)
        throw SolverError(
            fmt::format("Lanczos found {} eigenvalues below {:.6g} Hz but the Sturm count of K - sigma M "
                        "is {} after {} runs: a mode would be missing",
                        found, std::sqrt(std::max(shift, 0.0)) / (2 * std::numbers::pi), count.negative, run + 1));
      sol = first_modes(std::move(sol), std::max(options.n_modes, count.negative));
      sol.sturm_count = count.negative;
      sol.sturm_shift = shift;
      sol.sturm_seconds = sturm_seconds;
      sol.max_residual = max_backward_error(stiffness, mass, sol);
      return sol;
    }
    // Missed modes (or a cluster that straddles the n-th): ask for all of them, and a margin.
    nev = std::min(std::max(count.negative, found) + 2, most);
  }
}

}  // namespace

ModalSolution lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                           const ModalOptions& options) {
  if (options.eigensolver == Eigensolver::slepc) return slepc_lowest_modes(stiffness, mass, options);
  return complete_lowest_modes(stiffness, mass, options);
}

HermitianModalSolution lowest_modes(const Eigen::SparseMatrix<std::complex<double>>& stiffness,
                                    const Eigen::SparseMatrix<std::complex<double>>& mass,
                                    const ModalOptions& options) {
  if (options.eigensolver == Eigensolver::slepc)
    throw InputError(
        "eigensolver = \"slepc\" solves real symmetric pencils; a complex Hermitian one (a cyclic sector's "
        "travelling-wave nodal diameters) takes the default eigensolver (\"spectra\")");
  return complete_lowest_modes(stiffness, mass, options);
}

std::optional<ModalSolution> leading_modes(const ModalSolution& sol, const ModalOptions& options) {
  const int n = options.n_modes;
  if (n < 1 || sol.eigenvalues.size() < n) return std::nullopt;
  const std::optional<double> cut =
      options.verify_count ? count_shift(sol.eigenvalues, n, options.cluster_tolerance) : std::nullopt;
  if (!cut) return first_modes(sol, n);
  if (sol.sturm_count < 0 || *cut > sol.sturm_shift) return std::nullopt;
  // The count of the larger solution proves the leading ones complete too, so it is kept.
  return first_modes(sol, std::max(n, static_cast<int>((sol.eigenvalues.array() <= *cut).count())));
}

}  // namespace bb
