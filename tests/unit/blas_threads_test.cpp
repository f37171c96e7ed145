// Factorizations on two threads at once must give the numbers of one thread, to rounding: the
// nodal diameters, force levels and calibration starts run that way. A BLAS without locks
// (OpenBLAS built without threads) fails this, which is why it is detected and run serially.
#include "linalg/blas_threads.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "assembly/free_system.hpp"
#include "linalg/spd_factor.hpp"
#include "mesh/hex_block.hpp"

namespace bb {
namespace {

// A clamped 12 x 12 x 12 hex8 block: supernodes large enough for the BLAS-3 kernels.
FreeSystem clamped_block() {
  HexBlockSpec b;
  b.corners = {Eigen::Vector3d(0, 0, 0), {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  b.nx = b.ny = b.nz = 12;
  b.element = ElementType::hex8;
  Model model;
  model.mesh = generate_hex_block(b);
  model.section = {2.1e11, 0.3, 7850.0, 0.0};
  std::vector<int> base;
  for (int i = 0; i < model.mesh.n_nodes(); ++i)
    if (model.mesh.coords(i, 2) < 1e-9) base.push_back(i);
  model.node_sets["base"] = base;
  model.constraints.push_back({"base", {0, 1, 2}, 0.0});
  return assemble_free_system(model);
}

Eigen::MatrixXd factor_and_solve(const Eigen::SparseMatrix<double>& k, const Eigen::MatrixXd& rhs) {
  SpdFactorization factor(FillOrdering::metis);
  if (!factor.factorize(k).ok) return {};
  return factor.solve(rhs);
}

TEST(BlasThreads, TwoFactorizationsAtOnceEqualOneAtATime) {
  if (!blas_allows_concurrent_calls()) GTEST_SKIP() << "this BLAS takes one call at a time (run serially)";
  const FreeSystem s = clamped_block();
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(s.stiffness.rows(), 4);
  const Eigen::MatrixXd serial = factor_and_solve(s.stiffness, rhs);
  ASSERT_GT(serial.size(), 0);
  EXPECT_EQ((factor_and_solve(s.stiffness, rhs) - serial).cwiseAbs().maxCoeff(), 0.0) << "serial again";
  constexpr int kRounds = 3;
  std::vector<Eigen::MatrixXd> results(2 * kRounds);
  {
    std::vector<std::jthread> two;
    for (int t = 0; t < 2; ++t)
      two.emplace_back([&, t] {
        for (int r = 0; r < kRounds; ++r) results[2 * r + t] = factor_and_solve(s.stiffness, rhs);
      });
  }
  // Rounding may differ (the kernels' alignment differs between threads); a race ruins digits.
  const double scale = serial.cwiseAbs().maxCoeff();
  for (const Eigen::MatrixXd& x : results) {
    ASSERT_EQ(x.rows(), serial.rows());
    EXPECT_LT((x - serial).cwiseAbs().maxCoeff(), 1e-12 * scale);
  }
}

}  // namespace
}  // namespace bb
