// Weighted nonlinear least squares of a calibration (Ceres, trust region, bounded, in log space):
// multi-start from the spec's values and a Latin hypercube, the covariance at the optimum scaled
// by the reduced chi-square, and warnings on identifiability (correlations, bounds, other minima).
// The model is a callback: this layer knows nothing of case files.
#pragma once
#include <functional>
#include <vector>

#include "identify/calibration_outcome.hpp"

namespace bb {

// The fitted points at parameter values (SI, spec.parameters order); with `gradients`, each point
// carries d residual / d log p. Throws (any exception) when the model cannot be evaluated there.
using FitEvaluator = std::function<std::vector<FitPoint>(const std::vector<double>& values, bool gradients)>;

// One line of progress per trust-region iteration; the caller decides where it goes.
struct FitIteration {
  int start = 0, starts = 0, iteration = 0, max_iterations = 0;
  double cost = 0.0, gradient_max_norm = 0.0;
  bool accepted = false;
};
using FitProgress = std::function<void(const FitIteration&)>;

// Fits spec.parameters to the `residuals` points of `evaluate` (analytic: with its gradients, else
// central differences of relative step spec.derivative_step). With `analytic`, the columns marked
// in `numeric_columns` (the parameters the model does not differentiate; their gradient entries
// are ignored) are central differences, two model runs each. Fills every member of the outcome
// but before/after, curves, calibrated, cross_check and derivatives.
CalibrationOutcome fit_parameters(const CalibrationSpec& spec, const FitEvaluator& evaluate, bool analytic,
                                  int residuals, const FitProgress& progress = {},
                                  const std::vector<bool>& numeric_columns = {});

}  // namespace bb
