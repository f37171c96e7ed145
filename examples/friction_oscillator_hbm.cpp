// A mass on a spring, rubbing on the ground through a Jenkins contact (a spring kt in series with a
// Coulomb slider, slip force mu n0), driven by a harmonic force: its frequency response by
// harmonic balance, and the stability of the peak by Hill's method.
//
// Far below the slip force the slider sticks and the oscillator is linear with stiffness k + kt;
// here the force is large enough for the slider to slip over part of each cycle near resonance, so
// the peak sits between the free (k) and the stuck (k + kt) resonances, bounded by friction damping.
#include <bladebench/hbm/fixed_frequency.hpp>
#include <bladebench/hbm/harmonic_balance.hpp>
#include <bladebench/hbm/hill_stability.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

int main() {
  const double mass = 1.0, k = 1e6, c = 10.0;  // [kg, N/m, N s/m]: 159.2 Hz free, 0.5 % damping
  bb::friction::FrictionModel model;
  model.mass = Eigen::MatrixXd::Constant(1, 1, mass);
  model.damping = Eigen::MatrixXd::Constant(1, 1, c);
  model.stiffness = Eigen::MatrixXd::Constant(1, 1, k);
  // One contact: normal stiffness kn and preload n0 [N], tangential stiffness kt, friction mu.
  model.contacts.push_back({.point = {.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 30.0},
                            .tangential = Eigen::RowVectorXd::Ones(1),
                            .normal = Eigen::RowVectorXd::Zero(1)});
  model.harmonic_load = Eigen::VectorXcd::Constant(1, 5.0);  // 5 N against a 9 N slip force

  // Five harmonics; the contact forces by alternating frequency-time with the default samples.
  const bb::hbm::HarmonicBalance system(model, {.harmonics = 5});
  const double free_hz = std::sqrt(k / mass) / (2 * std::numbers::pi);
  const double stuck_hz = std::sqrt((k + 1e6) / mass) / (2 * std::numbers::pi);

  // The sweep: each frequency starts from the previous solution (natural continuation).
  std::optional<Eigen::VectorXd> previous;
  double peak_hz = 0.0, peak_amplitude = 0.0;
  Eigen::VectorXd peak_x;
  bool all_converged = true;
  for (double f = 140.0; f <= 240.0; f += 1.0) {
    const double omega = 2 * std::numbers::pi * f;
    const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(system, omega, previous);
    all_converged = all_converged && s.converged;
    if (!s.converged) {
      std::printf("%.1f Hz: %s\n", f, s.failure.c_str());
      continue;
    }
    previous = s.x;
    const double amplitude = std::hypot(s.x[1], s.x[2]);  // first harmonic: x = [c0, a1, b1, a2, b2, ...]
    if (amplitude > peak_amplitude) {
      peak_amplitude = amplitude;
      peak_hz = f;
      peak_x = s.x;
    }
    if (static_cast<int>(f) % 10 == 0) std::printf("%6.1f Hz  %.4e m\n", f, amplitude);
  }
  const bb::hbm::HillStability stability = bb::hbm::hill_stability(system, peak_x, 2 * std::numbers::pi * peak_hz);
  std::printf("peak: %.1f Hz, %.4e m (free %.1f Hz, stuck %.1f Hz); Hill: %s, largest Re %.3g 1/s\n", peak_hz,
              peak_amplitude, free_hz, stuck_hz, stability.stable ? "stable" : "not stable", stability.max_real);
  const bool between = peak_hz > free_hz && peak_hz < stuck_hz;
  return all_converged && between && stability.ok && stability.stable ? 0 : 1;
}
