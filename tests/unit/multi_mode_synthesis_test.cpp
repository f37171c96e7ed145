// A few uncoupled nonlinear modes at one driven point (forced/multi_mode_synthesis.hpp): two modes
// far apart are each single mode near its own resonance, one mode is the single-mode synthesis,
// constant backbones give the sum of two linear receptances, a held point's force gives back the
// held amplitude when force-controlled, and the sensitivities equal central differences. Units: SI.
#include "forced/multi_mode_synthesis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <numbers>

#include "common/constants.hpp"

namespace multi_mode_synthesis_test {  // named: the unity build joins this file with others
namespace {

using bb::kTwoPi;
using bb::ModalBackbone;
using bb::ModalPoint;
using bb::MultiModePoint;
using bb::NonlinearMode;
using Modes = std::vector<NonlinearMode>;

// Two modes of a jointed structure 4 % apart, the second lighter and with other knots.
Modes close_modes() {
  const std::vector<double> a = {2e-5, 5e-5, 1e-4, 2e-4, 3.2e-4};
  return {{ModalBackbone(a, {78.60, 78.45, 78.34, 78.60, 78.66}),
           ModalBackbone(a, {0.0016, 0.0022, 0.0035, 0.0055, 0.0070}), 1.2},
          {ModalBackbone({3e-5, 1e-4, 3e-4}, {81.9, 81.6, 81.5}), ModalBackbone({3e-5, 3e-4}, {0.0020, 0.0045}), 0.7}};
}

// Three decades apart in frequency, 1000x in mass, damping 1e-4 to 2e-4: near either resonance
// the other mode adds at most 2 z m_light/m_heavy ~ 4e-7 of the resonant response. The frequencies
// move by 1e-5, a tenth of the damping, so that neither folds (one root at every force).
Modes far_modes() {
  const std::vector<double> a = {1e-5, 1e-4, 1e-3};
  return {{ModalBackbone(a, {10.0, 9.9999, 9.99995}), ModalBackbone(a, {1e-4, 2e-4, 1.5e-4}), 1e3},
          {ModalBackbone(a, {1.0e4, 0.99999e4, 0.999985e4}), ModalBackbone(a, {1.2e-4, 1.8e-4, 2e-4}), 1.0}};
}

TEST(MultiModeSynthesis, ModesFarApartAreEachSingleModeNearItsOwnResonance) {
  const Modes modes = far_modes();
  const auto bounds = bb::multi_mode_bounds(modes);
  for (size_t k = 0; k < 2; ++k) {
    const NonlinearMode& m = modes[k];
    const double a = 1e-4, f0 = m.frequency_hz(a);
    const double force = 2.0 * m.mass * m.damping_ratio(a) * std::pow(kTwoPi * f0, 2) * a;
    for (double r : {0.99995, 1.0, 1.00005}) {  // inside the half-power band, 1 +- z
      const MultiModePoint p = bb::multi_mode_stepped(modes, force, r * f0, {}, bounds);
      const ModalPoint q = bb::stepped_response(m, force, r * f0, std::nullopt);
      EXPECT_NEAR(p.amplitude, q.amplitude, 1e-6 * q.amplitude) << "mode " << k << " at " << r;
      EXPECT_NEAR(p.phase, q.phase, 1e-6) << "mode " << k << " at " << r;
      const MultiModePoint h = bb::multi_mode_held(modes, a, r * f0, bounds);
      const ModalPoint g = bb::held_response(m, a, r * f0);
      EXPECT_NEAR(h.force, g.force, 1e-6 * g.force) << "mode " << k << " at " << r;
      EXPECT_NEAR(h.phase, g.phase, 1e-6) << "mode " << k << " at " << r;
    }
  }
}

void expect_same(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double scale) {
  ASSERT_EQ(a.size(), b.size());
  for (Eigen::Index j = 0; j < a.size(); ++j) EXPECT_NEAR(a[j], b[j], 1e-12 * scale) << "parameter " << j;
}

TEST(MultiModeSynthesis, OneModeIsTheSingleModeSynthesis) {
  const Modes one = {close_modes().front()};
  const auto bounds = bb::multi_mode_bounds(one);
  std::vector<double> previous;
  std::optional<double> single;
  for (double f : {77.5, 78.0, 78.3, 78.45, 78.6, 79.0, 80.0}) {
    const MultiModePoint p = bb::multi_mode_stepped(one, 0.3, f, previous, bounds);
    const ModalPoint q = bb::stepped_response(one.front(), 0.3, f, single);
    previous = p.mode_amplitude, single = q.amplitude;
    EXPECT_NEAR(p.amplitude, q.amplitude, 1e-12 * q.amplitude);
    EXPECT_NEAR(p.phase, q.phase, 1e-12);
    EXPECT_EQ(p.stable, q.stable);
    expect_same(p.d_amplitude, q.d_amplitude, q.amplitude);
    expect_same(p.d_phase, q.d_phase, 1.0);
    const MultiModePoint h = bb::multi_mode_held(one, 8e-5, f, bounds);
    const ModalPoint g = bb::held_response(one.front(), 8e-5, f);
    EXPECT_NEAR(h.force, g.force, 1e-12 * g.force);
    EXPECT_NEAR(h.phase, g.phase, 1e-12);
    expect_same(h.d_force, g.d_force, g.force);
    expect_same(h.d_phase, g.d_phase, 1.0);
  }
}

TEST(MultiModeSynthesis, ConstantBackbonesGiveTheSumOfTwoLinearReceptances) {
  const Modes modes = {{ModalBackbone({1e-4}, {50.0}), ModalBackbone({1e-4}, {0.02}), 2.5},
                       {ModalBackbone({1e-4}, {56.0}), ModalBackbone({1e-4}, {0.03}), 1.5}};
  const auto bounds = bb::multi_mode_bounds(modes);
  const auto receptance = [&](double f) {
    const double w = kTwoPi * f;
    std::complex<double> h = 0.0;
    for (const auto& [f0, z, m] : {std::tuple{50.0, 0.02, 2.5}, std::tuple{56.0, 0.03, 1.5}}) {
      const double w0 = kTwoPi * f0;
      h += 1.0 / (m * std::complex<double>(w0 * w0 - w * w, 2.0 * z * w0 * w));
    }
    return h;
  };
  for (double f : {20.0, 49.0, 50.0, 53.0, 54.5, 56.0, 60.0, 150.0}) {
    const std::complex<double> x = 3.0 * receptance(f);
    const MultiModePoint p = bb::multi_mode_stepped(modes, 3.0, f, {}, bounds);
    EXPECT_NEAR(p.amplitude, std::abs(x), 1e-12 * std::abs(x)) << f;
    EXPECT_NEAR(p.phase, std::arg(x), 1e-12) << f;
    const MultiModePoint h = bb::multi_mode_held(modes, 1e-4, f, bounds);
    EXPECT_NEAR(h.force, 1e-4 / std::abs(receptance(f)), 1e-12 * h.force) << f;
    EXPECT_NEAR(h.phase, std::arg(receptance(f)), 1e-12) << f;
    EXPECT_TRUE(h.holds);
  }
}

TEST(MultiModeSynthesis, HeldForceForceControlledGivesBackTheHeldAmplitude) {
  const Modes modes = close_modes();
  const auto bounds = bb::multi_mode_bounds(modes);
  for (double held : {3e-5, 1e-4, 2.5e-4})
    for (double f : {77.0, 78.3, 78.5, 80.0, 81.0, 81.6, 83.0}) {
      const MultiModePoint h = bb::multi_mode_held(modes, held, f, bounds);
      ASSERT_TRUE(h.holds) << held << " at " << f;
      const MultiModePoint p = bb::multi_mode_stepped(modes, h.force, f, {}, bounds);
      EXPECT_NEAR(p.amplitude, held, 1e-10 * held) << held << " at " << f;
      EXPECT_NEAR(p.phase, h.phase, 1e-9) << held << " at " << f;
    }
}

// The modes' parameters in turn (each: frequency knots, damping knots, mass), scaled by `factor`.
Modes moved(Modes modes, Eigen::Index j, double factor) {
  for (NonlinearMode& m : modes) {
    if (j >= m.parameters()) {
      j -= m.parameters();
      continue;
    }
    const auto k = static_cast<size_t>(j), nf = m.frequency_hz.knots(), nz = m.damping_ratio.knots();
    if (k < nf)
      m.frequency_hz.set_value(k, m.frequency_hz.values()[k] * factor);
    else if (k < nf + nz)
      m.damping_ratio.set_value(k - nf, m.damping_ratio.values()[k - nf] * factor);
    else
      m.mass *= factor;
    break;
  }
  return modes;
}

double value_of(const Modes& modes, Eigen::Index j) {
  const Modes twice = moved(modes, j, 2.0);  // the one value that changed, doubled
  for (size_t k = 0; k < modes.size(); ++k) {
    if (twice[k].mass != modes[k].mass) return modes[k].mass;
    for (size_t i = 0; i < modes[k].frequency_hz.knots(); ++i)
      if (twice[k].frequency_hz.values()[i] != modes[k].frequency_hz.values()[i])
        return modes[k].frequency_hz.values()[i];
    for (size_t i = 0; i < modes[k].damping_ratio.knots(); ++i)
      if (twice[k].damping_ratio.values()[i] != modes[k].damping_ratio.values()[i])
        return modes[k].damping_ratio.values()[i];
  }
  return NAN;
}

void expect_derivatives(const Modes& modes, const std::function<MultiModePoint(const Modes&)>& solve) {
  const MultiModePoint p = solve(modes);
  ASSERT_EQ(p.d_amplitude.size(), bb::multi_mode_parameters(modes));
  for (Eigen::Index j = 0; j < bb::multi_mode_parameters(modes); ++j) {
    const double value = value_of(modes, j), h = 1e-6;
    const MultiModePoint plus = solve(moved(modes, j, 1.0 + h)), minus = solve(moved(modes, j, 1.0 - h));
    // Differences of step h carry roundoff of about eps / h of the value: 1e-6 relative to the larger.
    const auto check = [&](double exact, double fp, double fm, double scale, const char* what) {
      EXPECT_NEAR(exact * value, (fp - fm) / (2.0 * h), 1e-6 * std::max(std::abs(exact * value), scale))
          << what << ", parameter " << j;
    };
    check(p.d_amplitude[j], plus.amplitude, minus.amplitude, p.amplitude, "amplitude");
    check(p.d_phase[j], plus.phase, minus.phase, 1.0, "phase");
    check(p.d_force[j], plus.force, minus.force, p.force, "force");
  }
}

TEST(MultiModeSynthesis, SensitivitiesEqualCentralDifferences) {
  const Modes modes = close_modes();
  for (double f : {78.0, 78.4, 79.5, 81.6, 82.5}) {
    expect_derivatives(modes,
                       [&](const Modes& m) { return bb::multi_mode_held(m, 8e-5, f, bb::multi_mode_bounds(m)); });
    expect_derivatives(modes,
                       [&](const Modes& m) { return bb::multi_mode_stepped(m, 0.3, f, {}, bb::multi_mode_bounds(m)); });
  }
}

// A hardening fold: an amplitude on its middle (unstable) branch is held by no force on the
// branches reached from rest; the point is the jump's force (the lower branch's largest), flagged.
TEST(MultiModeSynthesis, AnAmplitudeOnlyAFoldJumpsPastIsTheJumpsForceAndFlagged) {
  const Modes modes = {{ModalBackbone({1e-4, 1e-3, 1e-2}, {10.0, 11.0, 14.0}), ModalBackbone({1e-4}, {0.005}), 1.0},
                       {ModalBackbone({1e-4}, {1000.0}), ModalBackbone({1e-4}, {0.01}), 1.0}};
  const double f = 12.5;
  // The lower branch's largest force (where the up-stepping force jumps) and the middle branch's
  // smallest, sampled densely.
  double jump = 0.0, a_jump = 0.0, dip = INFINITY;
  for (double s = std::log(1e-5); s < std::log(1e-1); s += 1e-4) {
    const double force = bb::held_response(modes[0], std::exp(s), f).force;
    if (jump > 0.0 && force > dip) break;
    if (a_jump > 0.0 && force < jump)
      dip = std::min(dip, force);
    else
      jump = force, a_jump = std::exp(s);
  }
  ASSERT_LT(dip, 0.9 * jump);
  const std::vector<double> roots = bb::amplitudes_at_force(modes[0], 0.5 * (jump + dip), f);
  ASSERT_EQ(roots.size(), 3u);
  const double held = roots[1];  // the middle branch
  ASSERT_GT(held, a_jump);
  const MultiModePoint p = bb::multi_mode_held(modes, held, f, bb::multi_mode_bounds(modes));
  EXPECT_FALSE(p.holds);
  // To the resolution at which the single-mode solver tells a fold's two roots apart (400 samples
  // of its bracket in log a): the lower branch ends a little early, never late (here 5e-5 early).
  EXPECT_NEAR(p.force, jump, 1e-3 * jump);
  EXPECT_LE(p.force, jump);
  EXPECT_GT(std::abs(std::log(p.amplitude / held)), 0.01);  // what it reaches is not the held amplitude
}

}  // namespace
}  // namespace multi_mode_synthesis_test
