// The SLEPc eigensolver (spectrum slicing, counts from its own inertias) against closed forms and
// the default eigensolver. Skipped in a build without the PETSc/SLEPc plugin.
#include "linalg/slepc_modes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "common/errors.hpp"
#include "distributed/distributed.hpp"
#include "linalg/modal_solver.hpp"
#include "reduction/craig_bampton.hpp"

namespace bb {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

// A fixed-fixed chain of n unit masses and unit springs, `copies` times side by side (uncoupled):
// lambda_j = 4 sin^2(j pi / (2 (n + 1))), each `copies` times.
void chain(int n, int copies, Sparse& k, Sparse& m) {
  std::vector<Eigen::Triplet<double>> kt, mt;
  for (int c = 0; c < copies; ++c)
    for (int i = 0; i < n; ++i) {
      const int r = c * n + i;
      kt.emplace_back(r, r, 2.0);
      if (i + 1 < n) {
        kt.emplace_back(r, r + 1, -1.0);
        kt.emplace_back(r + 1, r, -1.0);
      }
      mt.emplace_back(r, r, 1.0);
    }
  k.resize(n * copies, n * copies);
  m.resize(n * copies, n * copies);
  k.setFromTriplets(kt.begin(), kt.end());
  m.setFromTriplets(mt.begin(), mt.end());
}

double chain_eigenvalue(int n, int j) { return 4 * std::pow(std::sin(j * std::numbers::pi / (2.0 * (n + 1))), 2); }

ModalOptions slepc_options(int n_modes) {
  ModalOptions o;
  o.n_modes = n_modes;
  o.eigensolver = Eigensolver::slepc;
  o.shift_frequency_hz = 0.01;  // sigma = -(2 pi 0.01)^2, below every eigenvalue of the chain
  return o;
}

#define SKIP_WITHOUT_SLEPC() \
  if (!distributed::built_with_slepc()) GTEST_SKIP() << "built without PETSc/SLEPc"

TEST(SlepcModes, LowestModesOfAChainAreItsClosedFormAndTheSlicingCountsThem) {
  SKIP_WITHOUT_SLEPC();
  Sparse k, m;
  chain(200, 1, k, m);
  const ModalSolution sol = lowest_modes(k, m, slepc_options(6));
  ASSERT_EQ(sol.eigenvalues.size(), 6);
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(sol.eigenvalues[j] / chain_eigenvalue(200, j + 1), 1.0, 1e-10) << j;
  EXPECT_EQ(sol.sturm_count, 6);  // inertia at the slicing's top
  EXPECT_EQ(sol.sturm_seconds, 0.0);
  EXPECT_LT(sol.max_residual, 1e-10);
  // Mass-normalized and orthogonal, to the residual tolerance (1e-10) over the modes' relative gaps.
  const Eigen::MatrixXd gram = sol.shapes.transpose() * (m * sol.shapes);
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(6, 6)).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(SlepcModes, AgreesWithTheDefaultEigensolverToTheLastDigitsItResolves) {
  SKIP_WITHOUT_SLEPC();
  Sparse k, m;
  chain(300, 1, k, m);
  ModalOptions spectra = slepc_options(8);
  spectra.eigensolver = Eigensolver::spectra;
  const ModalSolution a = lowest_modes(k, m, spectra), b = lowest_modes(k, m, slepc_options(8));
  ASSERT_EQ(a.eigenvalues.size(), b.eigenvalues.size());
  for (Eigen::Index j = 0; j < a.eigenvalues.size(); ++j) {
    EXPECT_NEAR(b.eigenvalues[j] / a.eigenvalues[j], 1.0, 1e-10);
    EXPECT_NEAR(std::abs(a.shapes.col(j).dot(m * b.shapes.col(j))), 1.0, 1e-8);  // same shape up to sign
  }
  EXPECT_EQ(a.sturm_count, b.sturm_count);
}

TEST(SlepcModes, ARepeatedEigenvalueThatStraddlesTheCountComesBackWhole) {
  SKIP_WITHOUT_SLEPC();
  Sparse k, m;
  chain(100, 2, k, m);  // every eigenvalue twice
  const ModalSolution sol = lowest_modes(k, m, slepc_options(3));
  ASSERT_EQ(sol.eigenvalues.size(), 4);  // the pair 3/4 whole
  EXPECT_NEAR(sol.eigenvalues[2] / sol.eigenvalues[3], 1.0, 1e-10);
  EXPECT_NEAR(sol.eigenvalues[3] / chain_eigenvalue(100, 2), 1.0, 1e-10);
  EXPECT_EQ(sol.sturm_count, 4);
}

TEST(SlepcModes, ABandReturnsExactlyTheModesBelowItsTop) {
  SKIP_WITHOUT_SLEPC();
  Sparse k, m;
  chain(150, 1, k, m);
  const double top = 0.5 * (chain_eigenvalue(150, 7) + chain_eigenvalue(150, 8));
  const ModalSolution sol = slepc_modes_below(k, m, top, slepc_options(1));
  ASSERT_EQ(sol.eigenvalues.size(), 7);
  EXPECT_EQ(sol.sturm_count, 7);
  EXPECT_NEAR(sol.eigenvalues[6] / chain_eigenvalue(150, 7), 1.0, 1e-10);
  EXPECT_THROW(slepc_modes_below(k, m, -1.0, slepc_options(1)), InputError);  // top below the shift
}

TEST(SlepcModes, SpdSolveByMumpsMatchesADenseSolve) {
  SKIP_WITHOUT_SLEPC();
  Sparse k, m;
  chain(60, 1, k, m);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(60, 2);
  b(0, 0) = 1.0;
  b(30, 1) = 2.0;
  const Eigen::MatrixXd x = slepc_solve_spd(k, b);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(k).ldlt().solve(b);
  EXPECT_LT((x - dense).cwiseAbs().maxCoeff(), 1e-12 * dense.cwiseAbs().maxCoeff());
}

TEST(SlepcModes, CraigBamptonOnSlepcIsTheDefaultReductionUpToTheSignOfEachMode) {
  SKIP_WITHOUT_SLEPC();
  Sparse k, m;
  chain(120, 1, k, m);
  const std::vector<int> masters{0, 60, 119};
  const std::vector<ReducedDof> names{{"a", 0, 0}, {"b", 0, 0}, {"c", 0, 0}};
  CraigBamptonOptions options;
  options.n_modes = 5;
  options.shift_frequency_hz = 0.01;
  const ReducedModel a = craig_bampton(k, m, masters, names, options);
  options.eigensolver = Eigensolver::slepc;
  const ReducedModel b = craig_bampton(k, m, masters, names, options);
  // A mode's sign flips its row and column of the coupling blocks; magnitudes are the same.
  const double scale = a.stiffness.cwiseAbs().maxCoeff();
  EXPECT_LT((a.stiffness.cwiseAbs() - b.stiffness.cwiseAbs()).cwiseAbs().maxCoeff(), 1e-9 * scale);
  EXPECT_LT((a.mass.cwiseAbs() - b.mass.cwiseAbs()).cwiseAbs().maxCoeff(), 1e-9 * a.mass.cwiseAbs().maxCoeff());
  EXPECT_LT((a.recovery.leftCols(3) - b.recovery.leftCols(3)).cwiseAbs().maxCoeff(), 1e-10);  // constraint modes
}

TEST(SlepcModes, AHermitianPencilIsRefusedWithTheEigensolverItNeeds) {
  Eigen::SparseMatrix<std::complex<double>> k(4, 4), m(4, 4);
  for (int i = 0; i < 4; ++i) {
    k.insert(i, i) = 2.0;
    m.insert(i, i) = 1.0;
  }
  EXPECT_THROW(lowest_modes(k, m, slepc_options(1)), InputError);
}

}  // namespace
}  // namespace bb
