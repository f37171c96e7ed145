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
  // Run 0 at x, run 2j + 1 at x + h e_j, run 2j + 2 at x - h e_j.
  const auto n = static_cast<std::size_t>(parameters_);
  std::vector<Eigen::VectorXd> runs(2 * n + 1, Eigen::VectorXd(m));
  std::vector<char> ok(2 * n + 1, 0);
  std::size_t first_run = 0;
  {
    const std::lock_guard<std::mutex> guard(last_lock_);
    if (last_x_ == x) {
      std::copy(last_residuals_.begin(), last_residuals_.end(), runs[0].data());
      ok[0] = 1;
      first_run = 1;
    }
  }
  for_each_index(2 * n + 1 - first_run, std::min(workers_, 2 * n + 1 - first_run), [&](std::size_t run) {
    const std::size_t k = run + first_run;
    std::vector<double> y = x;
    if (k > 0) {
      const std::size_t j = (k - 1) / 2;
      y[j] = k % 2 == 1 ? x[j] + step_ : x[j] - step_;
    }
    ok[k] = residual_(y, runs[k].data()) ? 1 : 0;
  });
  if (!ok[0]) return false;
  std::copy(runs[0].data(), runs[0].data() + m, residuals);
  // Row-major m x n, as Ceres lays out a parameter block's Jacobian.
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> jacobian(jacobians[0], m,
                                                                                              parameters_);
  int one_sided = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const bool up = ok[2 * j + 1] != 0, down = ok[2 * j + 2] != 0;
    if (!up && !down) return false;
    auto column = jacobian.col(static_cast<Eigen::Index>(j));
    if (up && down)
      column = (runs[2 * j + 1] - runs[2 * j + 2]) / (2.0 * step_);
    else
      column = up ? (runs[2 * j + 1] - runs[0]) / step_ : (runs[0] - runs[2 * j + 2]) / step_;
    one_sided += up != down;
  }
  if (one_sided_ && one_sided > 0) std::atomic_ref<int>(*one_sided_).fetch_add(one_sided);
  return true;
}

}  // namespace bb
