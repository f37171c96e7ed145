// Frequency sweeps of a linear response and peak finding.
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace bb {

// Complex responses (one per output) at a frequency [Hz].
using ResponseAt = std::function<Eigen::VectorXcd(double frequency_hz)>;

struct Sweep {
  std::vector<double> frequency_hz;  // ascending
  Eigen::MatrixXcd response;         // one row per frequency, one column per output
};

// f_min, f_min + step, ..., f_max (the last point lands on f_max within step / 1000). Throws
// std::invalid_argument unless f_min < f_max and step > 0.
std::vector<double> fixed_grid(double f_min, double f_max, double step);

Sweep sweep(const ResponseAt& response, const std::vector<double>& frequency_hz);

// Starts on fixed_grid(f_min, f_max, coarse_step) and bisects the intervals on both sides of every
// local maximum of any output's amplitude until they are narrower than min_step.
Sweep adaptive_sweep(const ResponseAt& response, double f_min, double f_max, double coarse_step, double min_step);

struct Peak {
  double frequency_hz = 0.0;  // interpolated between grid points
  double amplitude = 0.0;     // interpolated
  int index = 0;              // grid point of the sampled maximum
};

// Interior local maxima of `amplitude` sampled at `frequency_hz`, each refined by the parabola
// through the maximum and its two neighbours. A maximum counts only if it stands above the lower
// of the minima on its two sides by the factor `min_prominence` (1.0 keeps every maximum).
std::vector<Peak> find_peaks(const std::vector<double>& frequency_hz, const Eigen::VectorXd& amplitude,
                             double min_prominence = 1.01);

}  // namespace bb
