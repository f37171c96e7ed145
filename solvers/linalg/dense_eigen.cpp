#include "linalg/dense_eigen.hpp"

#include <Eigen/Eigenvalues>

namespace bb {
namespace {

template <class Solver, class Scalar>
DenseEigen<Scalar> result_of(const Solver& s, bool vectors) {
  DenseEigen<Scalar> out;
  out.ok = s.info() == Eigen::Success;
  out.values = s.eigenvalues();
  if (vectors) out.vectors = s.eigenvectors();
  return out;
}

int options(bool vectors) { return vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly; }

}  // namespace

DenseEigen<double> symmetric_eigen(const Eigen::MatrixXd& a, bool vectors) {
  return result_of<Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>, double>(
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, options(vectors)), vectors);
}

DenseEigen<std::complex<double>> symmetric_eigen(const Eigen::MatrixXcd& a, bool vectors) {
  return result_of<Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>, std::complex<double>>(
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(a, options(vectors)), vectors);
}

DenseEigen<double> symmetric_eigen(const Eigen::MatrixXd& k, const Eigen::MatrixXd& m, bool vectors) {
  return result_of<Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>, double>(
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(k, m, options(vectors) | Eigen::Ax_lBx), vectors);
}

DenseEigen<std::complex<double>> symmetric_eigen(const Eigen::MatrixXcd& k, const Eigen::MatrixXcd& m, bool vectors) {
  return result_of<Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd>, std::complex<double>>(
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd>(k, m, options(vectors) | Eigen::Ax_lBx), vectors);
}

}  // namespace bb
