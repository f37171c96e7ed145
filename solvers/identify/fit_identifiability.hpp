// What a fit's data determine at its optimum (identify/least_squares_fit's second half): the
// covariance from the Jacobian in log parameters, the parameters and combinations the data do not
// identify, the cost along the weakest direction, other starts' minima inside the confidence region.
#pragma once
#include <ceres/problem.h>

#include <cstddef>
#include <vector>

#include "identify/calibration_outcome.hpp"

namespace bb {

// Standard deviations, correlations, the weakest-direction profile and the identifiability
// warnings at the optimum x (log values; restored on return) of `problem`, into `out`
// (out.values and out.reduced_chi_square already set).
void add_covariance(ceres::Problem& problem, std::vector<double>& x, const CalibrationSpec& cal,
                    CalibrationOutcome& out);

// Warns for each converged start that ends inside the 95 % joint confidence region of the best at
// other values (a minimum that is not unique); n parameters.
void warn_other_minima(CalibrationOutcome& out, std::size_t n);

}  // namespace bb
