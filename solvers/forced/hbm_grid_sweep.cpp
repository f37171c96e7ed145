// The grid sweep of one force level, with one H for the level or an H per frequency.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/constants.hpp"
#include "forced/hbm_level_system.hpp"
#include "forced/hbm_response.hpp"
#include "frf/sweep.hpp"
#include "linalg/damped_newton.hpp"

namespace bb {

using Eigen::Index;

const hbm::HarmonicBalance& LevelSystems::at(int harmonics) const {
  std::unique_ptr<hbm::HarmonicBalance>& s = systems_[harmonics];
  if (!s) s = std::make_unique<hbm::HarmonicBalance>(level_system(p_, spec_, force_, harmonics, samples_));
  return *s;
}

const hbm::TruncationProbe& LevelSystems::probe(int harmonics) const {
  std::unique_ptr<hbm::TruncationProbe>& t = probes_[harmonics];
  if (!t) t = std::make_unique<hbm::TruncationProbe>(at(harmonics));
  return *t;
}

double relative_change(double value, double reference) {
  return reference > 0.0 ? std::abs(value - reference) / reference : (value == reference ? 0.0 : 1.0);
}

Eigen::VectorXd with_harmonics(const Eigen::VectorXd& x, Index contact_dofs, int harmonics) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(contact_dofs * (2 * harmonics + 1));
  const Index n = std::min(x.size(), y.size());
  y.head(n) = x.head(n);  // coefficient-major layout: the lower harmonics come first
  return y;
}

hbm::HbmSolution approach_in_steps(const hbm::HarmonicBalance& system, double w0, Eigen::VectorXd x, double omega,
                                   int steps, int& iterations, ChordFactorization* chord) {
  hbm::HbmSolution s;
  for (int k = 1; k <= steps; ++k) {
    s = hbm::solve_at_frequency(system, w0 + (omega - w0) * k / steps, x, chord);
    iterations += s.iterations;
    if (!s.converged) break;
    x = s.x;
  }
  return s;
}

hbm::HbmSolution solve_on_last_arc(const hbm::HarmonicBalance& system,
                                   const std::vector<hbm::ContinuationPoint>& points, double omega) {
  const hbm::ContinuationPoint& a = points.at(points.size() - 2);
  const hbm::ContinuationPoint& b = points.back();
  const double t = b.omega == a.omega ? 1.0 : (omega - a.omega) / (b.omega - a.omega);
  return hbm::solve_at_frequency(system, omega, Eigen::VectorXd(a.x + t * (b.x - a.x)));
}

