#include "forced/backbone_extraction.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace bb {

BackbonePoint extract_backbone_point(const std::vector<double>& frequency_hz, const std::vector<double>& amplitude_m,
                                     const std::vector<double>& force_n) {
  const size_t n = frequency_hz.size();
  if (n < 5 || amplitude_m.size() != n || force_n.size() != n)
    throw std::invalid_argument("a backbone point needs at least 5 points of frequency, amplitude and force");
  for (size_t i = 0; i < n; ++i)
    if (!(frequency_hz[i] > 0.0) || !(amplitude_m[i] > 0.0) || !(force_n[i] > 0.0))
      throw std::invalid_argument("frequencies, amplitudes and forces must be positive");
  const double two_pi = 2.0 * std::numbers::pi;
  std::vector<double> x(n), y(n);
  for (size_t i = 0; i < n; ++i) {
    x[i] = std::pow(two_pi * frequency_hz[i], 2);
    y[i] = std::pow(force_n[i] / amplitude_m[i], 2);
  }
  const size_t smallest = static_cast<size_t>(std::min_element(y.begin(), y.end()) - y.begin());
  const auto [xmin, xmax] = std::minmax_element(x.begin(), x.end());
  const double x0 = x[smallest], scale = 0.5 * (*xmax - *xmin);
  Eigen::MatrixXd A(static_cast<Eigen::Index>(n), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  for (size_t i = 0; i < n; ++i) {
    const double u = (x[i] - x0) / scale, w = 1.0 / y[i];
    const auto r = static_cast<Eigen::Index>(i);
    A.row(r) << w * u * u, w * u, w;
    b[r] = 1.0;  // w y_i
  }
  const Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
  const double alpha = c[0], beta = c[1], gamma = c[2];
  const double u_star = -beta / (2.0 * alpha), y_min = gamma - beta * beta / (4.0 * alpha);
  const double x_star = x0 + u_star * scale;
  if (!(alpha > 0.0) || !(y_min > 0.0) || x_star < *xmin || x_star > *xmax)
    throw std::invalid_argument("the curve has no resonance inside its band (the force has no interior minimum)");
  BackbonePoint p;
  p.mass_kg = std::sqrt(alpha) / scale;
  // y_min = 4 m^2 w0^4 z^2 (1 - z^2), x* = w0^2 (1 - 2 z^2): two fixed-point steps from w0^2 = x*.
  double w0sq = x_star, z2 = 0.0;
  for (int it = 0; it < 3; ++it) {
    z2 = y_min / (4.0 * p.mass_kg * p.mass_kg * w0sq * w0sq);
    z2 = 0.5 * (1.0 - std::sqrt(std::max(0.0, 1.0 - 4.0 * z2)));  // z^2 (1 - z^2) = q, the small root
    w0sq = x_star / (1.0 - 2.0 * z2);
  }
  p.damping_ratio = std::sqrt(z2);
  p.frequency_hz = std::sqrt(w0sq) / two_pi;
  // The held amplitude where the forcing frequency crosses the resonance (linear between points).
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return x[a] < x[b]; });
  p.amplitude_m = amplitude_m[order.front()];
  for (size_t k = 1; k < n; ++k) {
    const size_t i = order[k - 1], j = order[k];
    if (x[j] >= x_star) {
      const double t = x[j] > x[i] ? (x_star - x[i]) / (x[j] - x[i]) : 0.0;
      p.amplitude_m = amplitude_m[i] + t * (amplitude_m[j] - amplitude_m[i]);
      break;
    }
  }
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double u = (x[i] - x0) / scale;
    const double model = std::sqrt(std::max(0.0, alpha * u * u + beta * u + gamma));
    sum += std::pow(model / std::sqrt(y[i]) - 1.0, 2);
  }
  p.rms_relative = std::sqrt(sum / static_cast<double>(n));
  return p;
}

}  // namespace bb
