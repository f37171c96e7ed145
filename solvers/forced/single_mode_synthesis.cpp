#include "forced/single_mode_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "common/constants.hpp"

namespace bb {
namespace {

// D = w0^2 - w^2 + 2 i z w0 w at amplitude a, with its partials in w0 and z and their rates in a.
struct Dynamic {
  double re = 0.0, im = 0.0, abs = 0.0;
  double w0 = 0.0, z = 0.0, w = 0.0;
  double dw0_da = 0.0, dz_da = 0.0;
  double dabs_dw0() const { return (re * 2.0 * w0 + im * 2.0 * z * w) / abs; }
  double dabs_dz() const { return im * 2.0 * w0 * w / abs; }
  // phase of x to F is -arg D; its partials
  double dphase_dw0() const { return -(re * 2.0 * z * w - im * 2.0 * w0) / (abs * abs); }
  double dphase_dz() const { return -(re * 2.0 * w0 * w) / (abs * abs); }
};

Dynamic dynamic(const NonlinearMode& mode, double a, double f_exc_hz) {
  Dynamic d;
  d.w0 = kTwoPi * mode.frequency_hz(a);
  d.z = mode.damping_ratio(a);
  d.w = kTwoPi * f_exc_hz;
  d.re = d.w0 * d.w0 - d.w * d.w;
  d.im = 2.0 * d.z * d.w0 * d.w;
  d.abs = std::hypot(d.re, d.im);
  d.dw0_da = kTwoPi * mode.frequency_hz.slope(a);
  d.dz_da = mode.damping_ratio.slope(a);
  return d;
}

// d(m a |D|)/da along the backbone.
double force_rate(const NonlinearMode& mode, double a, const Dynamic& d) {
  return mode.mass * (d.abs + a * (d.dabs_dw0() * d.dw0_da + d.dabs_dz() * d.dz_da));
}

// Partials (a held) of |D| and of the phase per parameter, and of the force m a |D|.
void partials(const NonlinearMode& mode, double a, const Dynamic& d, Eigen::VectorXd& dabs, Eigen::VectorXd& dphase) {
  const Eigen::VectorXd wf = mode.frequency_hz.weights(a), wz = mode.damping_ratio.weights(a);
  const Eigen::Index nf = wf.size(), nz = wz.size();
  dabs = Eigen::VectorXd::Zero(mode.parameters());
  dphase = Eigen::VectorXd::Zero(mode.parameters());
  dabs.head(nf) = d.dabs_dw0() * kTwoPi * wf;
  dphase.head(nf) = d.dphase_dw0() * kTwoPi * wf;
  dabs.segment(nf, nz) = d.dabs_dz() * wz;
  dphase.segment(nf, nz) = d.dphase_dz() * wz;
}

void require_positive_damping(const NonlinearMode& mode) {
  const auto& a = mode.damping_ratio.amplitudes();
  if (mode.damping_ratio.range(a.front(), a.back()).first <= 0.0)
    throw std::invalid_argument("the damping ratio must be positive along the whole backbone");
}

}  // namespace

ModalPoint held_response(const NonlinearMode& mode, double amplitude, double f_exc_hz) {
  const Dynamic d = dynamic(mode, amplitude, f_exc_hz);
  ModalPoint p;
  p.amplitude = amplitude;
  p.force = mode.mass * amplitude * d.abs;
  p.phase = -std::atan2(d.im, d.re);
  p.stable = force_rate(mode, amplitude, d) > 0.0;
  Eigen::VectorXd dabs;
  partials(mode, amplitude, d, dabs, p.d_phase);
  p.d_force = mode.mass * amplitude * dabs;
  p.d_force[mode.parameters() - 1] = amplitude * d.abs;
  p.d_amplitude = Eigen::VectorXd::Zero(mode.parameters());
  return p;
}

BackboneBounds backbone_bounds(const NonlinearMode& mode) {
  require_positive_damping(mode);
  const auto& af = mode.frequency_hz.amplitudes();
  const auto& az = mode.damping_ratio.amplitudes();
  BackboneBounds b;
  b.a_lo = std::min(af.front(), az.front()), b.a_hi = std::max(af.back(), az.back());
  std::tie(b.f_lo, b.f_hi) = mode.frequency_hz.range(b.a_lo, b.a_hi);
  std::tie(b.z_lo, b.z_hi) = mode.damping_ratio.range(b.a_lo, b.a_hi);
  return b;
}

std::vector<double> amplitudes_at_force(const NonlinearMode& mode, double force, double f_exc_hz,
                                        const std::optional<BackboneBounds>& bounds) {
  if (!(force > 0.0) || !(f_exc_hz > 0.0)) throw std::invalid_argument("force and frequency must be positive");
  const BackboneBounds b = bounds ? *bounds : backbone_bounds(mode);
  // |D| lies between 2 z w0 w (its imaginary part) and w0^2 + w^2 + 2 z w0 w: so do the roots'
  // m a |D| = F, in a bracket where the residual changes sign at every root.
  const double w = kTwoPi * f_exc_hz, w_lo = kTwoPi * b.f_lo, w_hi = kTwoPi * b.f_hi;
  const double d_max = w_hi * w_hi + w * w + 2.0 * b.z_hi * w_hi * w, d_min = 2.0 * b.z_lo * w_lo * w;
  const double a_lo = 0.5 * force / (mode.mass * d_max), a_hi = 2.0 * force / (mode.mass * d_min);
  const auto residual = [&](double s) {
    const double a = std::exp(s);
    return std::log(mode.mass * a * dynamic(mode, a, f_exc_hz).abs / force);
  };
  // Sampled densely enough to separate the roots of a fold (the spline has no finer structure
  // than its knots), each sign change refined by bisection in log a.
  constexpr int kSamples = 400;
  const double s0 = std::log(a_lo), s1 = std::log(a_hi);
  std::vector<double> roots;
  double sp = s0, rp = residual(s0);
  for (int k = 1; k <= kSamples; ++k) {
    const double s = s0 + (s1 - s0) * k / kSamples, r = residual(s);
    if ((rp < 0.0) != (r < 0.0)) {
      double lo = sp, hi = s, rlo = rp;
      for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++it) {
        const double mid = 0.5 * (lo + hi), rm = residual(mid);
        if ((rm < 0.0) == (rlo < 0.0))
          lo = mid, rlo = rm;
        else
          hi = mid;
      }
      roots.push_back(std::exp(0.5 * (lo + hi)));
    }
    sp = s, rp = r;
  }
  return roots;
}