namespace {

// Unknowns from which a grid sweep reuses factorized Jacobians (chord steps; see sweep_grid_on).
constexpr Index kChordUnknowns = 200;

// How a bridge by arclength ended: at its grid frequency, or not; folds_back when the branch of the
// path's last point turned away from the grid frequency and ran back out of the band (a fold that
// the response jumps off: no step size or later frequency reaches beyond it along that branch).
enum class Bridge { reached, failed, folds_back };

// Traces the branch by pseudo-arclength from the path's last point to grid[i], through a fold if
// there is one, and appends the traced points, the last solved at grid[i].
Bridge bridge_by_arclength(const hbm::HarmonicBalance& system, const std::vector<double>& grid, int i, double max_step,
                           hbm::ContinuationResult& path) {
  hbm::ContinuationOptions c;
  c.omega_start = path.points.back().omega;
  c.omega_end = kTwoPi * grid[static_cast<size_t>(i)];
  c.initial = path.points.back().x;
  c.initial_step = 0.01 * (c.omega_end - c.omega_start) / c.omega_start;  // a hundredth of the gap, scaled
  // A fold's branch may run back far below the gap (Table XI at 60 N, H = 5: 1.5 Hz, to 171.7 Hz)
  // before it turns forward again, along an arc far longer than the gap: the sweep's largest step,
  // back to the band's start (where a stuck contact's free slider leaves J singular, a path can
  // wander along its null space far below it).
  c.max_step = std::max(max_step, 0.25 * (c.omega_end - c.omega_start) / c.omega_start);
  c.min_step = 1e-4 * c.initial_step;
  // Back to 1 % below the band's start: a fold's lower turn need not lie inside the band (the same
  // level swept from 172 Hz turns at 171.7 Hz: the bridge stopped there, 11 frequencies failed).
  c.omega_back = std::max(c.omega_start - kTwoPi * grid.front(), 0.0) + 0.01 * c.omega_start;
  c.max_points = 5000;
  // A bridge crosses a fold or two (the worst Table XI needs: 4 turning points at 60 N, H = 5);
  // 60 N at H = 2 wandered 5000 points and 183 turning points near 174.75 Hz (64 s) without
  // arriving, where Newton with more iterations then converged.
  c.max_turning_points = 12;
  const hbm::ContinuationResult bridge = hbm::continue_in_frequency(system, c);
  path.corrector_iterations += bridge.corrector_iterations;
  path.rejected_steps += bridge.rejected_steps;
  if (bridge.turned_back) return Bridge::folds_back;
  if (!bridge.converged || bridge.points.size() < 2) return Bridge::failed;
  path.turning_points += bridge.turning_points;
  path.jumps += bridge.jumps;
  path.corners += bridge.corners;
  path.points.insert(path.points.end(), bridge.points.begin() + 1, bridge.points.end());
  // The bridge ends past the grid frequency: solved there from the last arc interpolated, so that
  // the table holds every frequency of the grid.
  const hbm::ContinuationPoint& a = path.points[path.points.size() - 2];
  const hbm::ContinuationPoint& b = path.points.back();
  if (b.omega != c.omega_end && b.omega != a.omega) {
    hbm::HbmSolution s = solve_on_last_arc(system, path.points, c.omega_end);
    path.corrector_iterations += s.iterations;
    if (s.converged) path.points.back() = {c.omega_end, std::move(s.x), s.residual, s.iterations, 0.0, 1.0};
  }
  return Bridge::reached;
}

// The start of the next grid point: the polynomial through the last few points where they run
// forward in frequency (a smooth branch: each point more gains an order over the secant), else
// the secant.
Eigen::VectorXd extrapolated(const std::vector<hbm::ContinuationPoint>& pts, double omega, Index nc, int harmonics) {
  constexpr size_t kOrder = 3;  // cubic: Table XI at H = 7 takes 17 % fewer iterations than by the secant
  const size_t n = pts.size();
  if (n < 2) return pts.back().x;
  size_t k = 1;  // points used beyond the last
  while (k < kOrder && k + 1 < n && pts[n - k - 1].omega < pts[n - k].omega) ++k;
  if (!(pts[n - 1].omega < omega) || k < 2) {
    const hbm::ContinuationPoint &b = pts[n - 2], &c = pts[n - 1];
    return c.x + (c.x - with_harmonics(b.x, nc, harmonics)) * ((omega - c.omega) / (c.omega - b.omega));
  }
  Eigen::VectorXd guess = Eigen::VectorXd::Zero(pts.back().x.size());
  for (size_t a = n - k - 1; a < n; ++a) {
    double l = 1.0;
    for (size_t b = n - k - 1; b < n; ++b)
      if (b != a) l *= (omega - pts[b].omega) / (pts[a].omega - pts[b].omega);
    guess += l * with_harmonics(pts[a].x, nc, harmonics);
  }
  return guess;
}

// What the point scope compares between two H at one frequency: each response's largest
// displacement and first-harmonic amplitude, and the IP / OOP components.
std::vector<double> point_values(const PreparedHbm& p, const hbm::HarmonicBalance& system, const Eigen::VectorXd& x,
                                 double omega) {
  const Eigen::MatrixXd q = system.recover(x, omega);
  const Eigen::VectorXcd z = first_harmonic(q);
  std::vector<double> v;
  for (Index r : p.responses) {
    v.push_back(largest_excursion(q.row(r)));
    v.push_back(std::abs(z[r]));
  }
  if (p.ip_oop)
    for (int k = 0; k < 2; ++k) v.push_back(peak_values(p, z, k).component);
  return v;
}

double largest_relative_change(const std::vector<double>& lower, const std::vector<double>& higher) {
  double change = 0.0;
  for (size_t k = 0; k < higher.size(); ++k) change = std::max(change, relative_change(lower[k], higher[k]));
  return change;
}

struct PointChoice {
  hbm::HbmSolution solution;
  int harmonics = 0;
  double change = kNan;  // from the H one step below; NaN when the pair did not both converge
  int iterations = 0;
};

// Solves one frequency at H = start (clamped to [harmonics, max_harmonics - step]) and
// start + step, then raises the pair by a step until the two agree to harmonic_tolerance or the
// upper one reaches max_harmonics; keeps the upper H of the last pair (the lower where only it
// converged). solve(h, from) solves at H = h from the lower H's solution, or from the sweep's
// guess when from is null.
PointChoice choose_harmonics(const PreparedHbm& p, const HbmSpec& spec, const LevelSystems& systems, double omega,
                             int start, const std::function<hbm::HbmSolution(int, const Eigen::VectorXd*)>& solve) {
  const int step = spec.harmonic_step, top = spec.max_harmonics;
  int a = std::clamp(start, spec.harmonics, std::max(spec.harmonics, top - step));
  PointChoice c;
  hbm::HbmSolution sa = solve(a, nullptr);
  c.iterations += sa.iterations;
  for (;;) {
    const int b = std::min(a + step, top);
    hbm::HbmSolution sb = solve(b, sa.converged ? &sa.x : nullptr);
    c.iterations += sb.iterations;
    double change = kNan;
    if (sa.converged && sb.converged)
      change = largest_relative_change(point_values(p, systems.at(a), sa.x, omega),
                                       point_values(p, systems.at(b), sb.x, omega));
    if (change <= spec.harmonic_tolerance || b >= top) {
      const bool upper = sb.converged || !sa.converged;
      c.harmonics = upper ? b : a;
      c.change = change;
      c.solution = upper ? std::move(sb) : std::move(sa);
      return c;
    }
    a = b;
    sa = std::move(sb);
  }
}

// Grid frequencies the forward pass lost, solved again from the side beyond them: Newton from the
// next frequency's solution, then in eight substeps back from it. A forward step can meet a kink or
// a nearby second solution that the step from above does not (Table XI, H = 13, 200 N, 174.70 Hz:
// every forward fallback failed while 174.75 Hz converged). Runs of failures are filled from the top
// down, each from the one just filled. Returns the frequencies (Hz) still failed.
std::vector<double> retry_from_above(const LevelSystems& systems, const std::vector<double>& grid,
                                     const std::vector<int>& failed, HbmLevel& level, bool per_point) {
  hbm::ContinuationResult& path = level.path;
  std::vector<double> still;
  for (auto f = failed.rbegin(); f != failed.rend(); ++f) {
    const int i = *f;
    const double omega = kTwoPi * grid[static_cast<size_t>(i)];
    const double above = i + 1 < static_cast<int>(grid.size()) ? kTwoPi * grid[static_cast<size_t>(i + 1)] : kNan;
    const auto next = std::find_if(path.points.begin(), path.points.end(),
                                   [above](const hbm::ContinuationPoint& q) { return q.omega == above; });
    if (next == path.points.end()) {
      still.push_back(omega / kTwoPi);
      continue;
    }
    const size_t at = static_cast<size_t>(next - path.points.begin());
    const int h = per_point ? level.point_harmonics[at] : level.harmonics;
    const hbm::HarmonicBalance& system = systems.at(h);
    hbm::HbmSolution s = hbm::solve_at_frequency(system, omega, next->x);
    path.corrector_iterations += s.iterations;
    if (!s.converged) s = approach_in_steps(system, above, next->x, omega, 8, path.corrector_iterations);
    if (!s.converged) {
      still.push_back(omega / kTwoPi);
      continue;
    }
    path.points.insert(path.points.begin() + static_cast<std::ptrdiff_t>(at),
                       {omega, std::move(s.x), s.residual, s.iterations, 0.0, 1.0});
    if (per_point) {
      level.point_harmonics.insert(level.point_harmonics.begin() + static_cast<std::ptrdiff_t>(at), h);
      level.point_change.insert(level.point_change.begin() + static_cast<std::ptrdiff_t>(at), kNan);
    }
  }
  std::reverse(still.begin(), still.end());
  return still;
}

// sweep_grid on the frequencies `grid`.
void sweep_grid_on(const PreparedHbm& p, const HbmSpec& spec, const LevelSystems& systems, const FirstSolution& first,
                   const std::vector<double>& grid, HbmLevel& level, const SweepReport& report) {
  const bool per_point = spec.harmonic_scope == HbmSpec::HarmonicScope::point;
  hbm::ContinuationResult& path = level.path;
  const int n = static_cast<int>(grid.size());
  const Index nc = static_cast<Index>(systems.at(level.harmonics).contact_dofs().size());
  int h_last = level.harmonics;  // H of the last point accepted
  const auto accept = [&](double omega, hbm::HbmSolution& s, int h, double change, int iterations) {
    path.points.push_back({omega, std::move(s.x), s.residual, iterations, 0.0, 1.0});
    if (per_point) {
      level.point_harmonics.push_back(h);
      level.point_change.push_back(change);
    }
    h_last = h;
  };

  const double omega0 = kTwoPi * grid.front();
  hbm::HbmSolution s0;
  int h0 = level.harmonics;
  double change0 = kNan;
  if (per_point) {
    PointChoice c =
        choose_harmonics(p, spec, systems, omega0, level.harmonics, [&](int h, const Eigen::VectorXd* from) {
          if (from) {
            hbm::HbmSolution s = hbm::solve_at_frequency(systems.at(h), omega0, with_harmonics(*from, nc, h));
            if (s.converged) return s;
          }
          return first(h);
        });
    s0 = std::move(c.solution), h0 = c.harmonics, change0 = c.change;
    s0.iterations = c.iterations;
  } else {
    s0 = first(level.harmonics);
  }
  path.corrector_iterations = s0.iterations;
  if (!s0.converged) {
    path.failure = "first point: " + s0.failure;
    return;
  }
  accept(omega0, s0, h0, change0, s0.iterations);

  std::vector<int> failed;  // grid indices
  std::string last_failure;
  // The Jacobian factorized at one frequency serves the next ones as long as it contracts, where
  // its LU costs more than the residuals a chord step spends. Table XI (9 contact DOFs, events AFT):
  // H = 9 (171 unknowns) no gain, H = 11 (207) 2.4x and H = 13 (243) 1.3x faster sweeps.
  ChordFactorization chord;
  const auto chord_for = [&chord](const hbm::HarmonicBalance& system) {
    return system.unknowns() >= kChordUnknowns ? &chord : nullptr;
  };
  // The path's size when a bridge from its last point folded back and patient Newton failed too:
  // until a later frequency converges from its guess, the same fallbacks from that point (substeps,
  // bridge, patient Newton) are not tried again, and the frequencies beyond the fold are left to the
  // pass from above. Table XI at 30 N, H = 1, mu = 0.503: 39 frequencies each spent about 700
  // iterations on them, 15 s for a level that otherwise takes 0.06 s.
  size_t dead_end = 0;
  // The path's size when a bridge from its last point failed otherwise (it wandered along kinks, or
  // its corrector stalled): a bridge from the same point meets the same kinks whatever frequency it
  // aims at, so later frequencies keep their substeps and patient Newton but no bridge from there.
  // Table XI at 80 N, kt = 3.37e8, mu = 2 (a calibration's trial values): 13 turns near 188.3 Hz,
  // 5 800 iterations at each of 20 frequencies (20 s); at 260 N, kt = 2.74e7, mu = 1.41 the failed
  // bridge from 171.90 Hz is followed by 172.00 Hz converging by the later fallbacks.
  size_t no_bridge = 0;
  const auto lose = [&](int i, const std::string& why) {
    failed.push_back(i);
    last_failure = why;
    ++path.rejected_steps;
  };
  for (int i = 1; i < n; ++i) {
    const double omega = kTwoPi * grid[static_cast<size_t>(i)];
    const auto& pts = path.points;
    const Eigen::VectorXd guess = extrapolated(pts, omega, nc, h_last);
    hbm::HbmSolution s;
    int h = h_last, iterations = 0;
    double change = kNan;
    if (per_point) {
      // Start one step below the previous point's pair, so that H falls again past a resonance.
      PointChoice c = choose_harmonics(
          p, spec, systems, omega, h_last - 2 * spec.harmonic_step, [&](int hh, const Eigen::VectorXd* from) {
            return hbm::solve_at_frequency(systems.at(hh), omega, with_harmonics(from ? *from : guess, nc, hh),
                                           chord_for(systems.at(hh)));
          });
      s = std::move(c.solution), h = c.harmonics, change = c.change, iterations = c.iterations;
    } else {
      s = hbm::solve_at_frequency(systems.at(h_last), omega, guess, chord_for(systems.at(h_last)));
      iterations = s.iterations;
    }
    path.corrector_iterations += iterations;
    const bool at_dead_end = !s.converged && pts.size() == dead_end;
    if (!s.converged && !at_dead_end) {
      // Approach it in smaller steps from the last converged point (a kink between the two).
      h = h_last, change = kNan;
      const hbm::HarmonicBalance& system = systems.at(h_last);
      s = approach_in_steps(system, pts.back().omega, pts.back().x, omega, 8, path.corrector_iterations,
                            chord_for(system));
      iterations = s.iterations;
    }
    report(omega, i, iterations);
    if (at_dead_end) {
      lose(i, s.failure);
      continue;
    }
    if (!s.converged) {
      // A fold (the branch turns back) or a kink the grid cannot step over: trace the branch by
      // arclength from the last converged point to this frequency, through the fold.
      const size_t before = path.points.size();
      const Bridge bridge = pts.size() == no_bridge
                                ? Bridge::failed
                                : bridge_by_arclength(systems.at(h_last), grid, i, spec.sweep.max_step, path);
      if (bridge == Bridge::reached) {
        if (per_point)
          for (size_t k = before; k < path.points.size(); ++k) {
            level.point_harmonics.push_back(h_last);
            level.point_change.push_back(kNan);
          }
        continue;
      }
      // Last, Newton from the predicted guess with ten times the iterations: next to a kink it may
      // converge, linearly, where the sweep's budget and the bridge both stop (Table XI, H = 13,
      // 110 N, 178.05 Hz: |R| = 4e-4 N after 20 iterations; 100 N, 172.10 Hz: in 75 iterations
      // where the bridge folded back).
      s = hbm::solve_at_frequency(
          patient_level_system(p, spec, level.force, h_last, systems.at(h_last).aft_options().samples), omega, guess);
      path.corrector_iterations += s.iterations;
      if (s.converged) {
        accept(omega, s, h_last, kNan, s.iterations);
        continue;
      }
      if (bridge == Bridge::folds_back) dead_end = path.points.size();
      no_bridge = path.points.size();
      lose(i, s.failure);
      continue;
    }
    accept(omega, s, h, change, iterations);
  }
  const std::vector<double> lost = retry_from_above(systems, grid, failed, level, per_point);
  level.failed_hz.insert(level.failed_hz.end(), lost.begin(), lost.end());
  path.converged = lost.empty();
  if (!lost.empty())
    path.failure =
        fmt::format("{} of {} frequencies did not converge (first at {:.4f} Hz, last at {:.4f} Hz; last: {})",
                    lost.size(), n, lost.front(), lost.back(), last_failure);
  if (per_point) level.harmonics = *std::max_element(level.point_harmonics.begin(), level.point_harmonics.end());
}

}  // namespace

