#include "identify/prediction_bands.hpp"

#include <cmath>
#include <stdexcept>

namespace bb {

Eigen::MatrixXd parameter_covariance(const CalibrationOutcome& o) {
  const auto n = static_cast<Eigen::Index>(o.std_devs.size());
  if (n == 0 || o.correlation.rows() != n) return {};
  Eigen::MatrixXd c(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      c(i, j) = o.correlation(i, j) * o.std_devs[static_cast<size_t>(i)] * o.std_devs[static_cast<size_t>(j)];
      if (!std::isfinite(c(i, j))) return {};
    }
  return c;
}

void set_linearised_bands(std::vector<FitPoint>& points, const std::vector<double>& values,
                          const Eigen::MatrixXd& covariance) {
  const auto n = static_cast<Eigen::Index>(values.size());
  if (covariance.rows() != n) return;
  for (FitPoint& p : points) {
    if (p.gradient.size() != values.size()) continue;
    Eigen::VectorXd g(n);
    for (Eigen::Index j = 0; j < n; ++j) g[j] = p.gradient[static_cast<size_t>(j)] * p.sigma / values[static_cast<size_t>(j)];
    if (!g.allFinite()) continue;
    p.band = std::sqrt(std::max(0.0, g.dot(covariance * g)));
  }
}

double normal_quantile(double level) {
  if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("a band level lies in (0, 1)");
  // Bisection on erf: the quantile z with P(|Z| <= z) = level.
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erf(mid / std::sqrt(2.0)) < level ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

BandCoverage band_coverage(const std::vector<FitPoint>& points, bool held_out, double level) {
  const double z = normal_quantile(level);
  BandCoverage c;
  for (const FitPoint& p : points) {
    if (p.held_out != held_out || !std::isfinite(p.band)) continue;
    ++c.points;
    if (std::abs(p.misfit()) <= z * std::hypot(p.band, p.sigma)) ++c.covered;
  }
  return c;
}

}  // namespace bb
