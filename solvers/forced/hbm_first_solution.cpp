#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>

#include "forced/hbm_level_system.hpp"
#include "hbm/continuation.hpp"

namespace bb {

namespace {

// A homotopy in the force at fixed omega, from the solution x_from at force_from to `force`: each
// converged force is the start of the next, from that start alone with the sweep's iterations; the
// step is halved on failure (down to 1/4096 of the way) and doubled on success.
struct Homotopy {
  hbm::HbmSolution at;
  double reached = 0.0;  // fraction of the way from force_from to force
  int iterations = 0;
};

Homotopy force_homotopy(const PreparedHbm& p, const HbmSpec& spec, double force_from, const Eigen::VectorXd& x_from,
                        double force, int harmonics, int samples, double omega, double first_step) {
  Homotopy h;
  h.at.x = x_from;
  double step = first_step;
  while (h.reached < 1.0 && step >= 1.0 / 4096) {
    const double next = std::min(1.0, h.reached + step);
    const double f = next == 1.0 ? force : force_from + next * (force - force_from);
    hbm::HbmSolution trial = hbm::solve_from(level_system(p, spec, f, harmonics, samples), omega, h.at.x);
    h.iterations += trial.iterations;
    if (trial.converged) {
      h.at = std::move(trial);
      h.reached = next;
      step *= 2;
    } else {
      step /= 2;
    }
  }
  return h;
}

// The solution at omega reached from a neighbouring frequency: solved at omega (1 +- d) from
// `initial` (or the linear limits), then at omega from there in four substeps. A start that fails
// at one frequency can succeed a hair away (Table XI, H = 1, 300 N, kt = 4.6e9, mu = 0.6215: every
// start at 170 Hz failed, 170.05 and 169.95 Hz converge at once).
std::optional<hbm::HbmSolution> from_a_neighbouring_frequency(const hbm::HarmonicBalance& system, double omega,
                                                              const std::optional<Eigen::VectorXd>& initial,
                                                              int& iterations) {
  for (const double d : {1e-3, -1e-3, 1e-2, -1e-2}) {
    const double beside = omega * (1.0 + d);
    hbm::HbmSolution s = hbm::solve_at_frequency(system, beside, initial);
    iterations += s.iterations;
    if (s.converged) s = approach_in_steps(system, beside, s.x, omega, 4, iterations);
    if (s.converged) return s;
  }
  return std::nullopt;
}

// The solution at omega traced by pseudo-arclength from a frequency 5 % away, where the response is
// far from resonance and Newton from the linear limits converges: the path passes the folds and
// kinks between (Table XI, H = 5, 80 N, 172.2 Hz: every start at that frequency, the force homotopy
// and the neighbours 1 % away failed, inside a fold of the branch).
std::optional<hbm::HbmSolution> by_arclength_from_afar(const hbm::HarmonicBalance& system, double omega,
                                                       int& iterations,
                                                       std::initializer_list<double> offsets = {-0.05, 0.05}) {
  for (const double d : offsets) {
    hbm::ContinuationOptions c;
    c.omega_start = omega * (1.0 + d);
    c.omega_end = omega;
    c.initial_step = 0.05 * std::abs(d);
    c.max_step = 0.25 * std::abs(d);
    c.min_step = 1e-4 * c.initial_step;
    c.max_points = 5000;
    c.max_turning_points = 12;  // a fold or two, not a walk along kinks (as the sweep's bridges)
    const hbm::ContinuationResult path = hbm::continue_in_frequency(system, c);
    iterations += path.corrector_iterations;
    if (!path.converged || path.points.size() < 2) continue;
    hbm::HbmSolution s = solve_on_last_arc(system, path.points, omega);
    iterations += s.iterations;
    if (s.converged) return s;
  }
  return std::nullopt;
}

}  // namespace

// The first frequency's solution, from the cheapest start that converges: direct Newton from the
// caller's start (the previous level's solution, or the static pre-solve) or the linear limits,
// with the sweep's iterations; for H > 1 the H = 1 solution (itself found this way) lifted to H;
// Newton continued from the direct solve's best iterate; a homotopy in the force from the previous
// level's solution; Newton with ten times the sweep's iterations from that best iterate (Newton
// from a far start on this piecewise-smooth balance approaches the solution only linearly, by
// Levenberg-Marquardt steps across the contacts' kinks); a homotopy from 1/64 of the force; and
// for H > 3 the solution at H - 2 (found the same way) lifted by two; from a frequency a
// tenth or a hundredth of a percent away; last, along the branch by arclength from 5 % away. An iteration at H = 1
// costs a tenth to a hundredth of one at H = 5-13, so the lifted start comes before the long solves, and above H = 7,
// where the patient solve's 600 iterations cost most (Table XI, H = 13, 100 N, 170 Hz: they failed, the ladder
// converges), the ladder of H comes before it. The homotopy steps start from the last converged force alone with the
// sweep's iterations: a failed step costs 20 iterations, not the 600 of three patient starts (Table XI, H = 13, 110 N:
// 4 476 iterations before).
hbm::HbmSolution first_solution(const PreparedHbm& p, const HbmSpec& sweep_spec, double force, int harmonics,
                                int samples, double omega, const std::optional<Eigen::VectorXd>& initial,
                                std::optional<double> initial_force) {
  const hbm::HarmonicBalance quick = level_system(p, sweep_spec, force, harmonics, samples);
  hbm::HbmSolution direct = hbm::solve_at_frequency(quick, omega, initial);
  if (direct.converged) return direct;
  int total = direct.iterations;
  std::string failures;
  const auto done = [&](hbm::HbmSolution s) {
    s.iterations = total;
    return s;
  };
  const Eigen::Index dofs = quick.unknowns() / (2 * harmonics + 1);
  // The solution at `lower` harmonics (found by this function) lifted to H.
  const auto lifted_from = [&](int lower) -> std::optional<hbm::HbmSolution> {
    std::optional<Eigen::VectorXd> low_initial;
    if (initial) low_initial = with_harmonics(*initial, dofs, lower);
    const hbm::HbmSolution low =
        first_solution(p, sweep_spec, force, lower, samples, omega, low_initial, initial_force);
    total += low.iterations;
    if (low.converged) {
      hbm::HbmSolution lifted = hbm::solve_at_frequency(quick, omega, with_harmonics(low.x, dofs, harmonics));
      total += lifted.iterations;
      if (lifted.converged) return lifted;
    }
    failures += fmt::format("; from the H = {} solution: {}", lower, low.converged ? "no convergence" : low.failure);
    return std::nullopt;
  };
  if (harmonics > 1)
    if (auto s = lifted_from(1)) return done(std::move(*s));
  // The direct solve's best iterate, continued alone: a solve that stalled on a kink has usually
  // come close (Table XI, H = 7, 80 N: 1 more iteration, where 421 from the start).
  const bool came_close = direct.x.size() > 0 && direct.x.allFinite();
  if (came_close) {
    hbm::HbmSolution continued = hbm::solve_from(quick, omega, direct.x);
    total += continued.iterations;
    if (continued.converged) return done(std::move(continued));
  }
  if (initial && initial_force) {
    // Its first step goes half the way: the whole way from `initial` is the direct solve's first start.
    Homotopy from_neighbour =
        force_homotopy(p, sweep_spec, *initial_force, *initial, force, harmonics, samples, omega, 0.5);
    total += from_neighbour.iterations;
    if (from_neighbour.reached == 1.0) return done(std::move(from_neighbour.at));
    failures +=
        fmt::format("; force homotopy from {:g} N reached {:.4g} of the way", *initial_force, from_neighbour.reached);
  }
  const bool ladder = harmonics > 3, ladder_first = harmonics > 7;
  if (ladder_first)
    if (auto s = lifted_from(harmonics - 2)) return done(std::move(*s));
  const std::optional<Eigen::VectorXd> closest = came_close ? std::optional<Eigen::VectorXd>(direct.x) : initial;
  hbm::HbmSolution patient =
      hbm::solve_at_frequency(patient_level_system(p, sweep_spec, force, harmonics, samples), omega, closest);
  total += patient.iterations;
  if (patient.converged) return done(std::move(patient));
  hbm::HbmSolution low_force =
      hbm::solve_at_frequency(patient_level_system(p, sweep_spec, force / 64, harmonics, samples), omega, initial);
  total += low_force.iterations;
  if (low_force.converged) {
    Homotopy from_low =
        force_homotopy(p, sweep_spec, force / 64, low_force.x, force, harmonics, samples, omega, 1.0 / 63);
    total += from_low.iterations;
    if (from_low.reached == 1.0) return done(std::move(from_low.at));
    failures += fmt::format("; force homotopy from 1/64 of the force reached {:.4g} of the way", from_low.reached);
  } else {
    failures += "; force homotopy: no solution at 1/64 of the force";
  }
  // Table XI, H = 7, 260 N, 170 Hz without a neighbour level: every start above failed, the ladder converges.
  if (ladder && !ladder_first)
    if (auto s = lifted_from(harmonics - 2)) return done(std::move(*s));
  if (auto s = from_a_neighbouring_frequency(quick, omega, initial, total)) return done(std::move(*s));
  failures += "; from frequencies 0.1 % and 1 % away: no solution";
  if (auto s = by_arclength_from_afar(quick, omega, total)) return done(std::move(*s));
  failures += "; by arclength from 5 % away: not reached";
  patient.failure += failures;
  return done(std::move(patient));
}

hbm::HbmSolution first_solution_from_below(const hbm::HarmonicBalance& system, double omega) {
  int iterations = 0;
  hbm::HbmSolution s;
  if (auto traced = by_arclength_from_afar(system, omega, iterations, {-0.05}))
    s = std::move(*traced);
  else
    s.failure = "by arclength from 5 % below: not reached";
  s.iterations = iterations;
  return s;
}

}  // namespace bb