ModalPoint stepped_response(const NonlinearMode& mode, double force, double f_exc_hz,
                            std::optional<double> previous_amplitude, const std::optional<BackboneBounds>& bounds) {
  const std::vector<double> roots = amplitudes_at_force(mode, force, f_exc_hz, bounds);
  double a = 0.0, best = INFINITY;
  for (double r : roots) {
    if (!(force_rate(mode, r, dynamic(mode, r, f_exc_hz)) > 0.0)) continue;
    const double distance = previous_amplitude ? std::abs(std::log(r / *previous_amplitude)) : r;
    if (distance < best) best = distance, a = r;
  }
  if (!(a > 0.0)) a = roots.front();  // a root on the bracket's edge: the residual's sign alone
  ModalPoint p = held_response(mode, a, f_exc_hz);
  const Dynamic d = dynamic(mode, a, f_exc_hz);
  // F = m a |D(a, theta)| held: da/dtheta = -(dF/dtheta) / (dF/da); the phase moves with a too.
  const double rate = force_rate(mode, a, d);
  p.d_amplitude = -p.d_force / rate;
  const double dphase_da = d.dphase_dw0() * d.dw0_da + d.dphase_dz() * d.dz_da;
  p.d_phase += dphase_da * p.d_amplitude;
  p.d_force = Eigen::VectorXd::Zero(mode.parameters());
  p.force = force;
  p.d_amplitude_d_force = 1.0 / rate;
  p.d_phase_d_force = dphase_da / rate;
  return p;
}

}  // namespace bb
