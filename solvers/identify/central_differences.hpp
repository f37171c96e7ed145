// The Jacobian of a fit's residuals by central differences, its 2n + 1 model runs spread over
// workers (issue 31, point 5): each run of an hbm case is a whole sweep, and a calibration of one
// start otherwise leaves cores idle while Ceres differentiates column after column.
//
// Ceres evaluates the residuals at a candidate before it asks for the Jacobian there: the last
// residuals are kept, and a Jacobian at the same parameters reuses them as its centre run.
//
// Column j is (r(x + h e_j) - r(x - h e_j)) / (2 h) with one absolute step h for every parameter: a
// fit's parameters are log values, so h is the relative step of each parameter whatever its unit.
// (Ceres's numeric differences step h |x_j|, which on log values depends on the unit: log kt = 18.4
// in N/m took a 20 % step, a parameter whose value is 1 one of 1.5e-8.) The result is the same bit
// for bit whatever the number of workers (the model runs are deterministic and independent).
//
// Where the model cannot be run on one side of x (a bound of the physics just beyond the fit's
// bound, a peak leaving the band), that column is the one-sided difference with the centre run,
// O(h) instead of O(h^2), and counted; where it fails on both sides the evaluation fails.
#pragma once
#include <ceres/cost_function.h>

#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

namespace bb {

// Residuals at the parameters x (n values); false where the model cannot be evaluated there.
using ResidualFunction = std::function<bool(const std::vector<double>& x, double* residuals)>;

class CentralDifferences : public ceres::CostFunction {
 public:
  // `residual` must be safe to call from several threads at once. step > 0, workers >= 1.
  // `one_sided`, when given, counts the columns taken one-sided.
  CentralDifferences(ResidualFunction residual, int parameters, int residuals, double step, std::size_t workers,
                     int* one_sided = nullptr);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;
  // Only the columns `which` of the Jacobian at x (row-major m x n, the others untouched), around
  // `centre`, the residuals at x: two model runs per column. False where a column fails on both sides.
  bool Columns(const std::vector<double>& x, const double* centre, const std::vector<std::size_t>& which,
               double* jacobian) const;

 private:
  ResidualFunction residual_;
  int parameters_;
  double step_;
  std::size_t workers_;
  int* one_sided_;
  // The last successful residual-only evaluation.
  mutable std::mutex last_lock_;
  mutable std::vector<double> last_x_, last_residuals_;
};

}  // namespace bb
