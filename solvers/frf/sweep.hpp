// Frequency sweeps of a linear response and peak finding.
#pragma once
#include <Eigen/Dense>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace bb {

// Complex responses (one per output) at a frequency [Hz].
using ResponseAt = std::function<Eigen::VectorXcd(double frequency_hz)>;

struct Sweep {
  std::vector<double> frequency_hz;  // ascending
  Eigen::MatrixXcd response;         // one row per frequency, one column per output
};

// Guards against a step in the wrong unit (fixed_grid) and runaway refinement (adaptive_sweep).
inline constexpr std::size_t kMaxGridPoints = 10'000'000;
inline constexpr std::size_t kMaxRefinementPoints = 1'000'000;

// f_min, f_min + step, ..., f_max (the last point lands on f_max within step / 1000). Throws
// std::invalid_argument unless f_min < f_max and step > 0. Point k is f_min + k step (no
// accumulated drift); the last point is f_max exactly when it falls within step / 1000 of it,
// else the largest f_min + k step <= f_max. More than kMaxGridPoints also throws.
std::vector<double> fixed_grid(double f_min, double f_max, double step);

// Throws std::runtime_error when the response changes its number of outputs along the sweep.
Sweep sweep(const ResponseAt& response, const std::vector<double>& frequency_hz);

// Starts on fixed_grid(f_min, f_max, coarse_step) and bisects the intervals on both sides of every
// local maximum of any output's amplitude until they are narrower than min_step. A maximum at
// either end counts (its one interval is refined): a peak may hide between the last two points.
// New maxima revealed by the refinement are refined in turn. Throws std::invalid_argument unless
// min_step > 0, std::runtime_error when more than kMaxRefinementPoints would be added.
Sweep adaptive_sweep(const ResponseAt& response, double f_min, double f_max, double coarse_step, double min_step);

struct Peak {
  double frequency_hz = 0.0;  // interpolated between grid points
  double amplitude = 0.0;     // interpolated
  int index = 0;              // grid point of the sampled maximum
};

// Interior strict local maxima of `amplitude` (linear magnitudes, not dB) sampled at ascending
// `frequency_hz` (any spacing); a plateau or a maximum at either end is not a peak. Each is refined
// by the parabola through the maximum and its two neighbours, fitted to 1 / amplitude^2 against
// frequency^2: for one mode |w_r^2 - w^2 + 2 i zeta w_r w|^2 is exactly quadratic in w^2, so an
// isolated lightly damped peak is located exactly even when the step exceeds its half-power
// bandwidth (a parabola on the amplitude itself is off by up to a fifth of the step there); other
// modes nearby bend that quadratic, and the error then shrinks like step^2. Where
// that fit does not apply (a neighbour <= 0, a frequency < 0) the parabola goes through the
// amplitudes. Prominence: on each side the lowest amplitude before a sample higher than the peak
// (or the end); a maximum counts only if it stands above the higher of these two minima by the
// factor `min_prominence` (>= 1; 1.0 keeps every maximum), so ripple on a flank is dropped.
// Throws std::invalid_argument on mismatched sizes, non-ascending frequencies or min_prominence < 1.
std::vector<Peak> find_peaks(const std::vector<double>& frequency_hz, const Eigen::VectorXd& amplitude,
                             double min_prominence = 1.01);

// The largest sample of `values` (any quantity at ascending `frequency_hz`), refined by the parabola
// through it and its neighbours when it is an interior maximum with negative curvature; NaN when
// `values` is empty or not finite.
Peak largest_sample(const std::vector<double>& frequency_hz, const Eigen::VectorXd& values);

// Golden-section search for the maximum of a unimodal function on [a, b]. `value(x)` returns its
// value, or nullopt where it cannot be evaluated, which ends the search. Ends after max_iterations
// or once b - a <= relative_width * b. `compared` lists the points whose values decided a step
// (the two interior points at the start of each iteration), in order: the caller's best estimate.
struct GoldenSearch {
  double a = 0.0, b = 0.0;  // the final bracket
  std::vector<double> compared;
};
GoldenSearch golden_section_maximum(const std::function<std::optional<double>(double)>& value, double a, double b,
                                    int max_iterations, double relative_width = 0.0);

}  // namespace bb
