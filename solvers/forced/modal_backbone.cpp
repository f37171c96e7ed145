#include "forced/modal_backbone.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bb {

ModalBackbone::ModalBackbone(std::vector<double> amplitudes, std::vector<double> values)
    : a_(std::move(amplitudes)), y_(std::move(values)) {
  if (a_.empty() || a_.size() != y_.size())
    throw std::invalid_argument("a backbone needs one value per amplitude and at least one knot");
  for (size_t i = 0; i < a_.size(); ++i) {
    if (!(a_[i] > 0.0) || !std::isfinite(a_[i]) || !std::isfinite(y_[i]))
      throw std::invalid_argument("backbone amplitudes must be positive and values finite");
    if (i > 0 && !(a_[i] > a_[i - 1])) throw std::invalid_argument("backbone amplitudes must increase strictly");
    s_.push_back(std::log(a_[i]));
  }
  // Clamped spline (zero end slopes): A m = B y, so m = A^-1 B y for any values.
  const auto n = static_cast<Eigen::Index>(a_.size());
  second_ = Eigen::MatrixXd::Zero(n, n);
  m_ = Eigen::VectorXd::Zero(n);
  if (n < 2) return;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n), B = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double hl = j > 0 ? s_[j] - s_[j - 1] : 0.0, hr = j + 1 < n ? s_[j + 1] - s_[j] : 0.0;
    A(j, j) = 2.0 * (hl + hr);
    if (j > 0) A(j, j - 1) = hl, B(j, j - 1) += 6.0 / hl, B(j, j) -= 6.0 / hl;
    if (j + 1 < n) A(j, j + 1) = hr, B(j, j + 1) += 6.0 / hr, B(j, j) -= 6.0 / hr;
  }
  second_ = A.partialPivLu().solve(B);
  m_ = second_ * Eigen::Map<const Eigen::VectorXd>(y_.data(), n);
}

void ModalBackbone::set_value(size_t knot, double value) {
  if (knot >= y_.size() || !std::isfinite(value)) throw std::invalid_argument("backbone knot out of range");
  y_[knot] = value;
  m_ = second_ * Eigen::Map<const Eigen::VectorXd>(y_.data(), static_cast<Eigen::Index>(y_.size()));
}

double ModalBackbone::evaluate(double s, const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::VectorXd& m,
                               double* dyds) const {
  const size_t n = s_.size();
  if (n == 1 || s <= s_.front() || s >= s_.back()) {
    if (dyds) *dyds = 0.0;
    return s <= s_.front() || n == 1 ? y[0] : y[static_cast<Eigen::Index>(n - 1)];
  }
  const size_t j = static_cast<size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()) - 1;
  const auto i = static_cast<Eigen::Index>(j);
  const double h = s_[j + 1] - s_[j], l = s_[j + 1] - s, r = s - s_[j];
  if (dyds)
    *dyds = (-m[i] * l * l + m[i + 1] * r * r) / (2.0 * h) - (y[i] / h - m[i] * h / 6.0) +
            (y[i + 1] / h - m[i + 1] * h / 6.0);
  return (m[i] * l * l * l + m[i + 1] * r * r * r) / (6.0 * h) + (y[i] / h - m[i] * h / 6.0) * l +
         (y[i + 1] / h - m[i + 1] * h / 6.0) * r;
}

double ModalBackbone::operator()(double amplitude) const {
  const Eigen::Map<const Eigen::VectorXd> y(y_.data(), static_cast<Eigen::Index>(y_.size()));
  return evaluate(std::log(amplitude), y, m_, nullptr);
}

double ModalBackbone::slope(double amplitude) const {
  const Eigen::Map<const Eigen::VectorXd> y(y_.data(), static_cast<Eigen::Index>(y_.size()));
  double dyds = 0.0;
  evaluate(std::log(amplitude), y, m_, &dyds);
  return dyds / amplitude;
}

Eigen::VectorXd ModalBackbone::weights(double amplitude) const {
  const auto n = static_cast<Eigen::Index>(y_.size());
  Eigen::VectorXd w(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, i);
    w[i] = evaluate(std::log(amplitude), e, second_ * e, nullptr);
  }
  return w;
}

std::pair<double, double> ModalBackbone::range(double lo, double hi, int samples) const {
  double mn = (*this)(lo), mx = mn;
  for (int k = 1; k <= samples; ++k) {
    const double v = (*this)(lo * std::pow(hi / lo, static_cast<double>(k) / samples));
    mn = std::min(mn, v), mx = std::max(mx, v);
  }
  return {mn, mx};
}

}  // namespace bb
