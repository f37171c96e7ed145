// Model comparison (identify/model_comparison): scores, ranking, and the leave-one-curve-out folds
// (issue 68, point 3): each fold holds out one more fitted curve, only its own left-out curve
// counts, and the ranking takes the folds' rms when every model has it.
#include "identify/model_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace bb {
namespace model_comparison_test {  // named: the unity build joins this file with others
namespace {

CalibrationData data(const std::string& name, bool held_out) {
  CalibrationData d;
  d.name = name;
  d.held_out = held_out;
  return d;
}

FitPoint point(const std::string& set, double residual, bool held_out) {
  FitPoint p;
  p.set = set;
  p.quantity = "amplitude";
  p.measured = 1.0;
  p.sigma = 0.1;
  p.computed = 1.0 + residual * p.sigma;
  p.held_out = held_out;
  return p;
}

// Fits "a" and "b \"q\"", holds out "c".
CalibrationOutcome outcome() {
  CalibrationOutcome o;
  o.spec.data = {data("a", false), data("b \"q\"", false), data("c", true)};
  o.values = {1.0, 2.0};
  o.converged = true;
  o.after = {point("a", 1.0, false), point("b \"q\"", 2.0, false), point("c", 3.0, true)};
  return o;
}

TEST(ModelComparison, ScoresChargeParametersAndMeasurePredictionOnHeldOutPoints) {
  const ModelScore s = score_calibration("m", outcome());
  EXPECT_EQ(s.fitted_points, 2);
  EXPECT_EQ(s.held_out_points, 1);
  EXPECT_NEAR(s.chi_square, 5.0, 1e-12);
  EXPECT_NEAR(s.aic, 9.0, 1e-12);
  EXPECT_NEAR(s.bic, 5.0 + 2.0 * std::log(2.0), 1e-12);
  EXPECT_NEAR(s.held_out_rms, 3.0, 1e-12);
  EXPECT_TRUE(std::isnan(s.leave_one_out_rms));
}

TEST(ModelComparison, EachFoldHoldsOutOneMoreFittedCurveWithItsNameQuoted) {
  const CalibrationOutcome o = outcome();
  EXPECT_EQ(fitted_sets(o), (std::vector<std::string>{"a", "b \"q\""}));
  EXPECT_EQ(fold_hold_out_setting(o, "a"), "calibration.hold_out=[\"a\", \"c\"]");
  EXPECT_EQ(fold_hold_out_setting(o, "b \"q\""), "calibration.hold_out=[\"b \\\"q\\\"\", \"c\"]");
}

// Fold 1 left out "a" (residual 4 there), fold 2 left out "b" (residual 2): rms sqrt((16 + 4) / 2);
// the curves each fold fitted, and the case's own held-out curve, do not count.
TEST(ModelComparison, LeaveOneOutCountsOnlyEachFoldsLeftOutCurveAndRanksWhenEveryModelHasIt) {
  std::vector<CalibrationOutcome> folds(2, outcome());
  folds[0].after = {point("a", 4.0, true), point("b \"q\"", 0.5, false), point("c", 9.0, true)};
  folds[1].after = {point("a", 0.5, false), point("b \"q\"", 2.0, true), point("c", 9.0, true)};
  folds[1].converged = false;
  ModelScore good = score_calibration("good", outcome());
  score_leave_one_out(good, folds, {"a", "b \"q\""});
  EXPECT_NEAR(good.leave_one_out_rms, std::sqrt(10.0), 1e-12);
  EXPECT_EQ(good.folds, 2);
  EXPECT_EQ(good.folds_converged, 1);
  // A model better on the case's hold-out but worse on the folds ranks second by the folds.
  ModelScore other = score_calibration("other", outcome());
  other.held_out_rms = 0.1;
  other.leave_one_out_rms = 5.0;
  std::vector<ModelScore> scores = {good, other};
  const CalibrationOutcome a = outcome(), b = outcome();
  rank_models(scores, {&a, &b});
  EXPECT_EQ(scores[0].rank, 1);
  EXPECT_EQ(scores[1].rank, 2);
  // Without folds for every model, the case's hold-out decides.
  scores[0].leave_one_out_rms = NAN;
  rank_models(scores, {&a, &b});
  EXPECT_EQ(scores[1].rank, 1);
}

}  // namespace
}  // namespace model_comparison_test
}  // namespace bb
