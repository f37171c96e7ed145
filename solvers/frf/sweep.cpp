#include "frf/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace bb {
namespace {

// Evaluates the response and insists on one fixed number of outputs.
struct Evaluator {
  const ResponseAt& response;
  Eigen::Index outputs = -1;

  Eigen::VectorXcd operator()(double f) {
    Eigen::VectorXcd v = response(f);
    if (outputs < 0) outputs = v.size();
    if (v.size() != outputs)
      throw std::runtime_error(
          fmt::format("sweep: the response has {} outputs at {} Hz, {} before", v.size(), f, outputs));
    return v;
  }
};

Sweep to_sweep(std::vector<double> frequency_hz, const std::vector<Eigen::VectorXcd>& values, Eigen::Index outputs) {
  Sweep s;
  s.response.resize(static_cast<Eigen::Index>(values.size()), std::max<Eigen::Index>(outputs, 0));
  for (size_t i = 0; i < values.size(); ++i) s.response.row(static_cast<Eigen::Index>(i)) = values[i].transpose();
  s.frequency_hz = std::move(frequency_hz);
  return s;
}

// Interior or end sample that no neighbour exceeds and at least one neighbour lies below.
bool is_sampled_maximum(const std::vector<double>& a, size_t i) {
  const size_t n = a.size();
  const bool left_ok = i == 0 || a[i] >= a[i - 1], right_ok = i + 1 == n || a[i] >= a[i + 1];
  const bool rises = (i > 0 && a[i] > a[i - 1]) || (i + 1 < n && a[i] > a[i + 1]);
  return left_ok && right_ok && rises;
}

// For each i, the lowest amplitude from i back to (not including) the nearest strictly higher
// sample, or to the start. One pass with a stack of decreasing amplitudes: O(n).
std::vector<double> minima_back_to_higher(const std::vector<double>& a) {
  std::vector<double> low(a.size());
  std::vector<size_t> stack;
  for (size_t i = 0; i < a.size(); ++i) {
    double m = a[i];
    while (!stack.empty() && a[stack.back()] <= a[i]) {
      m = std::min(m, low[stack.back()]);
      stack.pop_back();
    }
    low[i] = m;
    stack.push_back(i);
  }
  return low;
}

struct Vertex {
  double x = 0.0, y = 0.0;
};

// Vertex of the parabola through (x0, y0), (x1, y1), (x2, y2), x0 < x1 < x2, in coordinates
// centred on x1 to keep the differences accurate.
Vertex parabola_vertex(double x0, double x1, double x2, double y0, double y1, double y2) {
  const double h0 = x0 - x1, h2 = x2 - x1;
  const double d0 = (y0 - y1) / h0, d2 = (y2 - y1) / h2;
  const double c = (d2 - d0) / (h2 - h0), b = d0 - c * h0;
  return {x1 - b / (2.0 * c), y1 - b * b / (4.0 * c)};
}

}  // namespace

std::vector<double> fixed_grid(double f_min, double f_max, double step) {
  if (!std::isfinite(f_min) || !std::isfinite(f_max) || !std::isfinite(step) || !(f_min < f_max) || !(step > 0.0))
    throw std::invalid_argument(
        fmt::format("fixed_grid: need f_min < f_max and step > 0, got {} .. {} step {}", f_min, f_max, step));
  const double steps = std::round((f_max - f_min) / step);
  if (!(steps < static_cast<double>(kMaxGridPoints)))
    throw std::invalid_argument(fmt::format("fixed_grid: {} .. {} Hz at step {} would take more than {} points", f_min,
                                            f_max, step, kMaxGridPoints));
  auto n = static_cast<size_t>(steps);
  const bool lands_on_end = n > 0 && std::abs(f_min + steps * step - f_max) <= step / 1000.0;
  if (!lands_on_end && n > 0 && f_min + steps * step > f_max) --n;
  std::vector<double> grid(n + 1);
  for (size_t k = 0; k <= n; ++k) grid[k] = f_min + static_cast<double>(k) * step;
  if (lands_on_end) grid[n] = f_max;
  return grid;
}

Sweep sweep(const ResponseAt& response, const std::vector<double>& frequency_hz) {
  Evaluator evaluate{response};
  std::vector<Eigen::VectorXcd> values;
  values.reserve(frequency_hz.size());
  for (double f : frequency_hz) values.push_back(evaluate(f));
  return to_sweep(frequency_hz, values, evaluate.outputs);
}

