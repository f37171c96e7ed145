// The Hermitian shift-invert Krylov-Schur solver (linalg/hermitian_lanczos.hpp) behind the
// travelling waves of a cyclic sector: the lowest eigenpairs of a Hermitian pencil against a dense
// solve, M-orthonormal shapes, and the Sturm count of the real form that catches a missed member
// of a repeated eigenvalue.
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <complex>
#include <vector>

#include "linalg/hermitian_lanczos.hpp"
#include "linalg/inertia.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {
namespace {

using Complex = std::complex<double>;
using ComplexSparse = Eigen::SparseMatrix<Complex>;

// A complex-coupled chain (a twisted ring): K tridiagonal Hermitian with phase-shifted off-diagonals,
// M diagonal with varying masses. Positive definite, no repeated eigenvalue.
struct TwistedChain {
  ComplexSparse K, M;
  explicit TwistedChain(int n) : K(n, n), M(n, n) {
    std::vector<Eigen::Triplet<Complex>> k, m;
    for (int i = 0; i < n; ++i) {
      k.emplace_back(i, i, 2.0e6 + 1.0e4 * i);
      m.emplace_back(i, i, 1.0 + 0.3 * std::sin(0.7 * i));
      if (i + 1 < n) {
        const Complex c = -1.0e6 * std::polar(1.0, 0.4 + 0.01 * i);
        k.emplace_back(i + 1, i, c);
        k.emplace_back(i, i + 1, std::conj(c));
      }
    }
    K.setFromTriplets(k.begin(), k.end());
    M.setFromTriplets(m.begin(), m.end());
  }
  Eigen::VectorXd dense_eigenvalues() const {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> dense{Eigen::MatrixXcd(K), Eigen::MatrixXcd(M)};
    return dense.eigenvalues();
  }
};

TEST(HermitianModes, LowestPairsEqualTheDenseSolveAndAreMOrthonormal) {
  const TwistedChain chain(200);
  ModalOptions options;
  options.n_modes = 8;
  const HermitianModalSolution sol = lowest_modes(chain.K, chain.M, options);
  const Eigen::VectorXd dense = chain.dense_eigenvalues();
  ASSERT_GE(sol.eigenvalues.size(), 8);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(sol.eigenvalues[i], dense[i], 1e-9 * dense[i]) << "pair " << i;
  const Eigen::MatrixXcd gram = sol.shapes.adjoint() * (chain.M * sol.shapes);
  EXPECT_LT((gram - Eigen::MatrixXcd::Identity(gram.rows(), gram.cols())).norm(), 1e-10);
  EXPECT_LT(sol.max_residual, options.tolerance);
  EXPECT_EQ(sol.sturm_count, 8) << "the count of the real form, halved";
}

// Two uncoupled copies of the chain: every eigenvalue twice. In exact arithmetic one start vector
// sees one member of each pair; whether rounding brings the other or the Sturm count sends the
// solver back for it, both members of every pair come back and the count agrees.
TEST(HermitianModes, TheSturmCountRecoversTheSecondMemberOfEveryPair) {
  const TwistedChain chain(150);
  const int n = 150;
  ComplexSparse K(2 * n, 2 * n), M(2 * n, 2 * n);
  std::vector<Eigen::Triplet<Complex>> k, m;
  for (int copy = 0; copy < 2; ++copy)
    for (int c = 0; c < n; ++c) {
      for (ComplexSparse::InnerIterator it(chain.K, c); it; ++it)
        k.emplace_back(copy * n + it.row(), copy * n + c, it.value());
      for (ComplexSparse::InnerIterator it(chain.M, c); it; ++it)
        m.emplace_back(copy * n + it.row(), copy * n + c, it.value());
    }
  K.setFromTriplets(k.begin(), k.end());
  M.setFromTriplets(m.begin(), m.end());
  ModalOptions options;
  options.n_modes = 6;
  const HermitianModalSolution sol = lowest_modes(K, M, options);
  const Eigen::VectorXd dense = chain.dense_eigenvalues();
  ASSERT_GE(sol.eigenvalues.size(), 6);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(sol.eigenvalues[i], dense[i / 2], 1e-9 * dense[i / 2]) << "member " << i;
  EXPECT_EQ(sol.sturm_count, static_cast<int>(sol.eigenvalues.size()));
}

TEST(HermitianModes, TheRealFormCountsEachEigenvalueOnce) {
  const TwistedChain chain(60);
  const Eigen::VectorXd dense = chain.dense_eigenvalues();
  const double between = 0.5 * (dense[9] + dense[10]);
  const InertiaCount c = eigenvalues_below(chain.K, chain.M, between);
  ASSERT_TRUE(c.ok) << c.message;
  EXPECT_EQ(c.negative, 10);
}

TEST(HermitianModes, ATooSmallBasisIsRefused) {
  const TwistedChain chain(10);
  HermitianLanczosOptions o;
  o.nev = 4;
  o.ncv = 4;
  EXPECT_THROW(hermitian_lanczos(chain.K, chain.M, o), std::invalid_argument);
}

}  // namespace
}  // namespace bb
