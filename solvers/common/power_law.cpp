#include "common/power_law.hpp"

#include <cmath>
#include <limits>

namespace bb {

double power_law_error(const std::array<double, 3>& x, double d_before, double d) {
  if (!std::isfinite(d) || !std::isfinite(d_before)) return std::numeric_limits<double>::infinity();
  if (d == 0) return 0.0;
  if (!(d_before > 0)) return std::numeric_limits<double>::infinity();
  // ratio(p) = (x1^-p - x2^-p) / (x0^-p - x1^-p) falls from ln(x2/x1) / ln(x1/x0) (p -> 0) towards 0.
  const auto ratio = [&](double p) {
    return (std::pow(x[1], -p) - std::pow(x[2], -p)) / (std::pow(x[0], -p) - std::pow(x[1], -p));
  };
  const double target = d / d_before;
  if (!(target < std::log(x[2] / x[1]) / std::log(x[1] / x[0]))) return std::numeric_limits<double>::infinity();
  double lo = 1e-6, hi = 30.0;
  if (ratio(hi) > target) lo = hi;  // converging faster than x^-30: the difference is the error
  for (int k = 0; k < 100 && hi - lo > 1e-10; ++k) (ratio(0.5 * (lo + hi)) > target ? lo : hi) = 0.5 * (lo + hi);
  const double p = 0.5 * (lo + hi);
  const double a = std::pow(x[1], -p), b = std::pow(x[2], -p);
  return d * a / (a - b);
}

}  // namespace bb
