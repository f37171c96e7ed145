// Model comparison: several model forms calibrated on the same data, ranked by what they predict
// of curves held out of their fits (rms residual of the held-out points, in sigma) and by
// information criteria of their fits, for Gaussian errors of known sigma:
//   AIC = chi2 + 2 k,  BIC = chi2 + k ln n,   chi2 = sum of squared fitted residuals, k parameters,
// n fitted points. AIC and BIC reward a fit and charge its parameters; only the held-out error
// measures prediction, which is what a calibrated joint model is for.
#pragma once
#include <string>
#include <vector>

#include "identify/calibration_outcome.hpp"

namespace bb {

struct ModelScore {
  std::string name;  // the case's name
  int parameters = 0, fitted_points = 0, held_out_points = 0;
  double chi_square = 0.0, aic = 0.0, bic = 0.0;
  double held_out_rms = 0.0;            // rms residual of the held-out points [sigma]; NaN: none held out
  double held_out_largest_error = 0.0;  // largest |computed / measured - 1| of the held-out points
  double band_coverage = -1.0;          // share of held-out points in their 95 % band; -1: no bands
  int cross_check_passed = 0, cross_check_entries = 0;
  bool converged = false;
  int rank = 0;  // by held-out rms (then BIC), 1 the best
};

// Scores one calibration.
ModelScore score_calibration(const std::string& name, const CalibrationOutcome& o);

// Ranks scores in place (rank 1 = lowest held-out rms; without held-out points, lowest BIC). The
// sets fitted and held out by each outcome must be the same: std::invalid_argument names the
// first that differs (a comparison on other data compares nothing).
void rank_models(std::vector<ModelScore>& scores, const std::vector<const CalibrationOutcome*>& outcomes);

}  // namespace bb
