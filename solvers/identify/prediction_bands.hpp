// Bands on predicted values: the identified parameters' uncertainty carried into every computed
// point, linearised (var = g^T C g, g the point's exact sensitivities; the delta method), and the
// share of measured points that the 95 % prediction interval covers, where a new measurement
// also carries its own noise: computed +- z sqrt(band^2 + sigma^2).
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "identify/calibration_outcome.hpp"
#include "identify/fit_points.hpp"

namespace bb {

// The parameters' covariance in their own units, from the outcome's standard deviations and
// correlation; empty when the fit has none (a singular Jacobian, a NaN deviation).
Eigen::MatrixXd parameter_covariance(const CalibrationOutcome& o);

// Sets each point's band from its gradient (d r / d log p, FitPoint::gradient: d computed / d p_j
// = gradient_j sigma / p_j) and the covariance; points without a full gradient keep NaN.
void set_linearised_bands(std::vector<FitPoint>& points, const std::vector<double>& values,
                          const Eigen::MatrixXd& covariance);

struct BandCoverage {
  int points = 0;   // with a band
  int covered = 0;  // measured within the prediction interval
  double share() const { return points ? static_cast<double>(covered) / points : 0.0; }
};

// Of the held-out points (held_out = true) or the fitted ones, how many the two-sided prediction
// interval of probability `level` holds.
BandCoverage band_coverage(const std::vector<FitPoint>& points, bool held_out, double level = 0.95);

// The tables `at` (a model run at the identified values) with a column `<column>_band_1sigma`
// beside every numeric column that some parameter moves (wall times aside: `*seconds`, `*_per_step`): sqrt(d^T C d), d
// the column's central differences over the parameters (`minus[j]`, `plus[j]`: the same model at p_j -+ step[j]), C the
// covariance in the parameters' own units. A cell whose differences are not finite (a run without that row's solution)
// gets NaN. Tables the runs do not all have are returned unchanged.
ResultTables with_band_columns(const ResultTables& at, const std::vector<ResultTables>& minus,
                               const std::vector<ResultTables>& plus, const std::vector<double>& step,
                               const Eigen::MatrixXd& covariance);

// The two-sided standard normal quantile of `level` (1.95996 for 0.95).
double normal_quantile(double level);

}  // namespace bb
