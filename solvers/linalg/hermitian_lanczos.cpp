#include "linalg/hermitian_lanczos.hpp"

#include <Eigen/CholmodSupport>
#include <cholmod.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "common/errors.hpp"
#include "linalg/blas_threads.hpp"
#include "linalg/dense_eigen.hpp"

namespace bb {
namespace {

using Complex = std::complex<double>;
using ComplexSparse = Eigen::SparseMatrix<Complex>;
using Index = Eigen::Index;

// The basis V (M-orthonormal columns), M V and Op V = (K - sigma M)^{-1} M V, k columns in use.
class KrylovBasis {
 public:
  KrylovBasis(const ComplexSparse& stiffness, const ComplexSparse& mass, const HermitianLanczosOptions& o)
      : mass_(mass), v_(mass.rows(), o.ncv), mv_(mass.rows(), o.ncv), w_(mass.rows(), o.ncv) {
    use_one_thread_per_factorization();
    factor_.cholmod().nmethods = 1;
    factor_.cholmod().method[0].ordering = o.ordering == FillOrdering::amd ? CHOLMOD_AMD : CHOLMOD_METIS;
    factor_.cholmod().postorder = 1;
    ComplexSparse shifted = stiffness - o.sigma * mass;
    shifted.makeCompressed();
    factor_.compute(shifted);
    if (factor_.info() != Eigen::Success)
      throw SolverError(fmt::format(
          "Hermitian shift-invert: K - sigma M with sigma = {:.6g} is not positive definite (CHOLMOD)", o.sigma));
  }

  Index size() const { return k_; }
  Index capacity() const { return v_.cols(); }
  const Eigen::MatrixXcd& v() const { return v_; }
  const Eigen::MatrixXcd& w() const { return w_; }

  // f made M-orthogonal to the basis (twice, classical Gram-Schmidt); its M-norm.
  double orthogonalize(Eigen::VectorXcd& f) const {
    for (int pass = 0; pass < 2; ++pass) f -= v_.leftCols(k_) * (mv_.leftCols(k_).adjoint() * f).eval();
    return std::sqrt(std::max(f.dot(mass_ * f).real(), 0.0));
  }

  // Appends f made M-orthogonal to the basis. When nothing of f is left but rounding, the basis
  // spans an invariant subspace (the Krylov space is exhausted): a random direction goes on.
  void append(Eigen::VectorXcd f, std::mt19937& random) {
    double before = m_norm(f);
    double norm = orthogonalize(f);
    for (int attempt = 0; !(norm > 1e-13 * before) && attempt < 5; ++attempt) {
      f = random_vector(random);
      before = m_norm(f);
      norm = orthogonalize(f);
    }
    if (!(norm > 1e-13 * before)) throw SolverError("Hermitian Lanczos: no direction left to expand the basis");
    v_.col(k_) = f / norm;
    mv_.col(k_) = mass_ * v_.col(k_);
    w_.col(k_) = factor_.solve(Eigen::VectorXcd(mv_.col(k_)));
    ++k_;
  }

  // The basis becomes V Y (Y with orthonormal columns): a thick restart with the kept Ritz vectors.
  void compress(const Eigen::MatrixXcd& y) {
    const Index p = y.cols();
    v_.leftCols(p) = (v_.leftCols(k_) * y).eval();
    mv_.leftCols(p) = (mv_.leftCols(k_) * y).eval();
    w_.leftCols(p) = (w_.leftCols(k_) * y).eval();
    k_ = p;
  }

  // The projection of Op on the basis, V^H M Op V (Hermitian up to rounding).
  Eigen::MatrixXcd projection() const {
    const Eigen::MatrixXcd h = mv_.leftCols(k_).adjoint() * w_.leftCols(k_);
    return 0.5 * (h + h.adjoint());
  }

  double m_norm(const Eigen::VectorXcd& x) const { return std::sqrt(std::max(x.dot(mass_ * x).real(), 0.0)); }

  Eigen::VectorXcd random_vector(std::mt19937& random) const {
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    Eigen::VectorXcd x(mass_.rows());
    for (Index i = 0; i < x.size(); ++i) x[i] = Complex(u(random), u(random));
    return x;
  }

 private:
  const ComplexSparse& mass_;
  Eigen::CholmodSupernodalLLT<ComplexSparse, Eigen::Lower> factor_;
  Eigen::MatrixXcd v_, mv_, w_;
  Index k_ = 0;
};

}  // namespace

HermitianLanczosResult hermitian_lanczos(const ComplexSparse& stiffness, const ComplexSparse& mass,
                                         const HermitianLanczosOptions& o) {
  const Index n = stiffness.rows();
  if (o.nev < 1 || o.ncv <= o.nev || o.ncv > n)
    throw std::invalid_argument(
        fmt::format("hermitian_lanczos: need 0 < nev < ncv <= n, got {}, {}, {}", o.nev, o.ncv, n));
  KrylovBasis basis(stiffness, mass, o);
  std::mt19937 random(20261127);
  Eigen::VectorXcd next = basis.random_vector(random);
  // Ritz vectors kept at a restart: the wanted ones and half the others, as ARPACK does.
  const Index keep = o.nev + (o.ncv - o.nev) / 2;
  double worst = INFINITY;
  for (int restart = 0; restart <= o.max_restarts; ++restart) {
    while (basis.size() < basis.capacity()) {
      basis.append(next, random);
      next = basis.w().col(basis.size() - 1);
    }
    basis.orthogonalize(next);  // the Krylov-Schur residual direction, kept across the restart
    const DenseEigen<std::complex<double>> ritz = symmetric_eigen(Eigen::MatrixXcd(basis.projection()));
    const Index m = basis.size();
    // Largest mu first: the lowest eigenvalues lambda = sigma + 1 / mu.
    const Eigen::MatrixXcd y = ritz.vectors.rowwise().reverse();
    const Eigen::VectorXd mu = ritz.values.reverse();
    worst = 0.0;
    for (Index i = 0; i < o.nev; ++i) {
      const Eigen::VectorXcd r = basis.w().leftCols(m) * y.col(i) - mu[i] * (basis.v().leftCols(m) * y.col(i));
      worst = std::max(worst, basis.m_norm(r) / std::max(std::abs(mu[i]), 1e-300));
    }
    if (worst <= o.tolerance) {
      // Ascending lambda follows from descending mu > 0; a non-positive mu is a failed shift.
      if (!(mu[o.nev - 1] > 0.0))
        throw SolverError("Hermitian shift-invert: a non-positive Ritz value (K - sigma M is not positive definite)");
      HermitianLanczosResult out;
      out.restarts = restart;
      out.shapes = basis.v().leftCols(m) * y.leftCols(o.nev);
      out.eigenvalues = (o.sigma + mu.head(o.nev).array().inverse()).matrix();
      return out;
    }
    basis.compress(y.leftCols(keep));
  }
  throw SolverError(
      fmt::format("Hermitian Lanczos: {} pairs not converged after {} restarts (worst relative residual "
                  "{:.2e}, tolerance {:.1e})",
                  o.nev, o.max_restarts, worst, o.tolerance));
}

}  // namespace bb
