#include "timeint/flow_trace.hpp"

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <complex>

namespace bb::timeint {

FlowTrace::FlowTrace(const Eigen::RowVectorXd& row, const Eigen::MatrixXd& a, const Eigen::VectorXd& z,
                     const Eigen::RowVectorXcd* modal, const Eigen::VectorXcd* lambda,
                     const Eigen::VectorXcd* coordinates, double check_tau, double check_value)
    : row_(row), a_(a), z_(z) {
  if (!modal) return;
  weights_ = modal->transpose().cwiseProduct(*coordinates);
  lambda_ = *lambda;
  const double scale = row.cwiseAbs().dot(z.cwiseAbs()) + std::abs(check_value);
  spectral_ = std::abs(value(check_tau) - check_value) <= 1e-9 * scale;
}

double FlowTrace::value(double tau) const {
  if (tau == 0.0) return row_.dot(z_);
  if (!spectral_) return row_.dot((a_ * tau).exp() * z_);
  return (weights_.array() * (lambda_.array() * tau).exp()).sum().real();
}

double FlowTrace::rate(double tau) const {
  if (!spectral_) return (row_ * a_).dot((a_ * tau).exp() * z_);
  return (weights_.array() * lambda_.array() * (lambda_.array() * tau).exp()).sum().real();
}

double crossing(const FlowTrace& g, double lo, double hi) {
  double g_lo = g.value(lo), g_hi = g.value(hi);
  if (g_lo > 0.0) return lo;
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > kPhaseResolution; ++it) {
    double mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (!(mid > lo && mid < hi) || it % 8 == 7) mid = 0.5 * (lo + hi);  // bisect now and then: bounded
    const double v = g.value(mid);
    if (v > 0.0) {
      hi = mid, g_hi = v;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    } else {
      lo = mid, g_lo = v;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    }
  }
  return hi;
}

double turning_point(const FlowTrace& g, double hi) {
  double lo = 0.0;
  for (int it = 0; it < 200 && hi - lo > kPhaseResolution; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g.rate(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {

// (e^(mu tau) - 1) / mu, accurate where mu tau is small (tau where mu = 0).
std::complex<double> integral_of_exponential(std::complex<double> mu, double tau) {
  const std::complex<double> x = mu * tau;
  if (x == 0.0) return tau;
  // e^x - 1 = (e^re - 1) cos y + (cos y - 1) + i e^re sin y, with cos y - 1 = -2 sin^2(y / 2)
  const double e = std::expm1(x.real()), half = std::sin(0.5 * x.imag());
  const std::complex<double> expm1_x(e * std::cos(x.imag()) - 2.0 * half * half, (e + 1.0) * std::sin(x.imag()));
  return expm1_x / mu;
}

}  // namespace

void add_fourier_integrals(const Eigen::MatrixXd& a, const Eigen::VectorXd& z, const Eigen::VectorXcd* coordinates,
                           const Eigen::MatrixXcd* vectors, const Eigen::VectorXcd* lambda, double theta0, double tau,
                           const std::vector<Eigen::Index>& entries, Eigen::MatrixXd& fourier) {
  using Eigen::Index;
  const int harmonics = static_cast<int>((fourier.cols() - 1) / 2);
  if (coordinates) {
    // q_d(theta0 + s) = sum_j V_dj c_j e^(lambda_j s): each harmonic's integral in closed form.
    for (size_t i = 0; i < entries.size(); ++i) {
      const Eigen::VectorXcd w = vectors->row(entries[i]).transpose().cwiseProduct(*coordinates);
      const auto r = static_cast<Index>(i);
      for (int h = 0; h <= harmonics; ++h) {
        const std::complex<double> shift(0.0, -static_cast<double>(h));
        std::complex<double> sum = 0.0;
        for (Index j = 0; j < w.size(); ++j) sum += w[j] * integral_of_exponential((*lambda)[j] + shift, tau);
        const std::complex<double> value = std::exp(shift * theta0) * sum;  // int q e^(-i h theta)
        if (h == 0) {
          fourier(r, 0) += value.real();
        } else {
          fourier(r, 2 * h - 1) += value.real();
          fourier(r, 2 * h) -= value.imag();
        }
      }
    }
    return;
  }
  // Pieces turn the fastest motion by at most 1 rad: 8 Gauss-Legendre points integrate it to rounding.
  static constexpr double kNodes[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double kWeights[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                         0.1012285362903763};
  for (int k = 0; k < 8; ++k) {
    const double x = k < 4 ? -kNodes[3 - k] : kNodes[k - 4], weight = (k < 4 ? kWeights[3 - k] : kWeights[k - 4]);
    const double s = 0.5 * tau * (1.0 + x), theta = theta0 + s;
    const Eigen::VectorXd q = (a * s).exp() * z;
    for (size_t i = 0; i < entries.size(); ++i) {
      const auto r = static_cast<Index>(i);
      const double value = 0.5 * tau * weight * q[entries[i]];
      fourier(r, 0) += value;
      for (int h = 1; h <= harmonics; ++h) {
        fourier(r, 2 * h - 1) += value * std::cos(h * theta);
        fourier(r, 2 * h) += value * std::sin(h * theta);
      }
    }
  }
}

}  // namespace bb::timeint
