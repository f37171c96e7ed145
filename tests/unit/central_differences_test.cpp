// The parallel central differences of a fit's Jacobian: the same bit for bit on any number of
// workers, one step in any unit of a parameter, and the centre run taken from the residuals Ceres
// has just evaluated at the same point.
#include "identify/central_differences.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <vector>

namespace {

// A smooth model with coupled parameters (one of them zero).
bool model(const double* x, double* r) {
  r[0] = std::exp(x[0]) * std::sin(x[1]) - 0.3;
  r[1] = x[0] * x[0] * x[2] + std::cos(x[1] * x[2]);
  r[2] = std::log1p(x[0] * x[0]) - x[2];
  r[3] = x[1] * x[1] * x[1];
  return true;
}

// The central differences with step h, serially, as the reference.
std::vector<double> reference_jacobian(const std::vector<double>& x, double h) {
  std::vector<double> j(12);
  for (int c = 0; c < 3; ++c) {
    std::vector<double> up = x, down = x, r_up(4), r_down(4);
    up[static_cast<size_t>(c)] += h;
    down[static_cast<size_t>(c)] -= h;
    model(up.data(), r_up.data());
    model(down.data(), r_down.data());
    for (int k = 0; k < 4; ++k) j[static_cast<size_t>(k * 3 + c)] = (r_up[k] - r_down[k]) / (2.0 * h);
  }
  return j;
}

TEST(CentralDifferences, AreTheSameBitForBitOnAnyNumberOfWorkers) {
  const std::vector<double> x = {0.7, -1.3, 0.0};
  const double* parameters[] = {x.data()};
  const std::vector<double> j_ref = reference_jacobian(x, 1e-4);
  std::vector<double> r_ref(4);
  model(x.data(), r_ref.data());
  for (const std::size_t workers : {1u, 2u, 7u}) {
    std::atomic<int> runs{0};
    const bb::CentralDifferences differences(
        [&](const std::vector<double>& y, double* r) {
          ++runs;
          return model(y.data(), r);
        },
        3, 4, 1e-4, workers);
    std::vector<double> r(4), j(12);
    double* jacobians[] = {j.data()};
    ASSERT_TRUE(differences.Evaluate(parameters, r.data(), jacobians));
    EXPECT_EQ(runs.load(), 7) << "2 n + 1 model runs";
    EXPECT_EQ(r, r_ref) << workers << " workers";
    EXPECT_EQ(j, j_ref) << workers << " workers";
    // And the derivatives are those of the model: d r3 / d x1 = 3 x1^2.
    EXPECT_NEAR(j[3 * 3 + 1], 3 * 1.3 * 1.3, 1e-6);
  }
}

// A fit's parameters are log values: a parameter given in another unit (kt in N/mm instead of N/m)
// is the same log value shifted by a constant, and its derivative must not change. A step relative
// to |x| (Ceres's numeric differences) took 20 % for log kt = 18.4 and 1.5e-8 at a value of 1.
TEST(CentralDifferences, TheStepIsTheSameInAnyUnitOfTheParameter) {
  const auto response = [](const std::vector<double>& y, double* r) {  // r = p^2 + sin(p), p = e^y
    const double p = std::exp(y[0]);
    r[0] = p * p + std::sin(p);
    return true;
  };
  const double in_m = std::log(1.3), in_mm = in_m + std::log(1000.0);
  const bb::CentralDifferences si(response, 1, 1, 1e-2, 1);
  const bb::CentralDifferences mm(
      [&](const std::vector<double>& y, double* r) { return response({y[0] - std::log(1000.0)}, r); }, 1, 1, 1e-2, 1);
  double r = 0.0, j_si = 0.0, j_mm = 0.0;
  double* a[] = {&j_si};
  double* b[] = {&j_mm};
  const double* x_si[] = {&in_m};
  const double* x_mm[] = {&in_mm};
  ASSERT_TRUE(si.Evaluate(x_si, &r, a));
  ASSERT_TRUE(mm.Evaluate(x_mm, &r, b));
  EXPECT_NEAR(j_mm, j_si, 1e-9 * std::abs(j_si));
  const double p = 1.3, exact = p * (2 * p + std::cos(p));  // p dr/dp
  EXPECT_NEAR(j_si, exact, 1e-3 * exact);                   // O(h^2) of a 1 % step
}

// A run that fails on one side of x (a physical limit just beyond a fit's bound) leaves that
// column one-sided, counted; a column that fails on both sides fails the evaluation.
TEST(CentralDifferences, ARunThatFailsOnOneSideLeavesThatColumnOneSided) {
  const auto linear = [](const std::vector<double>& y, double* r) {
    r[0] = 3.0 * y[0] - 2.0 * y[1];
    return y[0] < 1.0;  // the forward run of x0 = 0.96 + 0.1 fails
  };
  int one_sided = 0;
  const bb::CentralDifferences differences(linear, 2, 1, 1e-1, 2, &one_sided);
  const std::vector<double> x = {0.96, 0.5};
  const double* parameters[] = {x.data()};
  double r = 0.0;
  std::vector<double> j(2);
  double* jacobians[] = {j.data()};
  ASSERT_TRUE(differences.Evaluate(parameters, &r, jacobians));
  EXPECT_NEAR(j[0], 3.0, 1e-12) << "the backward difference of a linear model is exact";
  EXPECT_NEAR(j[1], -2.0, 1e-12);
  EXPECT_EQ(one_sided, 1);
  const bb::CentralDifferences both(
      [](const std::vector<double>& y, double* out) {
        out[0] = y[0];
        return std::abs(y[0] - 0.96) < 1e-12;  // only the centre runs
      },
      1, 1, 1e-1, 2);
  const double* at[] = {x.data()};
  EXPECT_TRUE(both.Evaluate(at, &r, nullptr));
  EXPECT_FALSE(both.Evaluate(at, &r, jacobians));
}

// Ceres evaluates a candidate's residuals, then (the step accepted) the Jacobian there: that
// Jacobian takes its centre from the residuals, 2 n runs instead of 2 n + 1, with the same values;
// at another point all 2 n + 1 run.
TEST(CentralDifferences, AJacobianWhereTheResidualsWereJustEvaluatedReusesThem) {
  std::atomic<int> runs{0};
  const bb::CentralDifferences differences(
      [&](const std::vector<double>& y, double* r) {
        ++runs;
        return model(y.data(), r);
      },
      3, 4, 1e-4, 2);
  const std::vector<double> x = {0.7, -1.3, 0.0}, other = {0.5, -1.3, 0.0};
  const double* at_x[] = {x.data()};
  const double* at_other[] = {other.data()};
  std::vector<double> r(4), j(12), r_fresh(4), j_fresh(12);
  double* jacobians[] = {j.data()};
  double* jacobians_fresh[] = {j_fresh.data()};
  ASSERT_TRUE(differences.Evaluate(at_x, r.data(), nullptr));
  EXPECT_EQ(runs.load(), 1);
  ASSERT_TRUE(differences.Evaluate(at_x, r.data(), jacobians));
  EXPECT_EQ(runs.load(), 7) << "the centre reused";
  ASSERT_TRUE(differences.Evaluate(at_other, r.data(), jacobians));
  EXPECT_EQ(runs.load(), 14) << "another point: every run";
  const bb::CentralDifferences fresh([](const std::vector<double>& y, double* out) { return model(y.data(), out); }, 3,
                                     4, 1e-4, 1);
  ASSERT_TRUE(fresh.Evaluate(at_x, r_fresh.data(), jacobians_fresh));
  ASSERT_TRUE(differences.Evaluate(at_x, r.data(), nullptr));
  ASSERT_TRUE(differences.Evaluate(at_x, r.data(), jacobians));
  EXPECT_EQ(r, r_fresh);
  EXPECT_EQ(j, j_fresh);
}

}  // namespace
