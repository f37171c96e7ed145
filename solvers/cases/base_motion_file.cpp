#include "cases/base_motion_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <string>

#include "common/constants.hpp"
#include "identify/measured_data.hpp"

namespace bb {
namespace {

constexpr double kNoiseFloor = 1e-3;  // harmonics below it relative to the first are left out
constexpr double kSpacingTolerance = 1e-6;

}  // namespace

std::vector<BaseHarmonic> base_harmonics_from_file(TomlReader& block, const std::filesystem::path& file, int periods,
                                                   int highest_order, double& first_amplitude) {
  const MeasuredData data = read_measured_data(file, DataKind::acceleration_history);
  const Eigen::VectorXd& time = data.column("time");
  const Eigen::VectorXd& acceleration = data.column("acceleration");
  const Eigen::Index n = time.size();
  const Eigen::Index needed = 2 * static_cast<Eigen::Index>(periods) * highest_order + 1;
  if (n < needed)
    block.fail("file", fmt::format("{}: {} samples resolve no harmonic {} over {} period(s): give at least {}",
                                   file.string(), n, highest_order, periods, needed));
  const double dt = (time[n - 1] - time[0]) / static_cast<double>(n - 1);
  if (!(dt > 0.0)) block.fail("file", fmt::format("{}: times must increase", file.string()));
  for (Eigen::Index j = 1; j < n; ++j)
    if (std::abs(time[j] - time[j - 1] - dt) > kSpacingTolerance * dt)
      block.fail("file", fmt::format("{}: times must be uniformly spaced (step {:.9g} s, found {:.9g} s)",
                                     data.where(j), dt, time[j] - time[j - 1]));
  // Harmonic h of the period is DFT bin h * periods.
  const auto bin = [&](int h) {
    std::complex<double> c = 0.0;
    const double k = static_cast<double>(h) * periods;
    for (Eigen::Index j = 0; j < n; ++j)
      c += acceleration[j] * std::polar(1.0, -kTwoPi * k * static_cast<double>(j) / static_cast<double>(n));
    return 2.0 * c / static_cast<double>(n);
  };
  const std::complex<double> first = bin(1);
  const double peak = acceleration.cwiseAbs().maxCoeff();
  if (!(std::abs(first) > kNoiseFloor * peak))
    block.fail("file", fmt::format("{}: its first harmonic ({:.3g} m/s^2) is lost in the signal (peak {:.3g} m/s^2): "
                                   "is `periods` the number of periods the file holds?",
                                   file.string(), std::abs(first), peak));
  first_amplitude = std::abs(first);
  std::vector<BaseHarmonic> out{BaseHarmonic{}};
  for (int h = 2; h <= highest_order; ++h) {
    const std::complex<double> c = bin(h);
    const double ratio = std::abs(c) / std::abs(first);
    if (ratio < kNoiseFloor) continue;
    double phase = std::remainder(std::arg(c) - h * std::arg(first), kTwoPi);
    out.push_back({h, ratio, phase * kDegPerRad});
  }
  return out;
}

}  // namespace bb
