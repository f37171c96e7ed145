// The eigenvalue of a computed mode as its Rayleigh quotient summed in long double
// (linalg/modal_residual.hpp): against the same sum in quadruple precision on a stiff irregular
// chain, and through the default eigensolver against a chain's closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "linalg/modal_residual.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

// A fixed-fixed chain of n unit masses and springs of stiffness s: lambda_j = 4 s sin^2(j pi / (2 (n + 1))),
// shape x_i = sin(i j pi / (n + 1)).
struct StiffChain {
  Sparse k, m;
  int n;
  double s;
  StiffChain(int n_, double s_) : k(n_, n_), m(n_, n_), n(n_), s(s_) {
    std::vector<Eigen::Triplet<double>> kt, mt;
    for (int i = 0; i < n; ++i) {
      kt.emplace_back(i, i, 2 * s);
      if (i + 1 < n) {
        kt.emplace_back(i, i + 1, -s);
        kt.emplace_back(i + 1, i, -s);
      }
      mt.emplace_back(i, i, 1.0);
    }
    k.setFromTriplets(kt.begin(), kt.end());
    m.setFromTriplets(mt.begin(), mt.end());
  }
  double eigenvalue(int j) const { return 4 * s * std::pow(std::sin(j * std::numbers::pi / (2.0 * (n + 1))), 2); }
  Eigen::VectorXd shape(int j) const {
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x[i] = std::sin((i + 1) * j * std::numbers::pi / (n + 1));
    return x;
  }
};

// x^T A x / x^T B x in quadruple precision (GCC's __float128): the reference.
double quad_quotient(const Sparse& a, const Sparse& b, const Eigen::VectorXd& x) {
  const auto form = [&](const Sparse& m) {
    __float128 sum = 0;
    for (Eigen::Index c = 0; c < m.outerSize(); ++c)
      for (Sparse::InnerIterator it(m, c); it; ++it)
        sum += static_cast<__float128>(it.value()) * static_cast<__float128>(x[it.index()]) *
               static_cast<__float128>(x[c]);
    return sum;
  };
  return static_cast<double>(form(a) / form(b));
}

TEST(RayleighQuotient, InLongDoubleIsTheQuadruplePrecisionQuotientOfAStiffIrregularChainsFirstMode) {
  // Springs from 1e3 to 1e9 N/m and masses from 0.5 to 2 kg in a fixed pseudo-random order: the
  // first mode's K x is a difference of terms 1e6 times larger than itself.
  const int n = 3000;
  Sparse k(n, n), m(n, n);
  std::vector<Eigen::Triplet<double>> kt, mt;
  std::uint64_t state = 12345;
  const auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int i = 0; i <= n; ++i) {
    const double spring = std::pow(10.0, 3.0 + 6.0 * uniform());
    if (i < n) kt.emplace_back(i, i, spring);
    if (i > 0) kt.emplace_back(i - 1, i - 1, spring);
    if (i > 0 && i < n) {
      kt.emplace_back(i - 1, i, -spring);
      kt.emplace_back(i, i - 1, -spring);
    }
    if (i < n) mt.emplace_back(i, i, 0.5 + 1.5 * uniform());
  }
  k.setFromTriplets(kt.begin(), kt.end());
  m.setFromTriplets(mt.begin(), mt.end());
  ModalOptions options;
  options.n_modes = 1;
  options.shift_frequency_hz = 1e-3;
  const Eigen::VectorXd x = lowest_modes(k, m, options).shapes.col(0);
  const double reference = quad_quotient(k, m, x);
  const double in_double = x.dot(k * x) / x.dot(m * x);
  const double error = std::abs(rayleigh_quotient(k, m, x) - reference) / reference;
  const double error_in_double = std::abs(in_double - reference) / reference;  // 8.6e-9 measured
  EXPECT_LT(error, 1e-10);  // 9.6e-12 measured: ||K|| / lambda_1 is 3e11 here
  EXPECT_GT(error_in_double, 100 * error);
}

TEST(RayleighQuotient, TheDefaultEigensolverReportsItsModesToTheClosedFormsDigits) {
  const StiffChain chain(4000, 1e9);
  ModalOptions options;
  options.n_modes = 4;
  options.shift_frequency_hz = 1e-3;
  const ModalSolution sol = lowest_modes(chain.k, chain.m, options);
  ASSERT_GE(sol.eigenvalues.size(), 4);
  for (int j = 1; j <= 4; ++j)
    EXPECT_NEAR(sol.eigenvalues[j - 1], chain.eigenvalue(j), 1e-11 * chain.eigenvalue(j)) << "mode " << j;
}

}  // namespace
}  // namespace bb
