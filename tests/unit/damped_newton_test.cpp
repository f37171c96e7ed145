// The damped Newton helper (linalg/damped_newton): quadratic convergence on a smooth system,
// backtracking that tames overshooting and undefined full steps, the secant step past a kink and
// Levenberg-Marquardt steps where backtracking is not allowed to, chord steps that reuse a
// factorization across solves, the minimum-norm step on an underdetermined system, and failures
// reported with a status and |R|, never thrown, never NaN.
#include "linalg/damped_newton.hpp"

#include <gtest/gtest.h>

#include <any>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace bb {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// R(x) = atan(x): Newton's full step from |x| > 1.39 lands further out each time.
NewtonPoint arctangent(const VectorXd& x) {
  NewtonPoint p;
  p.residual = VectorXd::Constant(1, std::atan(x[0]));
  p.jacobian = MatrixXd::Constant(1, 1, 1.0 / (1.0 + x[0] * x[0]));
  return p;
}

TEST(DampedNewton, ConvergesQuadraticallyOnASmoothSystem) {
  // Circle x0^2 + x1^2 = 4 meets the line x0 = x1 at (sqrt 2, sqrt 2).
  const NewtonSystem circle = [](const VectorXd& x) {
    NewtonPoint p;
    p.residual = VectorXd{{x[0] * x[0] + x[1] * x[1] - 4.0, x[0] - x[1]}};
    p.jacobian = MatrixXd{{2.0 * x[0], 2.0 * x[1]}, {1.0, -1.0}};
    return p;
  };
  const DampedNewtonResult r = damped_newton(circle, VectorXd{{1.0, 0.5}}, {.tolerance = 1e-14});
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_EQ(r.status, NewtonStatus::converged);
  EXPECT_TRUE(r.failure.empty());
  EXPECT_LE(r.iterations, 6);
  EXPECT_LE(r.residual, 1e-14);
  EXPECT_NEAR(r.x[0], std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(r.x[1], std::sqrt(2.0), 1e-14);
}

TEST(DampedNewton, BacktrackingTamesAFullStepThatOvershoots) {
  const DampedNewtonResult damped = damped_newton(arctangent, VectorXd::Constant(1, 20.0), {.tolerance = 1e-12});
  ASSERT_TRUE(damped.converged) << damped.failure;
  EXPECT_NEAR(damped.x[0], 0.0, 1e-12);
  // Without halvings the first full step (to -590) is rejected, and so is the secant step through
  // it (to -280): the iteration stops, at the start.
  const DampedNewtonResult full =
      damped_newton(arctangent, VectorXd::Constant(1, 20.0), {.tolerance = 1e-12, .max_backtracks = 0});
  EXPECT_FALSE(full.converged);
  EXPECT_EQ(full.status, NewtonStatus::line_search_failed);
  EXPECT_EQ(full.iterations, 0);
  EXPECT_EQ(full.x[0], 20.0);
  EXPECT_NE(full.failure.find("|R| ="), std::string::npos) << full.failure;
}

TEST(DampedNewton, TheSecantStepPassesAKinkThatTheNewtonStepOvershoots) {
  // R = x above 1 and 1 + 10 (x - 1) below, root 0.9: from 3 the Newton step lands at 0, where
  // |R| = 9. Its secant through that point (slope 4, then towards 10) descends and converges.
  const NewtonSystem kinked = [](const VectorXd& x) {
    NewtonPoint p;
    const bool above = x[0] >= 1.0;
    p.residual = VectorXd::Constant(1, above ? x[0] : 1.0 + 10.0 * (x[0] - 1.0));
    p.jacobian = MatrixXd::Constant(1, 1, above ? 1.0 : 10.0);
    return p;
  };
  const DampedNewtonResult r =
      damped_newton(kinked, VectorXd::Constant(1, 3.0), {.tolerance = 1e-12, .max_backtracks = 0});
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_NEAR(r.x[0], 0.9, 1e-12);
}

TEST(DampedNewton, ChordStepsReuseTheFactorizationAcrossNeighbouringSolves) {
  // Circles of radius 2, 2.001, ... meet the line x0 = x1: each solve starts at the last root.
  const auto circle = [](double radius) -> NewtonSystem {
    return [radius](const VectorXd& x) {
      NewtonPoint p;
      p.residual = VectorXd{{x[0] * x[0] + x[1] * x[1] - radius * radius, x[0] - x[1]}};
      p.jacobian = MatrixXd{{2.0 * x[0], 2.0 * x[1]}, {1.0, -1.0}};
      return p;
    };
  };
  ChordFactorization chord;
  VectorXd x{{1.0, 0.5}};
  for (int i = 0; i < 10; ++i) {
    const double radius = 2.0 + 1e-3 * i;
    const DampedNewtonResult r = damped_newton(circle(radius), x, {.tolerance = 1e-13, .chord = &chord});
    ASSERT_TRUE(r.converged) << r.failure;
    EXPECT_NEAR(r.x[0], radius / std::sqrt(2.0), 1e-13);
    EXPECT_NEAR(r.x[1], r.x[0], 1e-13);
    x = r.x;
  }
  // The first solve factorizes; the later ones mostly reuse (each chord step contracts by 1/2).
  EXPECT_GT(chord.chord_steps, 0);
  EXPECT_LT(chord.factorizations, 10 + 5);
  EXPECT_THROW(ChordFactorization(1.0), std::invalid_argument);
  EXPECT_THROW(ChordFactorization(0.0), std::invalid_argument);
}

TEST(DampedNewton, LevenbergMarquardtStepsReduceTheResidualWhereNoHalvingIsAllowed) {
  // From 20 neither halving nor the secant step helps (above); damped steps do.
  const DampedNewtonResult r = damped_newton(arctangent, VectorXd::Constant(1, 20.0),
                                             {.tolerance = 1e-12, .max_backtracks = 0, .levenberg_marquardt = true});
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_NEAR(r.x[0], 0.0, 1e-12);
}

TEST(DampedNewton, AStepIntoTheUndefinedIsHalvedBackIntoTheDomain) {
  // R = log(x) from 3: the full step lands at x < 0, where R is NaN.
  const NewtonSystem logarithm = [](const VectorXd& x) {
    NewtonPoint p;
    p.residual = VectorXd::Constant(1, std::log(x[0]));
    p.jacobian = MatrixXd::Constant(1, 1, 1.0 / x[0]);
    return p;
  };
  const DampedNewtonResult r = damped_newton(logarithm, VectorXd::Constant(1, 3.0), {.tolerance = 1e-13});
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_NEAR(r.x[0], 1.0, 1e-12);
}

TEST(DampedNewton, MinimumNormStepPutsNothingAlongTheNullSpace) {
  // One equation x0 + x1 = 2 in two unknowns: from 0 the minimum-norm solution (1, 1) in one step.
  const NewtonSystem line = [](const VectorXd& x) {
    NewtonPoint p;
    p.residual = VectorXd::Constant(1, x[0] + x[1] - 2.0);
    p.jacobian = MatrixXd{{1.0, 1.0}};
    return p;
  };
  const DampedNewtonResult r = damped_newton(line, VectorXd::Zero(2), {.tolerance = 1e-14});
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_EQ(r.iterations, 1);
  EXPECT_NEAR(r.x[0], 1.0, 1e-15);
  EXPECT_NEAR(r.x[1], 1.0, 1e-15);
}

TEST(DampedNewton, SingularAndInvalidSystemsAreReportedNotThrownAndNeverNaN) {
  // x0 + x1 = 1 and 2 x0 + 2 x1 = 3 have no solution and a singular Jacobian.
  const NewtonSystem inconsistent = [](const VectorXd& x) {
    NewtonPoint p;
    p.residual = VectorXd{{x[0] + x[1] - 1.0, 2.0 * x[0] + 2.0 * x[1] - 3.0}};
    p.jacobian = MatrixXd{{1.0, 1.0}, {2.0, 2.0}};
    return p;
  };
  for (const NewtonStepSolve how :
       {NewtonStepSolve::full_pivot_lu, NewtonStepSolve::partial_pivot_lu, NewtonStepSolve::minimum_norm}) {
    const DampedNewtonResult r =
        damped_newton(inconsistent, VectorXd::Zero(2), {.tolerance = 1e-12, .step_solve = how});
    EXPECT_FALSE(r.converged);
    EXPECT_NE(r.status, NewtonStatus::converged);
    if (how == NewtonStepSolve::full_pivot_lu) {
      EXPECT_EQ(r.status, NewtonStatus::singular_jacobian);
    }
    EXPECT_TRUE(r.x.allFinite());
    EXPECT_TRUE(std::isfinite(r.residual));
    EXPECT_NE(r.failure.find("|R| ="), std::string::npos) << r.failure;
  }
  // A start that cannot be evaluated stops at once; a non-finite start comes back as zeros.
  const NewtonSystem nowhere = [](const VectorXd&) {
    NewtonPoint p;
    p.valid = false;
    return p;
  };
  const DampedNewtonResult r =
      damped_newton(nowhere, VectorXd::Constant(2, std::numeric_limits<double>::quiet_NaN()), {.tolerance = 1.0});
  EXPECT_EQ(r.status, NewtonStatus::invalid_point);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_TRUE(r.x.allFinite());
  EXPECT_FALSE(std::isnan(r.residual));
}

TEST(DampedNewton, IterationCapIsReportedWithTheResidual) {
  const DampedNewtonResult r =
      damped_newton(arctangent, VectorXd::Constant(1, 3.0), {.tolerance = 1e-12, .max_iterations = 2});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.status, NewtonStatus::iteration_limit);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_NE(r.failure.find("|R| ="), std::string::npos) << r.failure;
}

