// The normwise backward error of computed modes, max_k ||K x - w^2 M x|| / ((||K|| + w^2 ||M||) ||x||)
// (1-norms of K and M): meaningful for rigid-body modes too, where K x ~ 0. Every eigensolver
// reports it the same way (linalg/modal_solver.cpp, linalg/slepc_modes.cpp).
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>

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

}  // namespace bb