Sweep adaptive_sweep(const ResponseAt& response, double f_min, double f_max, double coarse_step, double min_step) {
  if (!(min_step > 0.0) || !std::isfinite(min_step))
    throw std::invalid_argument(fmt::format("adaptive_sweep: min_step must be finite and > 0, got {}", min_step));
  Evaluator evaluate{response};
  std::vector<double> f = fixed_grid(f_min, f_max, coarse_step);
  std::vector<Eigen::VectorXcd> values;
  values.reserve(f.size());
  for (double x : f) values.push_back(evaluate(x));

  size_t added = 0;
  std::vector<double> amplitude;
  for (;;) {
    const size_t n = f.size();
    std::vector<char> split(n > 0 ? n - 1 : 0, 0);
    for (Eigen::Index o = 0; o < evaluate.outputs; ++o) {
      amplitude.resize(n);
      for (size_t i = 0; i < n; ++i) amplitude[i] = std::abs(values[i][o]);
      for (size_t i = 0; i < n; ++i) {
        if (!is_sampled_maximum(amplitude, i)) continue;
        if (i > 0) split[i - 1] = 1;
        if (i + 1 < n) split[i] = 1;
      }
    }
    std::vector<double> new_f;
    std::vector<Eigen::VectorXcd> new_values;
    new_f.reserve(n);
    new_values.reserve(n);
    size_t added_now = 0;
    for (size_t i = 0; i < n; ++i) {
      new_f.push_back(f[i]);
      new_values.push_back(std::move(values[i]));
      if (i + 1 == n || !split[i] || !(f[i + 1] - f[i] > min_step)) continue;
      const double mid = 0.5 * (f[i] + f[i + 1]);
      if (!(mid > f[i] && mid < f[i + 1])) continue;  // no double between them
      if (++added > kMaxRefinementPoints)
        throw std::runtime_error(
            fmt::format("adaptive_sweep: refinement of {} .. {} Hz needs more than {} extra points", f_min, f_max,
                        kMaxRefinementPoints));
      new_f.push_back(mid);
      new_values.push_back(evaluate(mid));
      ++added_now;
    }
    f = std::move(new_f);
    values = std::move(new_values);
    if (added_now == 0) break;
  }
  return to_sweep(std::move(f), values, evaluate.outputs);
}

std::vector<Peak> find_peaks(const std::vector<double>& frequency_hz, const Eigen::VectorXd& amplitude,
                             double min_prominence) {
  const size_t n = frequency_hz.size();
  if (static_cast<size_t>(amplitude.size()) != n)
    throw std::invalid_argument(fmt::format("find_peaks: {} frequencies, {} amplitudes", n, amplitude.size()));
  for (size_t i = 1; i < n; ++i)
    if (!(frequency_hz[i] > frequency_hz[i - 1]))
      throw std::invalid_argument(fmt::format("find_peaks: frequencies must ascend strictly (point {})", i));
  if (!(min_prominence >= 1.0)) throw std::invalid_argument("find_peaks: min_prominence must be >= 1");

  const std::vector<double> a(amplitude.data(), amplitude.data() + n);
  const std::vector<double> left_low = minima_back_to_higher(a);
  const std::vector<double> reversed(a.rbegin(), a.rend());
  const std::vector<double> right_low_reversed = minima_back_to_higher(reversed);

  std::vector<Peak> peaks;
  for (size_t i = 1; i + 1 < n; ++i) {
    if (!(a[i] > a[i - 1] && a[i] > a[i + 1])) continue;
    const double key = std::max(left_low[i], right_low_reversed[n - 1 - i]);
    if (!(a[i] >= min_prominence * key)) continue;

    const double f0 = frequency_hz[i - 1], f1 = frequency_hz[i], f2 = frequency_hz[i + 1];
    Peak p{.frequency_hz = f1, .amplitude = a[i], .index = static_cast<int>(i)};
    bool fitted = false;
    if (f0 >= 0.0 && a[i - 1] > 0.0 && a[i + 1] > 0.0) {
      // 1 / |H|^2 against f^2: exact for one mode, see the header.
      const Vertex v = parabola_vertex(f0 * f0, f1 * f1, f2 * f2, 1.0 / (a[i - 1] * a[i - 1]), 1.0 / (a[i] * a[i]),
                                       1.0 / (a[i + 1] * a[i + 1]));
      if (v.y > 0.0 && std::isfinite(v.y) && v.x >= f0 * f0 && v.x <= f2 * f2) {
        p.frequency_hz = std::sqrt(v.x);
        p.amplitude = 1.0 / std::sqrt(v.y);
        fitted = true;
      }
    }
    if (!fitted) {
      const Vertex v = parabola_vertex(f0, f1, f2, a[i - 1], a[i], a[i + 1]);
      p.frequency_hz = v.x;
      p.amplitude = v.y;
    }
    peaks.push_back(p);
  }
  return peaks;
}

Peak largest_sample(const std::vector<double>& frequency_hz, const Eigen::VectorXd& values) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (values.size() == 0 || !values.allFinite()) return {nan, nan, -1};
  Eigen::Index k = 0;
  values.maxCoeff(&k);
  const auto i = static_cast<size_t>(k);
  Peak p{.frequency_hz = frequency_hz[i], .amplitude = values[k], .index = static_cast<int>(k)};
  if (k == 0 || k + 1 == values.size() || !(values[k - 1] - 2 * values[k] + values[k + 1] < 0)) return p;
  const Vertex v = parabola_vertex(frequency_hz[i - 1], frequency_hz[i], frequency_hz[i + 1], values[k - 1], values[k],
                                   values[k + 1]);
  p.frequency_hz = v.x;
  p.amplitude = v.y;
  return p;
}

GoldenSearch golden_section_maximum(const std::function<std::optional<double>(double)>& value, double a, double b,
                                    int max_iterations, double relative_width) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double c = b - g * (b - a), d = a + g * (b - a);
  std::optional<double> vc = value(c), vd = value(d);
  GoldenSearch out;
  for (int it = 0; it < max_iterations && vc && vd && b - a > relative_width * b; ++it) {
    out.compared.insert(out.compared.end(), {c, d});
    if (*vc > *vd) {
      b = d, d = c, vd = vc, c = b - g * (b - a), vc = value(c);
    } else {
      a = c, c = d, vc = vd, d = a + g * (b - a), vd = value(d);
    }
  }
  out.a = a;
  out.b = b;
  return out;
}

}  // namespace bb