TEST(DampedNewton, CallersMeritConvergenceTestAndDataAreUsed) {
  // The caller's test asks for |R| <= 1e-12 where the tolerance alone would stop at 1e-3; the
  // merit is the caller's (10 |R|), and each point's data comes back with the final one.
  DampedNewtonOptions options{.tolerance = 1e-3};
  int merit_calls = 0;
  options.merit = [&merit_calls](const NewtonPoint& p) {
    ++merit_calls;
    return 10.0 * std::abs(p.residual[0]);
  };
  options.converged = [](const NewtonPoint& p) { return std::abs(p.residual[0]) <= 1e-12; };
  const NewtonSystem tagged = [](const VectorXd& x) {
    NewtonPoint p = arctangent(x);
    p.data = x[0];
    return p;
  };
  const DampedNewtonResult r = damped_newton(tagged, VectorXd::Constant(1, 3.0), options);
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_LE(std::abs(std::atan(r.x[0])), 1e-12);
  EXPECT_GT(merit_calls, 0);
  EXPECT_EQ(r.residual, 10.0 * std::abs(std::atan(r.x[0])));
  EXPECT_EQ(std::any_cast<double>(r.at.data), r.x[0]);
}

// A system that defers its Jacobian: the iteration assembles it only where it solves a step (and
// on the point it returns, unless told not to), never at the trial points the line search rejects,
// and converges along the same iterates as with the Jacobian given at every point.
TEST(DampedNewton, ADeferredJacobianIsAssembledOnlyWhereAStepIsSolved) {
  int evaluations = 0, assembled = 0;
  const NewtonSystem deferred = [&](const VectorXd& x) {
    ++evaluations;
    NewtonPoint p = arctangent(x);
    p.jacobian.resize(0, 0);
    p.data = x[0];
    p.complete_jacobian = [&assembled](NewtonPoint& q) {
      ++assembled;
      q.jacobian = arctangent(VectorXd::Constant(1, std::any_cast<double>(q.data))).jacobian;
    };
    return p;
  };
  DampedNewtonOptions options{.tolerance = 1e-13};
  const DampedNewtonResult eager = damped_newton(arctangent, VectorXd::Constant(1, 3.0), options);
  const DampedNewtonResult lazy = damped_newton(deferred, VectorXd::Constant(1, 3.0), options);
  ASSERT_TRUE(eager.converged && lazy.converged);
  EXPECT_EQ(lazy.iterations, eager.iterations);
  EXPECT_EQ(lazy.x[0], eager.x[0]);
  // From x = 3 the full step overshoots (atan), so some trials were rejected without a Jacobian:
  // one per step solved, plus the returned point's.
  EXPECT_GT(evaluations, lazy.iterations + 1);
  EXPECT_EQ(assembled, lazy.iterations + 1);
  EXPECT_EQ(lazy.at.jacobian.rows(), 1);
  options.jacobian_at_solution = false;
  assembled = 0;
  const DampedNewtonResult left = damped_newton(deferred, VectorXd::Constant(1, 3.0), options);
  EXPECT_EQ(assembled, left.iterations);
  EXPECT_EQ(left.at.jacobian.size(), 0);
}

}  // namespace
}  // namespace bb
