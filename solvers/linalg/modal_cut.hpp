// Where the count of the modes found is taken: just above the n-th eigenvalue, a repeated one there
// whole. Shared by the default eigensolver's Sturm count and SLEPc's slicing interval.
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <optional>

namespace bb {

// The shift at which the Sturm count is taken: just above the n-th eigenvalue, so that a repeated
// eigenvalue there is counted whole. When the n-th mode is a rigid-body mode (lambda ~ 0, where the
// count would hinge on rounding), a small fraction of the first elastic eigenvalue found; nullopt
// when none was found (every computed mode is rigid: nothing to separate).
inline std::optional<double> count_shift(const Eigen::VectorXd& eigenvalues, int n, double cluster_tolerance) {
  const double top = eigenvalues.maxCoeff();
  if (!(top > 0.0)) return std::nullopt;
  const double lambda_n = eigenvalues[n - 1];
  const double rigid = 1e-8 * top;
  if (std::abs(lambda_n) > rigid) return lambda_n + cluster_tolerance * std::abs(lambda_n);
  for (Eigen::Index k = n; k < eigenvalues.size(); ++k)
    if (eigenvalues[k] > rigid) return 1e-3 * eigenvalues[k];
  return std::nullopt;
}

}  // namespace bb
