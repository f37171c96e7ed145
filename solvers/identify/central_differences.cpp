#include "identify/central_differences.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <atomic>
#include <utility>

#include "common/parallel_indices.hpp"

namespace bb {

CentralDifferences::CentralDifferences(ResidualFunction residual, int parameters, int residuals, double step,
                                       std::size_t workers, int* one_sided)
    : residual_(std::move(residual)),
      parameters_(parameters),
      step_(step),
      workers_(std::max<std::size_t>(1, workers)),
      one_sided_(one_sided) {
  mutable_parameter_block_sizes()->push_back(parameters);
  set_num_residuals(residuals);
}

bool CentralDifferences::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const std::vector<double> x(parameters[0], parameters[0] + parameters_);
  const int m = num_residuals();
  if (jacobians == nullptr || jacobians[0] == nullptr) {
    if (!residual_(x, residuals)) return false;
    const std::lock_guard<std::mutex> guard(last_lock_);
    last_x_ = x;
    last_residuals_.assign(residuals, residuals + m);
    return true;
  }
  bool kept = false;  // Ceres evaluated the residuals here just before: reuse them as the centre run
  {
    const std::lock_guard<std::mutex> guard(last_lock_);
    if (last_x_ == x) {
      std::copy(last_residuals_.begin(), last_residuals_.end(), residuals);
      kept = true;
    }
  }
  if (!kept && !residual_(x, residuals)) return false;
  std::vector<std::size_t> all(static_cast<std::size_t>(parameters_));
  for (std::size_t j = 0; j < all.size(); ++j) all[j] = j;
  return Columns(x, residuals, all, jacobians[0]);
}

bool CentralDifferences::Columns(const std::vector<double>& x, const double* centre,
                                 const std::vector<std::size_t>& which, double* jacobian) const {
  const int m = num_residuals();
  // Run 2k at x + h e_j, run 2k + 1 at x - h e_j, for j = which[k].
  const std::size_t runs_count = 2 * which.size();
  std::vector<Eigen::VectorXd> runs(runs_count, Eigen::VectorXd(m));
  std::vector<char> ok(runs_count, 0);
  for_each_index(runs_count, std::min(workers_, std::max<std::size_t>(1, runs_count)), [&](std::size_t run) {
    const std::size_t j = which[run / 2];
    std::vector<double> y = x;
    y[j] = run % 2 == 0 ? x[j] + step_ : x[j] - step_;
    ok[run] = residual_(y, runs[run].data()) ? 1 : 0;
  });
  const Eigen::Map<const Eigen::VectorXd> at(centre, m);
  // Row-major m x n, as Ceres lays out a parameter block's Jacobian.
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> matrix(jacobian, m, parameters_);
  int one_sided = 0;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const bool up = ok[2 * k] != 0, down = ok[2 * k + 1] != 0;
    if (!up && !down) return false;
    auto column = matrix.col(static_cast<Eigen::Index>(which[k]));
    if (up && down)
      column = (runs[2 * k] - runs[2 * k + 1]) / (2.0 * step_);
    else if (up)
      column = (runs[2 * k] - at) / step_;
    else
      column = (at - runs[2 * k + 1]) / step_;
    one_sided += up != down;
  }
  if (one_sided_ && one_sided > 0) std::atomic_ref<int>(*one_sided_).fetch_add(one_sided);
  return true;
}

}  // namespace bb
