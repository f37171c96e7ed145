// The largest excursion of a harmonic-balance response over a period: a closed form (offset plus a
// sine) and a seven-harmonic signal against a dense brute-force sampling of the period.
#include "forced/hbm_response.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace bb {
namespace {

TEST(LargestExcursion, AnOffsetSineReachesOffsetPlusAmplitude) {
  Eigen::RowVectorXd c(3);
  c << -0.1, 0.0, 1.0;  // -0.1 + sin theta: |x| largest at theta = 3 pi / 2
  EXPECT_NEAR(largest_excursion(c), 1.1, 1e-12);
}

TEST(LargestExcursion, SevenHarmonicsAgreeWithADenseSamplingOfThePeriod) {
  const int harmonics = 7;
  Eigen::RowVectorXd c(2 * harmonics + 1);
  for (int j = 0; j < c.size(); ++j) c[j] = std::sin(1.7 * j + 0.3) / (1.0 + j);  // spread over every harmonic
  double brute = 0.0;
  const int n = 2'000'000;
  for (int k = 0; k < n; ++k) {
    const double theta = 2 * std::numbers::pi * k / n;
    double v = c[0];
    for (int h = 1; h <= harmonics; ++h) v += c[2 * h - 1] * std::cos(h * theta) + c[2 * h] * std::sin(h * theta);
    brute = std::max(brute, std::abs(v));
  }
  // The dense sampling misses the maximum by at most |x''| (pi / n)^2 / 2 ~ 1e-11.
  EXPECT_NEAR(largest_excursion(c), brute, 1e-9);
  EXPECT_GE(largest_excursion(c), brute - 1e-12);
}

}  // namespace
}  // namespace bb
