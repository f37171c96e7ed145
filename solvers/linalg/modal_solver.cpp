#include "linalg/modal_solver.hpp"

#include <Eigen/Eigenvalues>
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
#include "linalg/real_form.hpp"
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
  for (Eigen::Index k = 0; k < sol.shapes.cols(); ++k) {
    sol.shapes.col(k) /= std::sqrt(sol.shapes.col(k).dot(mass * sol.shapes.col(k)));
    sol.eigenvalues[k] = rayleigh_quotient(stiffness, mass, Eigen::VectorXd(sol.shapes.col(k)));
  }
  sort_by_eigenvalue(sol);
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
  for (Eigen::Index k = 0; k < sol.shapes.cols(); ++k)
    sol.eigenvalues[k] = rayleigh_quotient(stiffness, mass, Eigen::VectorXcd(sol.shapes.col(k)));
  sort_by_eigenvalue(sol);
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

// The Hermitian pencil on SLEPc (a real build of PETSc) through its real form, where every
// eigenvalue appears twice (z and i z): 2n real modes are solved and folded back into n complex
// ones by a Rayleigh-Ritz step on the complex span of (a + i b) of each real vector (a; b). That
// span has dimension n exactly: its Gram matrix has n eigenvalues near 2 and n near 0.
HermitianModalSolution slepc_hermitian_lowest_modes(const Eigen::SparseMatrix<std::complex<double>>& stiffness,
                                                    const Eigen::SparseMatrix<std::complex<double>>& mass,
                                                    const ModalOptions& options) {
  if (options.n_modes < 1) throw std::invalid_argument("n_modes must be >= 1");
  ModalOptions doubled = options;
  doubled.n_modes = 2 * options.n_modes;
  const ModalSolution real = slepc_lowest_modes(real_form(stiffness), real_form(mass), doubled);
  const Eigen::Index n = stiffness.rows(), found = real.eigenvalues.size();
  if (found == 0 || found % 2 != 0 || (real.sturm_count >= 0 && real.sturm_count % 2 != 0))
    throw SolverError(fmt::format(
        "the real form of a Hermitian pencil gave {} modes and a count of {}: each eigenvalue must appear twice", found,
        real.sturm_count));
  const Eigen::MatrixXcd z = real.shapes.topRows(n).cast<std::complex<double>>() +
                             std::complex<double>(0.0, 1.0) * real.shapes.bottomRows(n).cast<std::complex<double>>();
  const Eigen::MatrixXcd mz = mass * z;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> gram(z.adjoint() * mz);
  const Eigen::Index keep = found / 2;
  const Eigen::VectorXd g = gram.eigenvalues();  // ascending
  if (!(g[found - keep] > 1.0 && g[found - keep - 1] < 1.0))
    throw SolverError(
        fmt::format("the real form's {} modes do not span {} complex ones (Gram eigenvalues {:.3g} "
                    "and {:.3g} around the cut, 2 and 0 expected)",
                    found, keep, g[found - keep], g[found - keep - 1]));
  const Eigen::MatrixXcd basis =
      z * (gram.eigenvectors().rightCols(keep) * g.tail(keep).cwiseSqrt().cwiseInverse().asDiagonal());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> ritz(basis.adjoint() * (stiffness * basis));
  HermitianModalSolution sol;
  sol.eigenvalues = ritz.eigenvalues();
  sol.shapes = basis * ritz.eigenvectors();
  for (Eigen::Index k = 0; k < sol.shapes.cols(); ++k)
    sol.eigenvalues[k] = rayleigh_quotient(stiffness, mass, Eigen::VectorXcd(sol.shapes.col(k)));
  sort_by_eigenvalue(sol);
  sol.iterations = real.iterations;
  sol.converged_modes = static_cast<int>(keep);
  sol.sturm_count = real.sturm_count < 0 ? -1 : real.sturm_count / 2;
  sol.sturm_shift = real.sturm_shift;
  sol.lanczos_runs = real.lanczos_runs;
  sol.sturm_seconds = real.sturm_seconds;
  sol.max_residual = max_backward_error(stiffness, mass, sol);
  return sol;
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
  if (options.eigensolver == Eigensolver::slepc) return slepc_hermitian_lowest_modes(stiffness, mass, options);
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
