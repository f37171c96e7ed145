// The dense LU of the Newton steps (linalg/dense_lu): the solve of a square system to rounding,
// the 1-norm condition estimate against the exact value, and an exactly singular matrix reported
// by rcond 0 and a non-finite solve, never a finite wrong answer.
#include "linalg/dense_lu.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm, double* rcond,
             double* work, int* iwork, int* info);
}

namespace bb {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

double exact_rcond_1(const MatrixXd& a) {
  const auto norm1 = [](const MatrixXd& m) { return m.cwiseAbs().colwise().sum().maxCoeff(); };
  return 1.0 / (norm1(a) * norm1(a.inverse()));
}

TEST(DenseLU, SolvesToRoundingWithPivoting) {
  for (const int n : {1, 7, 135, 243}) {
    MatrixXd a = MatrixXd::Random(n, n);
    if (n > 1) a(0, 0) = 0.0;  // the first pivot must come from another row
    const VectorXd x = VectorXd::LinSpaced(n, -1.0, 2.0);
    const VectorXd b = a * x;
    const DenseLU lu(a);
    EXPECT_EQ(lu.rows(), n);
    const VectorXd solved = lu.solve(b);
    EXPECT_LE((solved - x).norm(), 1e-10 * x.norm() / lu.rcond()) << "n = " << n;
    EXPECT_LE((a * solved - b).norm(), 1e-12 * a.norm() * x.norm()) << "n = " << n;
  }
}

TEST(DenseLU, ConditionEstimateBracketsTheExactValue) {
  // Hager-Higham's estimate of |A^-1|_1 is a lower bound, within a small factor in practice.
  for (const double spread : {1.0, 1e4, 1e10}) {
    const int n = 40;
    MatrixXd q = MatrixXd::Random(n, n).householderQr().householderQ();
    VectorXd s = VectorXd::LinSpaced(n, 0.0, 1.0).unaryExpr([spread](double t) { return std::pow(spread, -t); });
    const MatrixXd a = q * s.asDiagonal() * q.transpose();
    const double exact = exact_rcond_1(a), estimate = DenseLU(a).rcond();
    EXPECT_GE(estimate, exact * (1 - 1e-8)) << spread;
    EXPECT_LE(estimate, 10.0 * exact) << spread;
  }
}

// The estimate takes LAPACK's dgecon algorithm with the BLAS's triangular solves: the same value
// as dgecon's to rounding, at the Newton steps' size, from well to badly conditioned.
TEST(DenseLU, ConditionEstimateIsLapacksDgecon) {
  for (const double spread : {1.0, 1e8, 1e14}) {
    const int n = 135;
    MatrixXd q = MatrixXd::Random(n, n).householderQr().householderQ();
    VectorXd s = VectorXd::LinSpaced(n, 0.0, 1.0).unaryExpr([spread](double t) { return std::pow(spread, -t); });
    const MatrixXd a = q * s.asDiagonal() * MatrixXd::Random(n, n).householderQr().householderQ();
    MatrixXd lu = a;
    std::vector<int> pivots(n), iwork(n);
    std::vector<double> work(4 * n);
    int info = 0;
    dgetrf_(&n, &n, lu.data(), &n, pivots.data(), &info);
    ASSERT_EQ(info, 0);
    const double norm = a.cwiseAbs().colwise().sum().maxCoeff();
    double lapack = 0.0;
    dgecon_("1", &n, lu.data(), &n, &norm, &lapack, work.data(), iwork.data(), &info);
    EXPECT_NEAR(DenseLU(a).rcond(), lapack, 1e-10 * lapack) << spread;
  }
}

TEST(DenseLU, ExactlySingularMatrixHasZeroConditionAndNoFiniteSolve) {
  MatrixXd a = MatrixXd::Random(5, 5);
  a.col(3) = 2.0 * a.col(1);
  a.row(4).setZero();
  const DenseLU lu(a);
  EXPECT_LT(lu.rcond(), 1e-15);
  const VectorXd x = lu.solve(VectorXd::Ones(5));
  EXPECT_FALSE(x.allFinite() && (a * x - VectorXd::Ones(5)).norm() < 1e-6);
}

TEST(DenseLU, EmptyMatrixIsWellConditioned) {
  const DenseLU lu{MatrixXd(0, 0)};
  EXPECT_EQ(lu.rows(), 0);
  EXPECT_EQ(lu.rcond(), 1.0);
  EXPECT_EQ(lu.solve(VectorXd(0)).size(), 0);
}

}  // namespace
}  // namespace bb