const hbm::ContinuationPoint& nearest_point(const hbm::ContinuationResult& path, double omega) {
  size_t nearest = 0;
  for (size_t i = 1; i < path.points.size(); ++i)
    if (std::abs(path.points[i].omega - omega) < std::abs(path.points[nearest].omega - omega)) nearest = i;
  return path.points.at(nearest);
}

void sweep_grid(const PreparedHbm& p, const HbmSpec& spec, const LevelSystems& systems, const FirstSolution& first,
                HbmLevel& level, const SweepReport& report) {
  const std::vector<double> grid = fixed_grid(spec.sweep.f_min, spec.sweep.f_max, spec.sweep.step_hz);
  const HbmLevel start = level;  // force and H, before the sweep
  sweep_grid_on(p, spec, systems, first, grid, level, report);
  if (level.path.converged || level.path.points.empty() || spec.harmonic_scope == HbmSpec::HarmonicScope::point) return;
  // Once more from the branch that comes up from below the band (first_solution_from_below).
  HbmLevel again = start;
  const FirstSolution from_below = [&](int h) {
    return first_solution_from_below(systems.at(h), kTwoPi * grid.front());
  };
  sweep_grid_on(p, spec, systems, from_below, grid, again, report);
  if (!again.path.converged) return;
  again.path.corrector_iterations += level.path.corrector_iterations;
  again.path.rejected_steps += level.path.rejected_steps;
  level = std::move(again);
}

