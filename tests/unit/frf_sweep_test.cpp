// Frequency sweeps and peak finding (frf/sweep): the thesis's 0.01 Hz grid, adaptive refinement
// around close lightly damped peaks, and the accuracy of interpolated peaks against the closed
// form of a damped oscillator and against natural frequencies. Units: SI, frequencies in Hz.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/constants.hpp"
#include "frf/receptance.hpp"
#include "frf/sweep.hpp"

namespace bb {
namespace {

using Complex = std::complex<double>;

// One response, modal superposition at a frequency in Hz.
ResponseAt modal_response(const ModalReceptance& modal) {
  return [modal](double f) -> Eigen::VectorXcd { return modal.at(kTwoPi * f).col(0); };
}

// Single mode at fn [Hz] of a k = 1e6 N/m oscillator: the receptance 1 / (k - m w^2 + i c w).
ModalReceptance one_dof(double fn, double zeta) {
  const double k = 1.0e6, wn = kTwoPi * fn, m = k / (wn * wn);
  return {.omega = Eigen::VectorXd::Constant(1, wn),
          .zeta = Eigen::VectorXd::Constant(1, zeta),
          .shapes_out = Eigen::MatrixXd::Constant(1, 1, 1.0 / std::sqrt(m)),
          .shapes_in = Eigen::MatrixXd::Constant(1, 1, 1.0 / std::sqrt(m)),
          .residual = {}};
}

Eigen::VectorXd amplitudes(const Sweep& s, Eigen::Index output = 0) { return s.response.col(output).cwiseAbs(); }

// The maximum of |H| in [lo, hi] by golden-section search (|H| is unimodal there).
double true_peak(const ResponseAt& response, double lo, double hi) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  auto amp = [&](double f) { return std::abs(response(f)[0]); };
  double a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  while (b - a > 1e-10) {
    if (amp(c) > amp(d))
      b = d;
    else
      a = c;
    c = b - g * (b - a);
    d = a + g * (b - a);
  }
  return 0.5 * (a + b);
}

TEST(SweepGrid, ThesisBandAtOneHundredthHertzHas2001PointsWithExactEnds) {
  const std::vector<double> f = fixed_grid(170.0, 190.0, 0.01);
  ASSERT_EQ(f.size(), 2001u);
  EXPECT_EQ(f.front(), 170.0);
  EXPECT_EQ(f.back(), 190.0);
  for (size_t k = 0; k + 1 < f.size(); ++k) {
    EXPECT_EQ(f[k], 170.0 + static_cast<double>(k) * 0.01);  // no accumulated drift
    EXPECT_LT(f[k], f[k + 1]);
  }
  EXPECT_EQ(fixed_grid(0.0, 5000.0, 0.01).size(), 500001u);
}

TEST(SweepGrid, LastPointStaysAtOrBelowFMaxWhenTheStepDoesNotDivide) {
  EXPECT_EQ(fixed_grid(0.0, 1.0, 0.3), (std::vector<double>{0.0, 0.3, 0.6, 0.3 * 3}));
  EXPECT_EQ(fixed_grid(0.0, 1.0, 0.4), (std::vector<double>{0.0, 0.4, 0.8}));
  const std::vector<double> snapped = fixed_grid(0.0, 1.00001, 0.1);  // within step / 1000 of f_max
  EXPECT_EQ(snapped.size(), 11u);
  EXPECT_EQ(snapped.back(), 1.00001);
  EXPECT_EQ(fixed_grid(10.0, 10.5, 2.0), (std::vector<double>{10.0}));
}

TEST(SweepGrid, RejectsEmptyRangesAndBadSteps) {
  EXPECT_THROW(fixed_grid(190.0, 170.0, 0.01), std::invalid_argument);
  EXPECT_THROW(fixed_grid(170.0, 170.0, 0.01), std::invalid_argument);
  EXPECT_THROW(fixed_grid(170.0, 190.0, 0.0), std::invalid_argument);
  EXPECT_THROW(fixed_grid(170.0, 190.0, -0.01), std::invalid_argument);
  EXPECT_THROW(fixed_grid(0.0, 5000.0, 1e-9), std::invalid_argument);  // 5e12 points
  EXPECT_THROW(fixed_grid(0.0, NAN, 1.0), std::invalid_argument);
}

TEST(FrfSweep, SweepHasOneRowPerFrequencyAndAFixedNumberOfOutputs) {
  const ResponseAt two = [](double f) -> Eigen::VectorXcd {
    return Eigen::Vector2cd(Complex(f, 0.0), Complex(0.0, 2 * f));
  };
  const Sweep s = sweep(two, {1.0, 2.0, 5.0});
  ASSERT_EQ(s.response.rows(), 3);
  ASSERT_EQ(s.response.cols(), 2);
  EXPECT_EQ(s.response(2, 0), Complex(5.0, 0.0));
  EXPECT_EQ(s.response(1, 1), Complex(0.0, 4.0));
  const ResponseAt changing = [](double f) -> Eigen::VectorXcd { return Eigen::VectorXcd::Zero(f < 2.0 ? 1 : 2); };
  EXPECT_THROW(sweep(changing, {1.0, 2.0}), std::runtime_error);
}

// |H| of a single mode peaks at wn sqrt(1 - 2 zeta^2) with 1 / (2 zeta k sqrt(1 - zeta^2)).
TEST(FrfSweep, OneDofPeakMatchesTheClosedFormFarBelowTheStep) {
  const double fn = 180.0, k = 1.0e6;
  for (double zeta : {0.01, 0.001}) {
    const double f_peak = fn * std::sqrt(1.0 - 2.0 * zeta * zeta);
    const double a_peak = 1.0 / (2.0 * zeta * k * std::sqrt(1.0 - zeta * zeta));
    // 0.01 Hz (the thesis) and 1 Hz, wider than the half-power band of zeta = 0.001 (0.36 Hz).
    for (double step : {0.01, 1.0}) {
      const Sweep s = sweep(modal_response(one_dof(fn, zeta)), fixed_grid(170.0 + 0.37 * step, 190.0, step));
      const std::vector<Peak> peaks = find_peaks(s.frequency_hz, amplitudes(s));
      ASSERT_EQ(peaks.size(), 1u) << "zeta " << zeta << " step " << step;
      EXPECT_LT(std::abs(peaks[0].frequency_hz - f_peak), 1e-4 * step) << "zeta " << zeta << " step " << step;
      EXPECT_LT(std::abs(peaks[0].amplitude / a_peak - 1.0), 1e-8) << "zeta " << zeta << " step " << step;
      EXPECT_LT(std::abs(s.frequency_hz[static_cast<size_t>(peaks[0].index)] - f_peak), step);
    }
  }
}

// Near mode r, |H| = |R_r / (w_r^2 - w^2 + 2 i zeta w_r w) + background from the other modes|: the
// background shifts the maximum off w_r by O(zeta^2) w_r, and makes 1 / |H|^2 no longer exactly
// quadratic in f^2, so interpolation errors shrink like step^2 instead of vanishing.
TEST(FrfSweep, ZeroToFiveKilohertzPeaksSitOnTheNaturalFrequencies) {
  // Four masses in a chain, modes at 579, 1261, 1558 and 2425 Hz, driving point at mass 4 (which
  // every mode moves; mass 1 hardly takes part in the fourth).
  const std::vector<double> m = {0.2, 0.3, 0.25, 0.1}, springs = {8.0e6, 6.0e6, 9.0e6, 7.0e6, 1.5e7};
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(4, 4), mass = Eigen::MatrixXd::Zero(4, 4);
  for (Eigen::Index i = 0; i < 4; ++i) {
    mass(i, i) = m[static_cast<size_t>(i)];
    stiffness(i, i) = springs[static_cast<size_t>(i)] + springs[static_cast<size_t>(i) + 1];
    if (i < 3) stiffness(i, i + 1) = stiffness(i + 1, i) = -springs[static_cast<size_t>(i) + 1];
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(stiffness, mass);
  const Eigen::VectorXd omega = es.eigenvalues().cwiseSqrt(), fn = omega / kTwoPi;
  ASSERT_LT(fn[3], 5000.0);

  double offset[2][4] = {};  // |true peak - f_r| per zeta and mode
  const double zetas[2] = {0.01, 0.001};
  for (size_t z = 0; z < 2; ++z) {
    const double zeta = zetas[z];
    const ModalReceptance modal{.omega = omega,
                                .zeta = Eigen::VectorXd::Constant(4, zeta),
                                .shapes_out = es.eigenvectors().bottomRows(1),
                                .shapes_in = es.eigenvectors().bottomRows(1),
                                .residual = {}};
    const ResponseAt response = modal_response(modal);
    // Measured worst errors against the exact maximum: 2.5e-2 Hz at 1 Hz, 2.4e-6 Hz at 0.01 Hz.
    for (auto [step, tolerance] : {std::pair{1.0, 0.05}, std::pair{0.01, 1e-5}}) {
      const Sweep s = sweep(response, fixed_grid(0.0, 5000.0, step));
      const std::vector<Peak> peaks = find_peaks(s.frequency_hz, amplitudes(s));
      ASSERT_EQ(peaks.size(), 4u) << "zeta " << zeta << " step " << step;
      for (size_t r = 0; r < 4; ++r) {
        const double f_r = fn[static_cast<Eigen::Index>(r)];
        const double exact = true_peak(response, f_r * (1 - zeta), f_r * (1 + zeta));
        EXPECT_LT(std::abs(peaks[r].frequency_hz - exact), tolerance)
            << "zeta " << zeta << " step " << step << " mode " << r + 1;
        EXPECT_LT(std::abs(peaks[r].frequency_hz - f_r), 0.5 * zeta * f_r) << "inside the half-power band";
        offset[z][r] = std::abs(exact - f_r);
      }
    }
  }
  // Ten times less damping, a hundred times smaller shift (measured 82 to 100).
  for (size_t r = 0; r < 4; ++r) {
    EXPECT_GT(offset[0][r] / offset[1][r], 50.0) << "mode " << r + 1;
    EXPECT_LT(offset[0][r] / offset[1][r], 150.0) << "mode " << r + 1;
  }
}

TEST(FrfSweep, AdaptiveSweepResolvesClosePeaksThatACoarseGridMisses) {
  // Two modes 1 % apart with zeta = 0.001: half-power bands of 0.35 Hz, 1.75 Hz apart.
  const double f1 = 174.85, f2 = 1.01 * f1, zeta = 0.001, min_step = 0.01;
  const ModalReceptance pair{.omega = kTwoPi * Eigen::Vector2d(f1, f2),
                             .zeta = Eigen::VectorXd::Constant(2, zeta),
                             .shapes_out = Eigen::RowVector2d(1.0, 1.0),
                             .shapes_in = Eigen::RowVector2d(1.0, 0.8),
                             .residual = {}};
  const ResponseAt response = modal_response(pair);
  const double exact[2] = {true_peak(response, f1 - 0.5, f1 + 0.5), true_peak(response, f2 - 0.5, f2 + 0.5)};
  // On the 2 Hz grid the two modes interfere within the three points of a parabola: whatever
  // maxima it shows lie more than a half-power band away from one of the true peaks.
  const Sweep coarse = sweep(response, fixed_grid(170.0, 190.0, 2.0));
  const std::vector<Peak> coarse_peaks = find_peaks(coarse.frequency_hz, amplitudes(coarse));
  double worst = 0.0;
  for (double f : exact) {
    double nearest = INFINITY;
    for (const Peak& p : coarse_peaks) nearest = std::min(nearest, std::abs(p.frequency_hz - f));
    worst = std::max(worst, nearest);
  }
  EXPECT_GT(worst, 2 * zeta * f1);

  const Sweep fine = adaptive_sweep(response, 170.0, 190.0, 2.0, min_step);
  for (size_t i = 0; i + 1 < fine.frequency_hz.size(); ++i) ASSERT_LT(fine.frequency_hz[i], fine.frequency_hz[i + 1]);
  EXPECT_EQ(fine.frequency_hz.front(), 170.0);
  EXPECT_EQ(fine.frequency_hz.back(), 190.0);
  const std::vector<Peak> peaks = find_peaks(fine.frequency_hz, amplitudes(fine));
  ASSERT_EQ(peaks.size(), 2u);
  for (size_t r = 0; r < 2; ++r) {
    EXPECT_LT(std::abs(peaks[r].frequency_hz - exact[r]), 0.1 * min_step) << "peak " << r + 1;
    const auto i = static_cast<size_t>(peaks[r].index);
    EXPECT_LE(fine.frequency_hz[i + 1] - fine.frequency_hz[i - 1], 2 * min_step) << "peak " << r + 1;
  }
  // A uniform grid at min_step needs 2001 points.
  EXPECT_LT(fine.frequency_hz.size(), 2001u / 10);
}

TEST(FrfSweep, AdaptiveSweepStopsRunawayRefinement) {
  // Alternating samples: every other point is a maximum, at every level of refinement.
  const ResponseAt jagged = [](double f) -> Eigen::VectorXcd {
    return Eigen::VectorXcd::Constant(1, 2.0 + std::sin(std::numbers::pi * f + 0.3));
  };
  EXPECT_THROW(adaptive_sweep(jagged, 0.0, 4.0e5, 1.0, 1e-6), std::runtime_error);
  EXPECT_THROW(adaptive_sweep(jagged, 0.0, 10.0, 1.0, 0.0), std::invalid_argument);
}

TEST(PeakFinding, EndMaximaAndPlateausAreNotPeaks) {
  const std::vector<double> f = {1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_TRUE(find_peaks(f, Eigen::Vector<double, 5>(5, 4, 3, 2, 1), 1.0).empty());
  EXPECT_TRUE(find_peaks(f, Eigen::Vector<double, 5>(1, 2, 3, 4, 5), 1.0).empty());
  EXPECT_TRUE(find_peaks(f, Eigen::Vector<double, 5>(1, 2, 2, 1, 0.5), 1.0).empty());
  EXPECT_TRUE(find_peaks(f, Eigen::Vector<double, 5>::Zero(), 1.0).empty());
  const std::vector<Peak> one = find_peaks(f, Eigen::Vector<double, 5>(5, 1, 3, 1, 5), 1.0);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].index, 2);
}

TEST(PeakFinding, ProminenceDropsRippleOnAFlank) {
  std::vector<double> f(11);
  for (size_t i = 0; i < f.size(); ++i) f[i] = static_cast<double>(i);
  Eigen::VectorXd a(11);
  a << 1, 2, 3, 3.01, 3.005, 4, 6, 10, 6, 4, 2;  // the 3.01 ripple stands 0.17 % above its dip
  const std::vector<Peak> filtered = find_peaks(f, a);
  ASSERT_EQ(filtered.size(), 1u);
  EXPECT_EQ(filtered[0].index, 7);
  EXPECT_EQ(find_peaks(f, a, 1.0).size(), 2u);
  // A 5 % bump between two dips passes the default 1 % but not a 10 % prominence.
  Eigen::VectorXd bump(11);
  bump << 1, 2, 2.1, 2, 4, 6, 10, 6, 4, 3, 2;
  EXPECT_EQ(find_peaks(f, bump).size(), 2u);
  EXPECT_EQ(find_peaks(f, bump, 1.1).size(), 1u);
  EXPECT_THROW(find_peaks(f, a, 0.5), std::invalid_argument);
}

TEST(PeakFinding, InterpolationWorksOnNonUniformGrids) {
  // A single mode sampled at irregular frequencies: the vertex is exact.
  const double fn = 250.0, zeta = 0.002;
  const ModalReceptance mode = one_dof(fn, zeta);
  const std::vector<double> f = {240.0, 246.3, 249.2, 249.9, 250.6, 253.0, 262.0};
  Eigen::VectorXd a(7);
  for (Eigen::Index i = 0; i < 7; ++i) a[i] = std::abs(mode.at(kTwoPi * f[static_cast<size_t>(i)])(0, 0));
  const std::vector<Peak> peaks = find_peaks(f, a);
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_NEAR(peaks[0].frequency_hz, fn * std::sqrt(1 - 2 * zeta * zeta), 1e-9);
  EXPECT_NEAR(peaks[0].amplitude, 1.0 / (2 * zeta * 1.0e6 * std::sqrt(1 - zeta * zeta)), 1e-9 * peaks[0].amplitude);
  // With a zero neighbour the parabola goes through the amplitudes: y = 1 - (f - 1.2)^2.
  const std::vector<Peak> plain = find_peaks({0.2, 1.0, 2.0}, Eigen::Vector3d(0.0, 0.96, 0.36));
  ASSERT_EQ(plain.size(), 1u);
  EXPECT_NEAR(plain[0].frequency_hz, 1.2, 1e-12);
  EXPECT_NEAR(plain[0].amplitude, 1.0, 1e-12);
  EXPECT_THROW(find_peaks({1.0, 3.0, 2.0}, Eigen::Vector3d(1, 2, 1)), std::invalid_argument);
  EXPECT_THROW(find_peaks({1.0, 2.0}, Eigen::Vector3d(1, 2, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace bb
