// Eigenpairs of small dense symmetric (or Hermitian) matrices and of symmetric-definite pencils
// K x = lambda M x: Eigen's solvers, instantiated once (linalg/dense_eigen.cpp) instead of in every
// file that needs them, which each took seconds to compile.
#pragma once
#include <Eigen/Core>

#include <complex>

namespace bb {

template <class Scalar>
struct DenseEigen {
  Eigen::VectorXd values;                                         // ascending
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> vectors;  // one per column (M-normalized for a
                                                                  // pencil); empty without `vectors`
  bool ok = false;  // Eigen's report (values and vectors are filled either way, as Eigen leaves them)
};

// A = A^T (A^H): only its lower triangle is read.
DenseEigen<double> symmetric_eigen(const Eigen::MatrixXd& a, bool vectors = true);
DenseEigen<std::complex<double>> symmetric_eigen(const Eigen::MatrixXcd& a, bool vectors = true);
// K x = lambda M x with K symmetric (Hermitian) and M positive definite.
DenseEigen<double> symmetric_eigen(const Eigen::MatrixXd& k, const Eigen::MatrixXd& m, bool vectors = true);
DenseEigen<std::complex<double>> symmetric_eigen(const Eigen::MatrixXcd& k, const Eigen::MatrixXcd& m,
                                                 bool vectors = true);

}  // namespace bb
