#include "forced/multi_mode_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <optional>
#include <stdexcept>

namespace bb {
namespace {

using Complex = std::complex<double>;

// Every mode's force-controlled point at `force`, from rest or from its previous amplitude.
std::vector<ModalPoint> mode_points(const std::vector<NonlinearMode>& modes, double force, double f_exc_hz,
                                    const std::vector<double>& previous, const std::vector<BackboneBounds>& bounds) {
  std::vector<ModalPoint> points;
  for (size_t k = 0; k < modes.size(); ++k) {
    const std::optional<double> from = previous.empty() ? std::nullopt : std::optional<double>(previous[k]);
    points.push_back(stepped_response(modes[k], force, f_exc_hz, from, bounds[k]));
  }
  return points;
}

Complex total(const std::vector<ModalPoint>& points) {
  Complex x = 0.0;
  for (const ModalPoint& p : points) x += std::polar(p.amplitude, p.phase);
  return x;
}

// The summed response and its sensitivities (the force held) from the modes' points.
MultiModePoint combine(const std::vector<NonlinearMode>& modes, const std::vector<ModalPoint>& points) {
  MultiModePoint out;
  const Complex x = total(points);
  out.amplitude = std::abs(x);
  out.phase = std::arg(x);
  const Eigen::Index n = multi_mode_parameters(modes);
  out.d_amplitude = Eigen::VectorXd::Zero(n), out.d_phase = Eigen::VectorXd::Zero(n);
  out.d_force = Eigen::VectorXd::Zero(n);
  const double norm = std::norm(x);
  Eigen::Index offset = 0;
  for (size_t k = 0; k < modes.size(); ++k) {
    const ModalPoint& p = points[k];
    const Complex xk = std::polar(p.amplitude, p.phase);
    for (Eigen::Index j = 0; j < modes[k].parameters(); ++j) {
      const Complex dx = std::conj(x) * xk * Complex(p.d_amplitude[j] / p.amplitude, p.d_phase[j]);
      out.d_amplitude[offset + j] = dx.real() / out.amplitude;
      out.d_phase[offset + j] = dx.imag() / norm;
    }
    offset += modes[k].parameters();
    out.stable = out.stable && p.stable;
    out.mode_amplitude.push_back(p.amplitude);
    out.force = p.force;
  }
  return out;
}

// The one-mode point as a MultiModePoint: the closed form, not a root find.
MultiModePoint single(const ModalPoint& p) {
  MultiModePoint out;
  out.amplitude = p.amplitude, out.phase = p.phase, out.force = p.force, out.stable = p.stable;
  out.mode_amplitude = {p.amplitude};
  out.d_amplitude = p.d_amplitude, out.d_phase = p.d_phase, out.d_force = p.d_force;
  return out;
}

// The smallest force in [lo, hi] (|x(lo)| < held <= |x(hi)|) where |x| reaches `held`: a scan in
// log F for the first crossing (|x(F)| need not be monotone), then bisection to round-off.
double smallest_holding_force(const std::function<double(double)>& amplitude, double held, double lo, double hi) {
  constexpr int kScan = 32;
  const double s0 = std::log(lo), s1 = std::log(hi);
  double a = s0, b = s1;
  for (int i = 1; i <= kScan; ++i) {
    const double s = s0 + (s1 - s0) * i / kScan;
    if (amplitude(std::exp(s)) >= held) {
      b = s;
      break;
    }
    a = s;
  }
  for (int it = 0; it < 200 && b - a > 1e-15 * std::max(1.0, std::abs(a)); ++it) {
    const double mid = 0.5 * (a + b);
    if (mid <= a || mid >= b) break;
    (amplitude(std::exp(mid)) >= held ? b : a) = mid;
  }
  // The end that reaches the amplitude nearer: both hold it to round-off unless a jump lies between.
  const double fa = std::exp(a), fb = std::exp(b);
  return std::abs(amplitude(fa) - held) < std::abs(amplitude(fb) - held) ? fa : fb;
}

}  // namespace

Eigen::Index multi_mode_parameters(const std::vector<NonlinearMode>& modes) {
  Eigen::Index n = 0;
  for (const NonlinearMode& m : modes) n += m.parameters();
  return n;
}

std::vector<BackboneBounds> multi_mode_bounds(const std::vector<NonlinearMode>& modes) {
  std::vector<BackboneBounds> bounds;
  for (const NonlinearMode& m : modes) bounds.push_back(backbone_bounds(m));
  return bounds;
}

MultiModePoint multi_mode_stepped(const std::vector<NonlinearMode>& modes, double force, double f_exc_hz,
                                  const std::vector<double>& previous, const std::vector<BackboneBounds>& bounds) {
  return combine(modes, mode_points(modes, force, f_exc_hz, previous, bounds));
}

MultiModePoint multi_mode_held(const std::vector<NonlinearMode>& modes, double amplitude, double f_exc_hz,
                               const std::vector<BackboneBounds>& bounds) {
  if (modes.size() == 1) return single(held_response(modes.front(), amplitude, f_exc_hz));
  // Each mode alone would need F_k: the sum of N responses reaches the amplitude at no less than
  // min F_k / N in the linear limit; above, it may need more than any F_k (near an antiresonance).
  double f_min = INFINITY, f_max = 0.0;
  for (const NonlinearMode& m : modes) {
    const double f = held_response(m, amplitude, f_exc_hz).force;
    f_min = std::min(f_min, f), f_max = std::max(f_max, f);
  }
  const auto reached = [&](double force) { return std::abs(total(mode_points(modes, force, f_exc_hz, {}, bounds))); };
  double lo = 0.5 * f_min / static_cast<double>(modes.size()), hi = 2.0 * f_max;
  for (int i = 0; i < 60 && reached(lo) >= amplitude; ++i) lo *= 0.5;
  int doublings = 0;
  for (; doublings < 100 && reached(hi) < amplitude; ++doublings) hi *= 2.0;
  if (doublings == 100)
    throw std::invalid_argument("no force holds the amplitude: the modes' responses cancel at this frequency");
  const double force = smallest_holding_force(reached, amplitude, lo, hi);
  const std::vector<ModalPoint> points = mode_points(modes, force, f_exc_hz, {}, bounds);
  MultiModePoint out = combine(modes, points);
  out.force = force;
  out.holds = std::abs(out.amplitude - amplitude) <= 1e-9 * amplitude;
  // d x/dF along each mode's branch; then F moves with the parameters to keep |x| held.
  const Complex x = total(points);
  Complex dx_dforce = 0.0;
  for (const ModalPoint& p : points)
    dx_dforce += std::polar(p.amplitude, p.phase) * Complex(p.d_amplitude_d_force / p.amplitude, p.d_phase_d_force);
  const Complex rate = std::conj(x) * dx_dforce;
  const double damp_dforce = rate.real() / out.amplitude, dphase_dforce = rate.imag() / std::norm(x);
  out.d_force = -out.d_amplitude / damp_dforce;
  out.d_phase += dphase_dforce * out.d_force;
  out.d_amplitude.setZero();
  return out;
}

}  // namespace bb
