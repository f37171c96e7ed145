// The Jacobian of a fit's residuals by central differences, its 2n + 1 model runs spread over
// workers (issue 31, point 5): each run of an hbm case is a whole sweep, and a calibration of one
// start otherwise leaves cores idle while Ceres differentiates column after column.
//
// Ceres evaluates the residuals at a candidate before it asks for the Jacobian there: the last
// residuals are kept, and a Jacobian at the same parameters reuses them as its centre run.
//
// The differences are Ceres's own (ceres::DynamicNumericDiffCostFunction with CENTRAL): step
// delta_j = max(sqrt(eps), relative_step |x_j|), column (r(x + delta_j e_j) - r(x - delta_j e_j))
// times (1 / delta_j) / 2, so that the result is that of the serial Ceres cost function bit for bit
// whatever the number of workers (the model runs are deterministic and independent).
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
  // `residual` must be safe to call from several threads at once. workers >= 1.
  CentralDifferences(ResidualFunction residual, int parameters, int residuals, double relative_step,
                     std::size_t workers);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  ResidualFunction residual_;
  int parameters_;
  double relative_step_;
  std::size_t workers_;
  // The last successful residual-only evaluation.
  mutable std::mutex last_lock_;
  mutable std::vector<double> last_x_, last_residuals_;
};

}  // namespace bb
