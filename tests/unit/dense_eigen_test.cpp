// The dense eigensolvers every small model shares (linalg/dense_eigen): ascending values, vectors
// that satisfy K x = lambda M x and are M-orthonormal, real and Hermitian alike, values alone when
// asked, and Eigen's failure reported rather than hidden.
#include "linalg/dense_eigen.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <complex>
#include <cstdlib>
#include <limits>

namespace bb {
namespace {

Eigen::MatrixXd spd(int n, int seed) {
  std::srand(static_cast<unsigned>(seed));
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
  return a * a.transpose() + n * Eigen::MatrixXd::Identity(n, n);
}

TEST(DenseEigen, PencilsRealAndHermitianGiveAscendingMOrthonormalEigenpairs) {
  const Eigen::MatrixXd k = spd(6, 1), m = spd(6, 2);
  const DenseEigen<double> e = symmetric_eigen(k, m);
  ASSERT_TRUE(e.ok);
  for (Eigen::Index i = 1; i < 6; ++i) EXPECT_LE(e.values[i - 1], e.values[i]);
  EXPECT_LT((k * e.vectors - m * e.vectors * e.values.asDiagonal()).norm(), 1e-10 * k.norm());
  EXPECT_LT((e.vectors.transpose() * m * e.vectors - Eigen::MatrixXd::Identity(6, 6)).norm(), 1e-12);
  EXPECT_EQ(symmetric_eigen(k, m, false).values, e.values);
  EXPECT_EQ(symmetric_eigen(k, m, false).vectors.size(), 0);

  const std::complex<double> i(0.0, 1.0);
  Eigen::MatrixXcd kc = k.cast<std::complex<double>>();
  kc(0, 1) += 0.3 * i;
  kc(1, 0) -= 0.3 * i;  // Hermitian
  const DenseEigen<std::complex<double>> h = symmetric_eigen(kc, m.cast<std::complex<double>>());
  ASSERT_TRUE(h.ok);
  EXPECT_LT((kc * h.vectors - m * h.vectors * h.values.asDiagonal()).norm(), 1e-10 * kc.norm());
  EXPECT_LT((h.vectors.adjoint() * m * h.vectors - Eigen::MatrixXcd::Identity(6, 6)).norm(), 1e-12);

  const DenseEigen<double> s = symmetric_eigen(k);
  ASSERT_TRUE(s.ok);
  EXPECT_LT((k * s.vectors - s.vectors * s.values.asDiagonal()).norm(), 1e-10 * k.norm());
  const DenseEigen<std::complex<double>> sh = symmetric_eigen(kc);
  EXPECT_LT((kc * sh.vectors - sh.vectors * sh.values.asDiagonal()).norm(), 1e-10 * kc.norm());
}

TEST(DenseEigen, AMatrixWithNonFiniteEntriesIsReportedAsAFailure) {
  Eigen::MatrixXd a = spd(4, 3);
  a(2, 1) = a(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(symmetric_eigen(a).ok);
}

}  // namespace
}  // namespace bb