void sweep_grid_windows(const PreparedHbm& p, const HbmSpec& spec, const LevelSystems& systems,
                        const PeakWindows& windows, HbmLevel& level, const SweepReport& report) {
  const std::vector<double> grid = fixed_grid(spec.sweep.f_min, spec.sweep.f_max, spec.sweep.step_hz);
  const Index nc = static_cast<Index>(systems.at(level.harmonics).contact_dofs().size());
  hbm::ContinuationResult& path = level.path;
  path.converged = true;
  for (const GridWindow& w : windows.windows) {
    const std::vector<double> part(grid.begin() + w.first, grid.begin() + w.last + 1);
    const double omega0 = kTwoPi * part.front();
    const FirstSolution first = [&](int h) {
      const Eigen::VectorXd x0 = with_harmonics(nearest_point(windows.around.path, omega0).x, nc, h);
      return first_solution(p, spec, systems.force(), h, systems.samples(), omega0, x0);
    };
    HbmLevel piece;
    piece.force = level.force;
    piece.harmonics = level.harmonics;
    sweep_grid_on(p, spec, systems, first, part, piece, report);
    const hbm::ContinuationResult& q = piece.path;
    path.points.insert(path.points.end(), q.points.begin(), q.points.end());
    path.corrector_iterations += q.corrector_iterations;
    path.rejected_steps += q.rejected_steps;
    path.turning_points += q.turning_points;
    path.jumps += q.jumps;
    path.corners += q.corners;
    level.failed_hz.insert(level.failed_hz.end(), piece.failed_hz.begin(), piece.failed_hz.end());
    if (!q.converged) {
      path.converged = false;
      path.failure += fmt::format("{}window {:.4f}-{:.4f} Hz: {}", path.failure.empty() ? "" : "; ", part.front(),
                                  part.back(), q.failure);
    }
  }
}

}  // namespace bb
