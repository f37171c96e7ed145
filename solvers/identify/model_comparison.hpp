// Model comparison: several model forms calibrated on the same data, ranked by what they predict
// of curves held out of their fits (rms residual of the held-out points, in sigma) and by
// information criteria of their fits, for Gaussian errors of known sigma:
//   AIC = chi2 + 2 k,  BIC = chi2 + k ln n,   chi2 = sum of squared fitted residuals, k parameters,
// n fitted points. AIC and BIC reward a fit and charge its parameters; only the held-out error
// measures prediction, which is what a calibrated joint model is for. Leave-one-curve-out refits
// (each fitted curve held out of one more fit, predicted by it) measure it on every curve the data
// have, not only on those a case holds out.
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
  // Leave-one-curve-out: rms residual [sigma] of every fitted curve's points predicted by the fit
  // that left that curve out; NaN when not run. `folds` refits, `folds_converged` of them converged.
  double leave_one_out_rms = NAN;
  int folds = 0, folds_converged = 0;
  int rank = 0;  // by leave-one-out rms where every model has it, else held-out rms; then BIC
};

// Scores one calibration.
ModelScore score_calibration(const std::string& name, const CalibrationOutcome& o);

// The sets a leave-one-curve-out fold leaves out: each data set the calibration fits, one per fold.
std::vector<std::string> fitted_sets(const CalibrationOutcome& o);
// The `calibration.hold_out` setting (as `calibrate --set`) of the fold that also leaves out `set`.
std::string fold_hold_out_setting(const CalibrationOutcome& o, const std::string& set);
// Fills s.leave_one_out_rms and the fold counts from the folds' outcomes, fold i having left out
// left_out[i]: only each fold's own left-out curve counts.
void score_leave_one_out(ModelScore& s, const std::vector<CalibrationOutcome>& folds,
                         const std::vector<std::string>& left_out);

// Ranks scores in place (rank 1 = lowest leave-one-out rms when every score has one, else lowest
// held-out rms; without held-out points, lowest BIC). The
// sets fitted and held out by each outcome must be the same: std::invalid_argument names the
// first that differs (a comparison on other data compares nothing).
void rank_models(std::vector<ModelScore>& scores, const std::vector<const CalibrationOutcome*>& outcomes);

}  // namespace bb
