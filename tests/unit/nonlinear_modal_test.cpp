// The nonlinear modal model: its backbone spline (knots interpolated, C1, constant beyond, fourth
// order, linear in the knot values), single-nonlinear-mode synthesis (the linear oscillator's
// receptance when the backbone is flat, the force balance at resonance, every root of a fold,
// jumps of up and down sweeps, exact sensitivities against central differences), and the backbone
// point read from a response-controlled curve. Units: SI.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <numbers>

#include "common/constants.hpp"
#include "forced/backbone_extraction.hpp"
#include "forced/modal_backbone.hpp"
#include "forced/single_mode_synthesis.hpp"

namespace bb {
namespace {

// A joint's decoupled backbone: the frequency moves by under 0.4 % (down, then up), the damping
// grows 4.4-fold (issue 68's rig).
NonlinearMode joint_mode() {
  const std::vector<double> a = {2e-5, 5e-5, 1e-4, 2e-4, 3.2e-4};
  return {ModalBackbone(a, {78.60, 78.45, 78.34, 78.60, 78.66}), ModalBackbone(a, {0.0016, 0.0022, 0.0035, 0.0055, 0.0070}),
          1.2};
}

TEST(ModalBackbone, InterpolatesItsKnotsIsFlatAtItsEndsAndConstantBeyond) {
  const ModalBackbone b({1e-5, 3e-5, 1e-4, 4e-4}, {2.0, 3.5, 1.0, 4.0});
  for (size_t i = 0; i < b.knots(); ++i) EXPECT_NEAR(b(b.amplitudes()[i]), b.values()[i], 1e-14);
  EXPECT_EQ(b(1e-9), 2.0);
  EXPECT_EQ(b(1.0), 4.0);
  EXPECT_NEAR(b.slope(1e-5 * (1.0 + 1e-9)), 0.0, 1e-3);  // zero slope at the end knots: C1 into the constants
  EXPECT_NEAR(b.slope(4e-4 * (1.0 - 1e-9)), 0.0, 1e-1);
}

TEST(ModalBackbone, SlopeIsTheDerivativeAndContinuousAcrossKnots) {
  const ModalBackbone b({1e-5, 3e-5, 1e-4, 4e-4}, {2.0, 3.5, 1.0, 4.0});
  for (double a : {1.5e-5, 3e-5, 6e-5, 1e-4, 2e-4}) {
    const double h = a * 1e-6;
    EXPECT_NEAR(b.slope(a), (b(a + h) - b(a - h)) / (2.0 * h), 1e-6 * std::abs(b.slope(a)) + 1e-3);
  }
  const double knot = 1e-4;
  EXPECT_NEAR(b.slope(knot * (1.0 - 1e-10)), b.slope(knot * (1.0 + 1e-10)), 1e-6 * std::abs(b.slope(knot)));
}

TEST(ModalBackbone, WeightsReproduceEveryChoiceOfValuesAndSumToOne) {
  ModalBackbone b({1e-5, 3e-5, 1e-4, 4e-4}, {2.0, 3.5, 1.0, 4.0});
  for (double a : {5e-6, 1e-5, 2e-5, 7e-5, 3e-4, 1e-3}) {
    const Eigen::VectorXd w = b.weights(a);
    EXPECT_NEAR(w.sum(), 1.0, 1e-13);
    double sum = 0.0;
    for (size_t i = 0; i < b.knots(); ++i) sum += w[static_cast<Eigen::Index>(i)] * b.values()[i];
    EXPECT_NEAR(sum, b(a), 1e-13);
  }
  b.set_value(2, -7.0);
  const double a = 7e-5;
  const Eigen::VectorXd w = b.weights(a);
  EXPECT_NEAR(w.dot(Eigen::Map<const Eigen::VectorXd>(b.values().data(), 4)), b(a), 1e-13);
}

// cos(s) on [0, pi] has zero slope at both ends, as the clamped spline: its error falls as h^4.
TEST(ModalBackbone, ConvergesAtFourthOrderOnASmoothCurve) {
  const auto error = [](int knots) {
    std::vector<double> a, y;
    for (int i = 0; i < knots; ++i) {
      const double s = std::numbers::pi * i / (knots - 1);
      a.push_back(std::exp(s)), y.push_back(std::cos(s));
    }
    const ModalBackbone b(a, y);
    double worst = 0.0;
    for (int k = 0; k <= 1000; ++k) {
      const double s = std::numbers::pi * k / 1000.0;
      worst = std::max(worst, std::abs(b(std::exp(s)) - std::cos(s)));
    }
    return worst;
  };
  const double order = std::log2(error(9) / error(17));
  EXPECT_GT(order, 3.7);
  EXPECT_LT(order, 4.3);
}

TEST(ModalBackbone, RefusesKnotsThatDoNotIncrease) {
  EXPECT_THROW(ModalBackbone({1e-5, 1e-5}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(ModalBackbone({1e-5, -1e-4}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(ModalBackbone({1e-5}, {1.0, 2.0}), std::invalid_argument);
}

TEST(SingleModeSynthesis, FlatBackboneIsTheLinearOscillatorsReceptance) {
  const NonlinearMode mode{ModalBackbone({1e-4}, {50.0}), ModalBackbone({1e-4}, {0.02}), 2.5};
  const double w0 = kTwoPi * 50.0;
  for (double f : {20.0, 45.0, 50.0, 51.0, 120.0}) {
    const double w = kTwoPi * f;
    const std::complex<double> receptance = 1.0 / (2.5 * std::complex<double>(w0 * w0 - w * w, 2.0 * 0.02 * w0 * w));
    const ModalPoint p = stepped_response(mode, 3.0, f, std::nullopt);
    EXPECT_NEAR(p.amplitude, 3.0 * std::abs(receptance), 1e-12 * p.amplitude);
    EXPECT_NEAR(p.phase, std::arg(receptance), 1e-12);
    EXPECT_TRUE(p.stable);
  }
}

TEST(SingleModeSynthesis, HeldForceAtResonanceIsTheModalDampingForce) {
  const NonlinearMode mode = joint_mode();
  for (double a : {3e-5, 1e-4, 2.5e-4}) {
    const double f0 = mode.frequency_hz(a), w0 = kTwoPi * f0;
    const ModalPoint p = held_response(mode, a, f0);
    EXPECT_NEAR(p.force, 2.0 * mode.mass * mode.damping_ratio(a) * w0 * w0 * a, 1e-12 * p.force);
    EXPECT_NEAR(p.phase, -std::numbers::pi / 2.0, 1e-12);
  }
}

// A strongly hardening backbone folds the force-controlled curve: three amplitudes hold the same
// force inside the fold, each a root, the middle one unstable; an up sweep stays on the upper
// branch beyond where a down sweep jumps up.
TEST(SingleModeSynthesis, HardeningFoldHasThreeRootsAndSweepsJumpApart) {
  const NonlinearMode mode{ModalBackbone({1e-4, 1e-3, 1e-2}, {10.0, 11.0, 14.0}), ModalBackbone({1e-4}, {0.005}), 1.0};
  const double force = 2.0 * mode.mass * 0.005 * std::pow(kTwoPi * 14.0, 2) * 5e-3;
  const std::vector<double> roots = amplitudes_at_force(mode, force, 12.5);
  ASSERT_EQ(roots.size(), 3u);
  for (double a : roots) EXPECT_NEAR(held_response(mode, a, 12.5).force, force, 1e-9 * force);
  EXPECT_TRUE(held_response(mode, roots[0], 12.5).stable);
  EXPECT_FALSE(held_response(mode, roots[1], 12.5).stable);
  EXPECT_TRUE(held_response(mode, roots[2], 12.5).stable);
  std::optional<double> up, down;
  std::vector<double> up_a, down_a;
  std::vector<double> grid;
  for (double f = 9.0; f <= 15.0 + 1e-9; f += 0.05) grid.push_back(f);
  for (double f : grid) up_a.push_back((up = stepped_response(mode, force, f, up).amplitude).value());
  for (auto it = grid.rbegin(); it != grid.rend(); ++it)
    down_a.insert(down_a.begin(), (down = stepped_response(mode, force, *it, down).amplitude).value());
  size_t differ = 0;
  for (size_t k = 0; k < grid.size(); ++k) differ += std::abs(std::log(up_a[k] / down_a[k])) > 0.5;
  EXPECT_GT(differ, 5u);  // the hysteresis band of the jumps
  EXPECT_NEAR(up_a.front(), down_a.front(), 1e-12 * up_a.front());
  EXPECT_NEAR(up_a.back(), down_a.back(), 1e-12 * up_a.back());
}

void expect_derivatives(const NonlinearMode& mode, const std::function<ModalPoint(const NonlinearMode&)>& solve) {
  const ModalPoint p = solve(mode);
  for (Eigen::Index j = 0; j < mode.parameters(); ++j) {
    const auto moved = [&](double factor) {
      NonlinearMode m = mode;
      const size_t nf = m.frequency_hz.knots(), nz = m.damping_ratio.knots(), k = static_cast<size_t>(j);
      if (k < nf)
        m.frequency_hz.set_value(k, m.frequency_hz.values()[k] * factor);
      else if (k < nf + nz)
        m.damping_ratio.set_value(k - nf, m.damping_ratio.values()[k - nf] * factor);
      else
        m.mass *= factor;
      return solve(m);
    };
    const double value = j < static_cast<Eigen::Index>(mode.frequency_hz.knots())
                             ? mode.frequency_hz.values()[static_cast<size_t>(j)]
                         : j + 1 < mode.parameters()
                             ? mode.damping_ratio.values()[static_cast<size_t>(j) - mode.frequency_hz.knots()]
                             : mode.mass;
    const double h = 1e-6;
    const ModalPoint plus = moved(1.0 + h), minus = moved(1.0 - h);
    // Differences of step h carry roundoff of about eps / h of the value: 1e-6 relative to the larger.
    const auto check = [&](double exact, double fp, double fm, double scale) {
      EXPECT_NEAR(exact * value, (fp - fm) / (2.0 * h), 1e-6 * std::max(std::abs(exact * value), scale))
          << "parameter " << j;
    };
    check(p.d_amplitude[j], plus.amplitude, minus.amplitude, p.amplitude);
    check(p.d_phase[j], plus.phase, minus.phase, 1.0);
    check(p.d_force[j], plus.force, minus.force, p.force);
  }
}

TEST(SingleModeSynthesis, SensitivitiesEqualCentralDifferences) {
  const NonlinearMode mode = joint_mode();
  for (double f : {78.0, 78.4, 78.5, 79.0}) {
    expect_derivatives(mode, [&](const NonlinearMode& m) { return held_response(m, 8e-5, f); });
    expect_derivatives(mode, [&](const NonlinearMode& m) { return stepped_response(m, 0.3, f, std::nullopt); });
  }
}

TEST(BackboneExtraction, RecoversTheModeFromItsOwnHeldDisplacementCurve) {
  const NonlinearMode mode = joint_mode();
  const double a = 1.5e-4;
  std::vector<double> f, amp, force;
  for (double x = 77.0; x <= 80.0 + 1e-9; x += 0.05)
    f.push_back(x), amp.push_back(a), force.push_back(held_response(mode, a, x).force);
  const BackbonePoint p = extract_backbone_point(f, amp, force);
  EXPECT_NEAR(p.frequency_hz, mode.frequency_hz(a), 1e-9 * p.frequency_hz);
  EXPECT_NEAR(p.damping_ratio, mode.damping_ratio(a), 1e-7 * p.damping_ratio);
  EXPECT_NEAR(p.mass_kg, mode.mass, 1e-8);
  EXPECT_NEAR(p.amplitude_m, a, 1e-15);
  EXPECT_LT(p.rms_relative, 1e-9);
}

// Acceleration held: the displacement moves by 8 % over the band, and the backbone with it; the
// point read is the backbone's where the curve crosses resonance, to a fraction of the damping.
TEST(BackboneExtraction, HeldAccelerationCurveGivesTheBackboneAtItsResonance) {
  const NonlinearMode mode = joint_mode();
  std::vector<double> f, amp, force;
  for (double x = 77.0; x <= 80.0 + 1e-9; x += 0.05) {
    const double a = 20.0 / std::pow(kTwoPi * x, 2);
    f.push_back(x), amp.push_back(a), force.push_back(held_response(mode, a, x).force);
  }
  const BackbonePoint p = extract_backbone_point(f, amp, force);
  EXPECT_NEAR(p.frequency_hz, mode.frequency_hz(p.amplitude_m), 0.01);
  EXPECT_NEAR(p.damping_ratio, mode.damping_ratio(p.amplitude_m), 0.05 * p.damping_ratio);
}

TEST(BackboneExtraction, RefusesACurveWithoutResonance) {
  const NonlinearMode mode = joint_mode();
  std::vector<double> f, amp, force;
  for (double x = 60.0; x <= 65.0; x += 0.5) f.push_back(x), amp.push_back(1e-4), force.push_back(held_response(mode, 1e-4, x).force);
  EXPECT_THROW(extract_backbone_point(f, amp, force), std::invalid_argument);
}

}  // namespace
}  // namespace bb
