// The harmonics of one force level: H raised until the truncation share or the change of the
// result meets the tolerance, the higher H of a peaks-scope grid sweep on windows around the peaks.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>

#include "common/power_law.hpp"
#include "forced/hbm_level.hpp"
#include "forced/hbm_level_system.hpp"
#include "frf/sweep.hpp"

namespace bb {

namespace {

using Eigen::Index;

bool increasing(const std::vector<double>& f) {
  return std::adjacent_find(f.begin(), f.end(), std::greater_equal<>()) == f.end();
}

// The largest relative change from `lower` to `higher` (two sweeps of one level at different H):
// each peak's frequency and component against the higher H's; with the path scope also each
// response's largest displacement along the curve, the lower path interpolated at the higher one's
// frequencies, on the scale of the higher curve's largest (a folding path: the peaks alone).
double result_change(const HbmSpec& spec, const HbmLevel& lower, const HbmLevel& higher) {
  double change = 0.0;
  const size_t n = std::min(lower.peaks.size(), higher.peaks.size());
  for (size_t k = 0; k < n; ++k) {
    change = std::max(change, relative_change(lower.peaks[k].frequency_hz, higher.peaks[k].frequency_hz));
    change = std::max(change, relative_change(lower.peaks[k].component, higher.peaks[k].component));
  }
  if (spec.harmonic_scope != HbmSpec::HarmonicScope::path || !increasing(lower.frequency_hz) ||
      !increasing(higher.frequency_hz) || lower.frequency_hz.size() < 2)
    return change;
  const std::vector<double>& fl = lower.frequency_hz;
  for (Index r = 0; r < higher.excursion.cols(); ++r) {
    const double scale = higher.excursion.col(r).maxCoeff();
    if (!(scale > 0.0)) continue;
    for (size_t i = 0; i < higher.frequency_hz.size(); ++i) {
      const double f = higher.frequency_hz[i];
      if (f < fl.front() || f > fl.back()) continue;
      const size_t j = std::min<size_t>(std::upper_bound(fl.begin(), fl.end(), f) - fl.begin(), fl.size() - 1);
      const double t = fl[j] > fl[j - 1] ? (f - fl[j - 1]) / (fl[j] - fl[j - 1]) : 1.0;
      const double e =
          (1 - t) * lower.excursion(static_cast<Index>(j - 1), r) + t * lower.excursion(static_cast<Index>(j), r);
      change = std::max(change, std::abs(e - higher.excursion(static_cast<Index>(i), r)) / scale);
    }
  }
  return change;
}

// The largest shift of a peak's frequency between two sweeps of a level [Hz].
double peak_shift_hz(const HbmLevel& a, const HbmLevel& b) {
  double shift = 0.0;
  for (size_t k = 0; k < std::min(a.peaks.size(), b.peaks.size()); ++k)
    shift = std::max(shift, std::abs(a.peaks[k].frequency_hz - b.peaks[k].frequency_hz));
  return shift;
}

// The grid windows of `half_width` steps either side of each peak, merged where they overlap or touch.
std::vector<GridWindow> windows_around(const std::vector<HbmPeak>& peaks, const std::vector<double>& grid,
                                       double step_hz, int half_width) {
  const int last = static_cast<int>(grid.size()) - 1;
  std::vector<GridWindow> windows;
  for (const HbmPeak& pk : peaks) {
    const int centre = std::clamp(static_cast<int>(std::lround((pk.frequency_hz - grid.front()) / step_hz)), 0, last);
    windows.push_back({std::max(centre - half_width, 0), std::min(centre + half_width, last)});
  }
  std::sort(windows.begin(), windows.end(), [](const GridWindow& a, const GridWindow& b) { return a.first < b.first; });
  std::vector<GridWindow> merged;
  for (const GridWindow& w : windows)
    if (!merged.empty() && w.first <= merged.back().last + 1)
      merged.back().last = std::max(merged.back().last, w.last);
    else
      merged.push_back(w);
  return merged;
}

// A peak within 1.5 grid steps of a window's edge inside the band, or outside every window: the
// maximum may lie beyond the window.
bool peak_at_inner_edge(const HbmLevel& level, const std::vector<GridWindow>& windows, const std::vector<double>& grid,
                        double step_hz) {
  const int last = static_cast<int>(grid.size()) - 1;
  for (const HbmPeak& pk : level.peaks) {
    const double f = pk.frequency_hz;
    const auto inside = std::find_if(windows.begin(), windows.end(), [&](const GridWindow& w) {
      return f >= grid[static_cast<size_t>(w.first)] - 0.5 * step_hz &&
             f <= grid[static_cast<size_t>(w.last)] + 0.5 * step_hz;
    });
    if (inside == windows.end()) return true;
    if ((inside->first > 0 && f < grid[static_cast<size_t>(inside->first)] + 1.5 * step_hz) ||
        (inside->last < last && f > grid[static_cast<size_t>(inside->last)] - 1.5 * step_hz))
      return true;
  }
  return false;
}

// The level at H on windows around `around`'s peaks: half-width three times the peaks' last shift
// in H, at least 16 grid steps, tripled while a peak lies at a window's edge. window_hz is the
// half-width kept (0 once the windows have grown to the whole band); the seconds of the narrower
// tries are added to the level's.
HbmLevel sweep_around_peaks(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics,
                            const HbmProgress& progress, const HbmLevel& around, double shift_hz, double& window_hz) {
  const double step = spec.sweep.step_hz;
  const std::vector<double> grid = fixed_grid(spec.sweep.f_min, spec.sweep.f_max, step);
  int half = std::max(16, static_cast<int>(std::ceil(3.0 * shift_hz / step)));
  double seconds = 0.0;
  for (;;) {
    PeakWindows windows{around, windows_around(around.peaks, grid, step, half)};
    HbmLevel level = sweep_hbm_level_windows(p, spec, force, harmonics, progress, windows);
    const bool whole = windows.windows.size() == 1 && windows.windows.front().first == 0 &&
                       windows.windows.front().last == static_cast<int>(grid.size()) - 1;
    if (whole || !peak_at_inner_edge(level, windows.windows, grid, step)) {
      window_hz = whole ? 0.0 : half * step;
      level.seconds += seconds;
      return level;
    }
    seconds += level.seconds;
    half *= 3;
  }
}

}  // namespace

HbmLevel sweep_hbm_level_adaptive(const PreparedHbm& p, const HbmSpec& spec, double force, const HbmProgress& progress,
                                  const LevelLink* link) {
  // The point scope chooses H inside the one sweep, frequency by frequency.
  if (spec.harmonic_scope == HbmSpec::HarmonicScope::point)
    return sweep_hbm_level(p, spec, force, spec.harmonics, progress, true, link);
  const bool by_windows =
      spec.harmonic_scope == HbmSpec::HarmonicScope::peaks && spec.sweep.method == HbmSweepSpec::Method::grid;
  std::vector<HbmLevel::HarmonicTrial> trials;
  std::vector<size_t> good_trials;  // of the sweeps that reached their end (or covered the band) with trusted peaks
  std::optional<HbmLevel> kept;     // the highest H so far among them
  size_t kept_trial = 0;
  double seconds = 0.0, shift_hz = 0.0;
  for (int h = spec.harmonics;;) {
    // More samples rescue a sweep only while no H has succeeded; after that a failed sweep is left
    // for the next H (on Table XI, 150 N at H = 7 took 275 s at 4096 samples and still failed).
    double window_hz = 0.0;
    HbmLevel level = by_windows && kept ? sweep_around_peaks(p, spec, force, h, progress, *kept, shift_hz, window_hz)
                                        : sweep_hbm_level(p, spec, force, h, progress, !kept, link);
    HbmLevel::HarmonicTrial t;
    t.harmonics = h;
    t.samples = level.samples;
    t.window_hz = window_hz;
    t.reached_end = level.path.converged;
    t.trusted = peaks_trusted(level);
    // With the path scope every point counts (a check may read any frequency), else the peaks.
    int needed = std::max(h, level.harmonics_needed);
    for (double share : level.harmonic_share) t.share = std::max(t.share, share);
    for (const HbmPeak& pk : level.peaks) {
      t.share = std::max(t.share, pk.truncation.largest());
      needed = std::max(needed, pk.truncation.needed(spec.harmonic_tolerance));
    }
    t.seconds = level.seconds;
    seconds += level.seconds;
    // For a peaks table, a grid sweep that covered the band counts when its peaks are trusted: a
    // frequency that failed away from them (on Table XI at H >= 3, 1-13 of 401 between 171.6 and
    // 178.4 Hz) does not move them, and one next to them makes them doubtful. So do windows
    // around the peaks with the peaks inside them.
    const bool covered = by_windows && !level.frequency_hz.empty() &&
                         (window_hz > 0.0 || level.frequency_hz.back() >= spec.sweep.f_max - 0.5 * spec.sweep.step_hz);
    const bool good = t.trusted && (t.reached_end || covered);
    const bool by_change = spec.harmonic_criterion == HbmSpec::HarmonicCriterion::change;
    if (by_change && good && kept) {
      t.change = result_change(spec, *kept, level);
      if (good_trials.size() >= 2) {  // the last good trial holds the change from the one before it
        const HbmLevel::HarmonicTrial& a = trials[good_trials[good_trials.size() - 2]];
        const HbmLevel::HarmonicTrial& b = trials[good_trials.back()];
        const std::array<double, 3> hs{static_cast<double>(a.harmonics), static_cast<double>(b.harmonics),
                                       static_cast<double>(h)};
        t.estimated_error = power_law_error(hs, b.change, t.change) - t.change;  // e(H) = e(H_b) - d
      }
    }
    if (good && kept) shift_hz = peak_shift_hz(*kept, level);
    if (good) good_trials.push_back(trials.size());
    trials.push_back(t);
    // The change is met by the higher H of the pair, which is kept (the better of the two).
    const bool met = good && (by_change ? t.change <= spec.harmonic_tolerance : t.share <= spec.harmonic_tolerance);
    if (good) kept = level, kept_trial = trials.size() - 1;
    if (met || h >= spec.max_harmonics) {
      if (!kept) kept = std::move(level), kept_trial = trials.size() - 1;
      break;
    }
    // By share: straight to the highest harmonic the points or peaks need; one more when the
    // shares were met but the sweep failed (a higher H may smooth the residual the corrector
    // stalled on). By change: the next step.
    h = std::min(spec.max_harmonics, std::max(h + spec.harmonic_step, by_change ? 0 : needed));
  }
  if (trials[kept_trial].window_hz > 0.0) {
    // The H chosen on the windows, over the whole band: the curve the tables and plots show. It
    // replaces the windows' level when its peaks are trusted (else the windows' stay, their path
    // the windows alone).
    HbmLevel band = sweep_hbm_level(p, spec, force, kept->harmonics, progress, false, link);
    HbmLevel::HarmonicTrial t = trials[kept_trial];
    t.window_hz = 0.0;
    t.samples = band.samples;
    t.reached_end = band.path.converged;
    t.trusted = peaks_trusted(band);
    t.band_change = result_change(spec, *kept, band);
    t.seconds = band.seconds;
    seconds += band.seconds;
    trials.push_back(t);
    if (t.trusted) kept = std::move(band), kept_trial = trials.size() - 1;
  }
  for (size_t i = 0; i < trials.size(); ++i) trials[i].chosen = i == kept_trial;
  kept->harmonic_trials = std::move(trials);
  kept->seconds = seconds;  // the cost of the choice, every H tried included
  return std::move(*kept);
}

}  // namespace bb
