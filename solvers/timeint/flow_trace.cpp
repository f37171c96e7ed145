#include "timeint/flow_trace.hpp"

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>

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

}  // namespace bb::timeint
