#include <fmt/format.h>

#include <algorithm>

#include "analysis/hbm_level_system.hpp"

namespace bb {

// The first frequency's solution. Direct Newton from the static pre-solve (or the linear limits)
// first; when that fails, a homotopy in the force: from 1/64 of it, each converged fraction the
// start of the next, the increment halved on failure.
hbm::HbmSolution first_solution(const PreparedHbm& p, const HbmSpec& sweep_spec, double force, int harmonics,
                                int samples, double omega, const std::optional<Eigen::VectorXd>& initial) {
  // No neighbour to start from: Newton from the static or linear starts may approach the solution
  // only linearly (Levenberg-Marquardt steps across the contacts' kinks), so this one point of a
  // level gets ten times the iterations of a sweep's point.
  HbmSpec spec = sweep_spec;
  spec.max_iterations = 10 * sweep_spec.max_iterations;
  const hbm::HarmonicBalance system = level_system(p, spec, force, harmonics, samples);
  hbm::HbmSolution direct = hbm::solve_at_frequency(system, omega, initial);
  if (direct.converged) return direct;
  double done = 1.0 / 64, step = 1.0 / 64;
  hbm::HbmSolution at =
      hbm::solve_at_frequency(level_system(p, spec, force * done, harmonics, samples), omega, initial);
  int total = direct.iterations + at.iterations;
  while (at.converged && done < 1.0 && step >= 1.0 / 4096) {
    const double next = std::min(1.0, done + step);
    hbm::HbmSolution trial =
        hbm::solve_at_frequency(level_system(p, spec, force * next, harmonics, samples), omega, at.x);
    total += trial.iterations;
    if (trial.converged) {
      at = std::move(trial), done = next, step *= 2;
    } else {
      step /= 2;
    }
  }
  if (at.converged && done == 1.0) {
    at.iterations = total;
    return at;
  }
  direct.failure += fmt::format("; force homotopy reached {:.4g} of the force", at.converged ? done : 0.0);
  if (harmonics > 1) {
    // A homotopy in H: the one-harmonic solution, its higher harmonics zero, starts this one.
    const Eigen::Index dofs = system.unknowns() / (2 * harmonics + 1);
    std::optional<Eigen::VectorXd> low_initial;
    if (initial) low_initial = with_harmonics(*initial, dofs, 1);
    const hbm::HbmSolution low = first_solution(p, sweep_spec, force, 1, samples, omega, low_initial);
    if (low.converged) {
      hbm::HbmSolution lifted = hbm::solve_at_frequency(system, omega, with_harmonics(low.x, dofs, harmonics));
      if (lifted.converged) {
        lifted.iterations += total + low.iterations;
        return lifted;
      }
    }
    direct.failure += fmt::format("; from the H = 1 solution: {}", low.converged ? "no convergence" : low.failure);
  }
  return direct;
}

}  // namespace bb
