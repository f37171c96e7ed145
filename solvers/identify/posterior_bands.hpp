// The posterior of a calibration sampled around its optimum (identify/ensemble_sampler.hpp), and
// the spread it gives every predicted point: a band that does not assume the cost is quadratic,
// where the linearised band (identify/prediction_bands.hpp) does. Likelihood exp(-cost / s), cost
// = sum r^2 / 2 over the fitted points (Gaussian: a robust loss is not applied here) and s the
// reduced chi-square when above 1 (as the linearised deviations are scaled); a flat prior within
// the bounds, in the fit's variables (log values, or linear where asked).
#pragma once
#include <functional>
#include <vector>

#include "identify/calibration_outcome.hpp"
#include "identify/least_squares_fit.hpp"

namespace bb {

// `fitted`: the fitted points at parameter values (the fit's evaluator); `predict`: every point,
// held-out too, in the order of `points` (the outcome's `after`), whose sampled_band it sets.
// Walkers start in a ball of a tenth of the linearised deviation about the optimum (1e-3 in the
// fit variables where there is none).
PosteriorSummary sample_posterior(const CalibrationSpec& spec, const CalibrationOutcome& o, const FitEvaluator& fitted,
                                  const std::function<std::vector<FitPoint>(const std::vector<double>&)>& predict,
                                  std::vector<FitPoint>& points);

}  // namespace bb
