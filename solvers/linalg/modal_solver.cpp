#include "linalg/modal_solver.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
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
    if (!s.ok) throw SolverError(fmt::format("modal shift-invert: K - sigma M with sigma = {:.6g}: {}", sigma, s.message));
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) = factor_.solve(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(x_in, rows())));
  }

 private:
  const Eigen::SparseMatrix<double>& k_;
  const Eigen::SparseMatrix<double>& m_;
  SpdFactorization factor_;
};

}  // namespace

ModalSolution lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                           const ModalOptions& options) {
  const auto n = stiffness.rows();
  if (options.n_modes < 1) throw std::invalid_argument("n_modes must be >= 1");
  if (options.n_modes >= n) {
    throw SolverError(fmt::format("asked for {} modes of a model with only {} free DOFs", options.n_modes, n));
  }
  const double sigma = -std::pow(2 * std::numbers::pi * options.shift_frequency_hz, 2);
  const int ncv = static_cast<int>(std::min<Eigen::Index>(
      n, options.subspace_size > 0 ? options.subspace_size : std::max(2 * options.n_modes + 1, 20)));
  ShiftInvertOp op(stiffness, mass, options.ordering);
  Spectra::SparseSymMatProd<double> bop(mass);
  Spectra::SymGEigsShiftSolver<ShiftInvertOp, Spectra::SparseSymMatProd<double>, Spectra::GEigsMode::ShiftInvert>
      eigs(op, bop, options.n_modes, ncv, sigma);
  eigs.init();
  const auto found = eigs.compute(Spectra::SortRule::LargestMagn, options.max_iterations, options.tolerance,
                                  Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful || found < options.n_modes) {
    throw SolverError(fmt::format("Lanczos found {} of {} modes in {} iterations (tolerance {:.1e})", found,
                                  options.n_modes, eigs.num_iterations(), options.tolerance));
  }
  ModalSolution sol;
  sol.eigenvalues = eigs.eigenvalues();
  sol.shapes = eigs.eigenvectors();
  sol.iterations = static_cast<int>(eigs.num_iterations());
  sol.converged_modes = static_cast<int>(found);
  // Normwise backward error, meaningful for rigid-body modes too (where K x ~ 0).
  auto norm1 = [](const Eigen::SparseMatrix<double>& a) {
    double best = 0.0;
    for (int c = 0; c < a.outerSize(); ++c) {
      double sum = 0.0;
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it) sum += std::abs(it.value());
      best = std::max(best, sum);
    }
    return best;
  };
  const double k_norm = norm1(stiffness), m_norm = norm1(mass);
  for (Eigen::Index k = 0; k < sol.shapes.cols(); ++k) {
    const double modal_mass = sol.shapes.col(k).dot(mass * sol.shapes.col(k));
    sol.shapes.col(k) /= std::sqrt(modal_mass);
    const Eigen::VectorXd kx = stiffness * sol.shapes.col(k);
    const double scale = (k_norm + std::abs(sol.eigenvalues[k]) * m_norm) * sol.shapes.col(k).norm();
    const double res = (kx - sol.eigenvalues[k] * (mass * sol.shapes.col(k))).norm() / std::max(scale, 1e-300);
    sol.max_residual = std::max(sol.max_residual, res);
  }
  return sol;
}

}  // namespace bb
