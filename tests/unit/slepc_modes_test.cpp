// The SLEPc eigensolver (spectrum slicing, counts from its own inertias) against closed forms and
// the default eigensolver. Skipped in a build without the PETSc/SLEPc plugin.
#include "linalg/slepc_modes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "distributed/distributed.hpp"
#include "linalg/modal_solver.hpp"
#include "reduction/craig_bampton.hpp"

namespace bb {
namespace {

using Sparse = Eigen::SparseMatrix<double>;
using ComplexSparse = Eigen::SparseMatrix<std::complex<double>>;

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

// Out of core, MUMPS writes its factors to MUMPS_OOC_TMPDIR and reads them back at every solve:
// the same factors, so the same modes and count as in memory. A folder that does not exist makes
// the out-of-core solve fail (and only it): the key reaches MUMPS.
TEST(SlepcModes, OutOfCoreFactorsGiveTheModesInMemoryGives) {
  SKIP_WITHOUT_SLEPC();
  Sparse k, m;
  chain(300, 1, k, m);
  ModalOptions on_disk = slepc_options(8);
  on_disk.out_of_core = true;
  const ModalSolution a = lowest_modes(k, m, slepc_options(8)), b = lowest_modes(k, m, on_disk);
  ASSERT_EQ(a.eigenvalues.size(), b.eigenvalues.size());
  for (Eigen::Index j = 0; j < a.eigenvalues.size(); ++j) EXPECT_NEAR(b.eigenvalues[j] / a.eigenvalues[j], 1.0, 1e-13);
  EXPECT_EQ(a.sturm_count, b.sturm_count);
  const char* before = std::getenv("MUMPS_OOC_TMPDIR");
  const std::string kept = before ? before : "";
  ::setenv("MUMPS_OOC_TMPDIR", "/nonexistent/bladebench-ooc", 1);
  EXPECT_THROW((void)lowest_modes(k, m, on_disk), SolverError);
  EXPECT_NO_THROW((void)lowest_modes(k, m, slepc_options(8)));
  if (before)
    ::setenv("MUMPS_OOC_TMPDIR", kept.c_str(), 1);
  else
    ::unsetenv("MUMPS_OOC_TMPDIR");
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

// A chain of n held at three masters (its ends and its middle), reduced by the default eigensolver
// and by SLEPc with the same options.
struct ChainReductions {
  Sparse k, m;
  std::vector<int> masters;
  std::vector<ReducedDof> names{{"a", 0, 0}, {"b", 0, 0}, {"c", 0, 0}};
  ReducedModel spectra, slepc;
};
ChainReductions reduce_three_point_chain(int n, CraigBamptonOptions options) {
  ChainReductions r;
  chain(n, 1, r.k, r.m);
  r.masters = {0, n / 2, n - 1};
  options.shift_frequency_hz = 0.01;
  options.eigensolver = Eigensolver::spectra;
  r.spectra = craig_bampton(r.k, r.m, r.masters, r.names, options);
  options.eigensolver = Eigensolver::slepc;
  r.slepc = craig_bampton(r.k, r.m, r.masters, r.names, options);
  return r;
}

TEST(SlepcModes, CraigBamptonOnSlepcIsTheDefaultReductionUpToTheSignOfEachMode) {
  SKIP_WITHOUT_SLEPC();
  CraigBamptonOptions options;
  options.n_modes = 5;
  const ChainReductions r = reduce_three_point_chain(120, options);
  const ReducedModel &a = r.spectra, &b = r.slepc;
  // A mode's sign flips its row and column of the coupling blocks; magnitudes are the same.
  const double scale = a.stiffness.cwiseAbs().maxCoeff();
  EXPECT_LT((a.stiffness.cwiseAbs() - b.stiffness.cwiseAbs()).cwiseAbs().maxCoeff(), 1e-9 * scale);
  EXPECT_LT((a.mass.cwiseAbs() - b.mass.cwiseAbs()).cwiseAbs().maxCoeff(), 1e-9 * a.mass.cwiseAbs().maxCoeff());
  EXPECT_LT((a.recovery.leftCols(3) - b.recovery.leftCols(3)).cwiseAbs().maxCoeff(), 1e-10);  // constraint modes
}

TEST(SlepcModes, CraigBamptonBelowACutTakesItsCountFromTheSlicingAndEqualsTheDefault) {
  SKIP_WITHOUT_SLEPC();
  // The slaves are two chains of 58 held at both ends: lambda_j = 4 sin^2(j pi / 118), each twice.
  CraigBamptonOptions options;
  options.modes_below_hz = std::sqrt(chain_eigenvalue(58, 4) * 1.01) / (2 * std::numbers::pi);
  const ChainReductions r = reduce_three_point_chain(119, options);
  const ReducedModel &a = r.spectra, &b = r.slepc;
  ASSERT_EQ(a.fixed_interface_frequencies_hz.size(), 8) << "4 eigenvalues below the cut, each twice";
  ASSERT_EQ(b.fixed_interface_frequencies_hz.size(), 8);
  for (int j = 0; j < 8; ++j)
    EXPECT_NEAR(b.fixed_interface_frequencies_hz[j], a.fixed_interface_frequencies_hz[j],
                1e-9 * a.fixed_interface_frequencies_hz[j]);
  EXPECT_LT((a.stiffness.diagonal() - b.stiffness.diagonal()).cwiseAbs().maxCoeff(),
            1e-9 * a.stiffness.cwiseAbs().maxCoeff());
  options.modes_below_hz = 1e-6;  // no mode below: the masters alone
  options.eigensolver = Eigensolver::slepc;
  EXPECT_EQ(craig_bampton(r.k, r.m, r.masters, r.names, options).size(), 3);
}

TEST(SlepcModes, CraigBamptonWithSlavesTheMastersDoNotHoldIsBadInputAsOnTheDefault) {
  SKIP_WITHOUT_SLEPC();
  // Two free-free chains side by side, one master on the first: the second floats.
  Sparse k, m;
  chain(30, 2, k, m);
  k.coeffRef(0, 0) = k.coeffRef(29, 29) = k.coeffRef(30, 30) = k.coeffRef(59, 59) = 1.0;
  const std::vector<int> masters{0};
  const std::vector<ReducedDof> names{{"a", 0, 0}};
  CraigBamptonOptions options;
  options.n_modes = 2;
  options.shift_frequency_hz = 0.01;
  for (Eigensolver solver : {Eigensolver::spectra, Eigensolver::slepc}) {
    options.eigensolver = solver;
    try {
      (void)craig_bampton(k, m, masters, names, options);
      ADD_FAILURE() << "a floating slave set was reduced by eigensolver " << static_cast<int>(solver);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("K_ss cannot be factored"), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not bad input: " << e.what();
    }
  }
}

// A twisted ring of n unit masses (`copies` uncoupled copies side by side): K tridiagonal with the
// corner coupling -e^{i theta}, a Bloch wave of phase theta; lambda_j = 4 sin^2((theta + 2 pi j) / (2 n)),
// j = 0 .. n - 1, each `copies` times.
void twisted_ring(int n, int copies, double theta, ComplexSparse& k, ComplexSparse& m) {
  std::vector<Eigen::Triplet<std::complex<double>>> kt, mt;
  for (int c = 0; c < copies; ++c)
    for (int i = 0; i < n; ++i) {
      const int r = c * n + i, next = c * n + (i + 1) % n;
      const std::complex<double> coupling = i + 1 < n ? -1.0 : -std::polar(1.0, theta);
      kt.emplace_back(r, r, 2.0);
      kt.emplace_back(next, r, coupling);
      kt.emplace_back(r, next, std::conj(coupling));
      mt.emplace_back(r, r, 1.0);
    }
  k.resize(n * copies, n * copies);
  m.resize(n * copies, n * copies);
  k.setFromTriplets(kt.begin(), kt.end());
  m.setFromTriplets(mt.begin(), mt.end());
}

std::vector<double> twisted_ring_eigenvalues(int n, int copies, double theta) {
  std::vector<double> values;
  for (int j = 0; j < n; ++j)
    for (int c = 0; c < copies; ++c)
      values.push_back(4 * std::pow(std::sin((theta + 2 * std::numbers::pi * j) / (2 * n)), 2));
  std::sort(values.begin(), values.end());
  return values;
}

TEST(SlepcModes, AHermitianPencilThroughItsRealFormHasTheClosedFormEigenvaluesOnceAndTheirCount) {
  SKIP_WITHOUT_SLEPC();
  ComplexSparse k, m;
  const int n = 90;
  const double theta = 0.7;
  twisted_ring(n, 1, theta, k, m);
  const HermitianModalSolution sol = lowest_modes(k, m, slepc_options(5));
  const std::vector<double> exact = twisted_ring_eigenvalues(n, 1, theta);
  ASSERT_EQ(sol.eigenvalues.size(), 5) << "each eigenvalue once, not twice as in the real form";
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(sol.eigenvalues[i], exact[static_cast<size_t>(i)], 1e-10) << "mode " << i;
  EXPECT_EQ(sol.sturm_count, 5) << "the real form's count, halved";
  const Eigen::MatrixXcd gram = sol.shapes.adjoint() * (m * sol.shapes);
  EXPECT_LT((gram - Eigen::MatrixXcd::Identity(5, 5)).norm(), 1e-10) << "complex M-orthonormal shapes";
  EXPECT_LT(sol.max_residual, 1e-10);
  // The same waves as the default eigensolver's, up to a complex phase each.
  ModalOptions spectra = slepc_options(5);
  spectra.eigensolver = Eigensolver::spectra;
  const HermitianModalSolution ref = lowest_modes(k, m, spectra);
  ASSERT_EQ(ref.eigenvalues.size(), 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(sol.eigenvalues[i], ref.eigenvalues[i], 1e-10 * ref.eigenvalues[i]) << "mode " << i;
    EXPECT_NEAR(std::abs(ref.shapes.col(i).dot(m * sol.shapes.col(i))), 1.0, 1e-8) << "mode " << i;
  }
}

TEST(SlepcModes, ARepeatedComplexEigenvalueStraddlingTheRequestIsReturnedWhole) {
  SKIP_WITHOUT_SLEPC();
  ComplexSparse k, m;
  twisted_ring(40, 2, 0.3, k, m);  // every eigenvalue twice: four times in the real form
  const HermitianModalSolution sol = lowest_modes(k, m, slepc_options(3));
  const std::vector<double> exact = twisted_ring_eigenvalues(40, 2, 0.3);
  ASSERT_EQ(sol.eigenvalues.size(), 4) << "the third eigenvalue's second member comes too";
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(sol.eigenvalues[i], exact[static_cast<size_t>(i)], 1e-10) << "mode " << i;
  EXPECT_EQ(sol.sturm_count, 4);
  const Eigen::MatrixXcd gram = sol.shapes.adjoint() * (m * sol.shapes);
  EXPECT_LT((gram - Eigen::MatrixXcd::Identity(4, 4)).norm(), 1e-10) << "a repeated pair's members independent";
}

}  // namespace
}  // namespace bb
