// What an identification reports: every start of the multi-start fit, the identified values with
// their covariance, the fitted points before and after, and the cross-check by an independent model.
#pragma once
#include <Eigen/Dense>
#include <toml++/toml.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checks/checks.hpp"
#include "identify/calibration_spec.hpp"
#include "identify/fit_points.hpp"
#include "results/table.hpp"

namespace bb {

// One start of a multi-start fit.
struct CalibrationStart {
  std::vector<double> start, values;            // parameter values at the start and at its end
  double initial_cost = 0.0, final_cost = 0.0;  // NaN when not evaluated
  int iterations = 0;
  bool converged = false;
  bool evaluated = true;  // false: the model could not be run at the start values
};

// The posterior sampled around the identified values ([calibration.sampler]).
struct PosteriorSummary {
  int walkers = 0, steps = 0, kept_steps = 0, evaluations = 0, predictions = 0;
  double acceptance = 0.0;
  std::vector<double> autocorrelation_steps;  // per parameter
  std::vector<double> mean, std_dev;          // per parameter, in its units
  std::string warning;                        // not mixed
  double seconds = 0.0;
};

struct CalibrationOutcome {
  std::vector<CalibrationStart> starts;  // every start, in order (the first from the case's values)
  size_t best = 0;                       // the start whose result is reported
  CalibrationSpec spec;
  std::vector<double> values;         // identified values, in spec.parameters order
  std::vector<double> std_devs;       // 1-sigma, from the covariance at the optimum (NaN if unavailable),
                                      // scaled by reduced_chi_square when that exceeds 1
  double reduced_chi_square = NAN;    // 2 cost / (residuals - parameters) at the optimum (with the loss)
  Eigen::MatrixXd correlation;        // empty if the covariance could not be computed
  std::vector<std::string> warnings;  // identifiability and convergence warnings
  // The cost along the weakest direction (the largest eigenvector of the covariance, in log values),
  // at t = -2, -1, 1, 2 of its standard deviation: a quadratic cost rises by t^2 / 2 times the
  // covariance's scale; a much flatter rise shows the linearized spread understates the uncertainty.
  struct ProfilePoint {
    double t = 0.0;
    std::vector<double> values;
    double rise = NAN;       // cost - cost at the optimum (NaN: the model could not be evaluated)
    double predicted = 0.0;  // t^2 / 2 times max(1, reduced chi-square)
  };
  std::vector<double> weakest_direction;  // unit vector in log values, parameters order; empty: none
  std::vector<ProfilePoint> weakest_profile;
  std::vector<std::pair<int, double>> history;  // (iteration, cost)
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int residual_evaluations = 0;  // model runs (a central-difference Jacobian costs 2 n of them)
  std::string derivatives;       // how the Jacobian was computed ("analytic ..." or "central differences ...")
  int jacobian_fallbacks = 0;    // analytic Jacobians taken by central differences (a point had no derivative)
  int one_sided_columns = 0;     // difference columns taken one-sided (the model failed on the other side)
  bool converged = false;
  std::string termination;                   // Ceres's report
  std::vector<FitPoint> before;              // fitted points at the case's start values
  std::vector<FitPoint> after;               // and at the identified values
  ResultTables curves_before, curves_after;  // the result tables the measured curves are fitted to
  toml::table calibrated;                    // the case table with the identified values
  // The cross-check case run with the identified values (spec.cross_check), every check entry.
  std::vector<CheckEntry> cross_check;
  // Its result tables at the identified values (with band columns when spec.cross_check_bands).
  ResultTables cross_check_tables;
  std::optional<PosteriorSummary> posterior;  // when [calibration.sampler] is given
  double cross_check_seconds = 0.0;
  // Why the cross-check case found no solution (its checks then have nothing to read); the
  // identification is kept and reported all the same.
  std::string cross_check_failure;
  bool cross_check_passed() const;
};

}  // namespace bb
