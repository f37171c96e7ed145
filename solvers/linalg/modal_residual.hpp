// The normwise backward error of computed modes, max_k ||K x - w^2 M x|| / ((||K|| + w^2 ||M||) ||x||)
// (1-norms of K and M): meaningful for rigid-body modes too, where K x ~ 0. Every eigensolver
// reports it the same way (linalg/modal_solver.cpp, linalg/slepc_modes.cpp).
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "linalg/modal_solver.hpp"

namespace bb {

template <class Scalar>
double sparse_norm1(const Eigen::SparseMatrix<Scalar>& a) {
  double best = 0.0;
  for (int c = 0; c < a.outerSize(); ++c) {
    double sum = 0.0;
    for (typename Eigen::SparseMatrix<Scalar>::InnerIterator it(a, c); it; ++it) sum += std::abs(it.value());
    best = std::max(best, sum);
  }
  return best;
}

template <class Scalar>
double max_backward_error(const Eigen::SparseMatrix<Scalar>& stiffness, const Eigen::SparseMatrix<Scalar>& mass,
                          const BasicModalSolution<Scalar>& sol) {
  const double k_norm = sparse_norm1(stiffness), m_norm = sparse_norm1(mass);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < sol.shapes.cols(); ++k) {
    const Eigen::Matrix<Scalar, Eigen::Dynamic, 1> kx = stiffness * sol.shapes.col(k);
    const double scale = (k_norm + std::abs(sol.eigenvalues[k]) * m_norm) * sol.shapes.col(k).norm();
    const double res = (kx - sol.eigenvalues[k] * (mass * sol.shapes.col(k))).norm() / std::max(scale, 1e-300);
    worst = std::max(worst, res);
  }
  return worst;
}

// x^H K x / x^H M x with both sums accumulated in long double (x86's 64-bit mantissa). In double
// the quotient carries a rounding error of about eps ||K|| / lambda relative (1e-9 for a stiff mesh's
// first mode, whatever the eigensolver); the shape's own error enters only squared. For Hermitian K
// and M the forms are real; their real parts are summed.
template <class Scalar>
double rayleigh_quotient(const Eigen::SparseMatrix<Scalar>& stiffness, const Eigen::SparseMatrix<Scalar>& mass,
                         const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x) {
  const auto quadratic_form = [&](const Eigen::SparseMatrix<Scalar>& a) {
    long double sum = 0.0L;
    for (Eigen::Index c = 0; c < a.outerSize(); ++c) {
      // conj(x_r) A_rc x_c; for Hermitian A its real part, as Re(conj(x_r) (A_rc x_c)).
      for (typename Eigen::SparseMatrix<Scalar>::InnerIterator it(a, c); it; ++it) {
        if constexpr (Eigen::NumTraits<Scalar>::IsComplex) {
          const long double ar = it.value().real(), ai = it.value().imag(), xr = x[c].real(), xi = x[c].imag();
          const long double yr = ar * xr - ai * xi, yi = ar * xi + ai * xr;  // A_rc x_c, exact in long double
          sum +=
              static_cast<long double>(x[it.index()].real()) * yr + static_cast<long double>(x[it.index()].imag()) * yi;
        } else {
          sum += static_cast<long double>(x[it.index()]) * it.value() * static_cast<long double>(x[c]);
        }
      }
    }
    return sum;
  };
  return static_cast<double>(quadratic_form(stiffness) / quadratic_form(mass));
}

// Modes in ascending eigenvalue order (stable): quotients refined after a solver sorted them may
// swap members of a cluster by a rounding.
template <class Scalar>
void sort_by_eigenvalue(BasicModalSolution<Scalar>& sol) {
  std::vector<Eigen::Index> order(static_cast<size_t>(sol.eigenvalues.size()));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return sol.eigenvalues[a] < sol.eigenvalues[b]; });
  if (std::is_sorted(order.begin(), order.end())) return;
  const BasicModalSolution<Scalar> unsorted = sol;
  for (size_t j = 0; j < order.size(); ++j) {
    sol.eigenvalues[static_cast<Eigen::Index>(j)] = unsorted.eigenvalues[order[j]];
    sol.shapes.col(static_cast<Eigen::Index>(j)) = unsorted.shapes.col(order[j]);
  }
}

}  // namespace bb
