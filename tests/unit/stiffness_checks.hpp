// Spectral checks shared by the element tests (plane and solid).
#pragma once
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>

namespace bb::test {

// K is positive semi-definite with exactly `zero_modes` zero eigenvalues (below 1e-10 of the
// largest), and the next eigenvalue is a genuine deformation mode above `separation` * largest.
inline ::testing::AssertionResult has_exactly_zero_energy_modes(const Eigen::MatrixXd& k, int zero_modes,
                                                                double separation) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k);
  const Eigen::VectorXd lambda = eig.eigenvalues();  // ascending
  const double largest = lambda.maxCoeff();
  if (!(largest > 0.0)) return ::testing::AssertionFailure() << "largest eigenvalue " << largest << " is not positive";
  int zero = 0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    if (lambda[i] < -1e-10 * largest)
      return ::testing::AssertionFailure()
             << "negative eigenvalue " << i << " (" << lambda[i] << "): K is not semi-definite";
    if (std::abs(lambda[i]) < 1e-10 * largest) ++zero;
  }
  if (zero != zero_modes)
    return ::testing::AssertionFailure() << zero << " zero eigenvalues, expected " << zero_modes << "; eigenvalues:\n"
                                         << lambda.transpose();
  if (!(lambda[zero_modes] > separation * largest))
    return ::testing::AssertionFailure() << "eigenvalue " << zero_modes << " (" << lambda[zero_modes]
                                         << ") is not clear of round-off: a spurious zero-energy mode";
  return ::testing::AssertionSuccess();
}

}  // namespace bb::test
