// The parallel central differences of a fit's Jacobian against Ceres's own, bit for bit, and the
// centre run taken from the residuals Ceres has just evaluated at the same point.
#include "identify/central_differences.hpp"

#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <vector>

namespace {

// A smooth model with coupled parameters (one of them zero: the absolute step floor applies).
bool model(const double* x, double* r) {
  r[0] = std::exp(x[0]) * std::sin(x[1]) - 0.3;
  r[1] = x[0] * x[0] * x[2] + std::cos(x[1] * x[2]);
  r[2] = std::log1p(x[0] * x[0]) - x[2];
  r[3] = x[1] * x[1] * x[1];
  return true;
}

struct CeresFunctor {
  bool operator()(double const* const* p, double* r) const { return model(p[0], r); }
};

TEST(CentralDifferences, EqualCeresCentralDifferencesBitForBitOnAnyNumberOfWorkers) {
  ceres::NumericDiffOptions options;
  options.relative_step_size = 1e-4;
  ceres::DynamicNumericDiffCostFunction<CeresFunctor, ceres::CENTRAL> reference(new CeresFunctor, ceres::TAKE_OWNERSHIP,
                                                                                options);
  reference.AddParameterBlock(3);
  reference.SetNumResiduals(4);
  const std::vector<double> x = {0.7, -1.3, 0.0};
  const double* parameters[] = {x.data()};
  std::vector<double> r_ref(4), j_ref(12);
  double* jacobians_ref[] = {j_ref.data()};
  ASSERT_TRUE(reference.Evaluate(parameters, r_ref.data(), jacobians_ref));
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

TEST(CentralDifferences, AFailedRunFailsTheEvaluation) {
  const bb::CentralDifferences differences(
      [](const std::vector<double>& y, double* r) {
        r[0] = y[0];
        return y[0] < 1.0;  // the forward run, 0.96 + 0.096, fails
      },
      1, 1, 1e-1, 2);
  const std::vector<double> x = {0.96};
  const double* parameters[] = {x.data()};
  double r = 0.0, j = 0.0;
  double* jacobians[] = {&j};
  EXPECT_TRUE(differences.Evaluate(parameters, &r, nullptr));
  EXPECT_FALSE(differences.Evaluate(parameters, &r, jacobians));
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
