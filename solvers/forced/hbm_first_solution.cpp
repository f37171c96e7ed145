#include <fmt/format.h>

#include <algorithm>

#include "forced/hbm_level_system.hpp"

namespace bb {

// The first frequency's solution, from the cheapest start that converges: direct Newton from the
// static pre-solve (or the linear limits) with the sweep's iterations; for H > 1 the H = 1 solution
// (itself found this way) lifted to H; then, with ten times the sweep's iterations (Newton from a
// far start on this piecewise-smooth balance approaches the solution only linearly, by
// Levenberg-Marquardt steps across the contacts' kinks), Newton from the direct solve's best
// iterate (Table XI, H = 7, 80 N: 1 iteration there, 421 from the start) and a homotopy in
// the force: from 1/64 of it, each converged fraction the start of the next, the increment halved
// on failure. An iteration at H = 1 costs a tenth to a hundredth of one at H = 5-13, so the lifted
// start comes before the long solves (Table XI, H = 13, 110 N: 4338 iterations before it did).
hbm::HbmSolution first_solution(const PreparedHbm& p, const HbmSpec& sweep_spec, double force, int harmonics,
                                int samples, double omega, const std::optional<Eigen::VectorXd>& initial) {
  const hbm::HarmonicBalance quick = level_system(p, sweep_spec, force, harmonics, samples);
  hbm::HbmSolution direct = hbm::solve_at_frequency(quick, omega, initial);
  if (direct.converged) return direct;
  int total = direct.iterations;
  std::string lifted_failure;
  if (harmonics > 1) {
    const Eigen::Index dofs = quick.unknowns() / (2 * harmonics + 1);
    std::optional<Eigen::VectorXd> low_initial;
    if (initial) low_initial = with_harmonics(*initial, dofs, 1);
    const hbm::HbmSolution low = first_solution(p, sweep_spec, force, 1, samples, omega, low_initial);
    total += low.iterations;
    if (low.converged) {
      hbm::HbmSolution lifted = hbm::solve_at_frequency(quick, omega, with_harmonics(low.x, dofs, harmonics));
      total += lifted.iterations;
      if (lifted.converged) {
        lifted.iterations = total;
        return lifted;
      }
    }
    lifted_failure = fmt::format("; from the H = 1 solution: {}", low.converged ? "no convergence" : low.failure);
  }
  // From the best iterate so far: a direct solve that stalled on a kink has usually come close.
  const std::optional<Eigen::VectorXd> closest =
      direct.x.size() > 0 && direct.x.allFinite() ? std::optional<Eigen::VectorXd>(direct.x) : initial;
  hbm::HbmSolution patient =
      hbm::solve_at_frequency(patient_level_system(p, sweep_spec, force, harmonics, samples), omega, closest);
  total += patient.iterations;
  if (patient.converged) {
    patient.iterations = total;
    return patient;
  }
  double done = 1.0 / 64, step = 1.0 / 64;
  hbm::HbmSolution at =
      hbm::solve_at_frequency(patient_level_system(p, sweep_spec, force * done, harmonics, samples), omega, initial);
  total += at.iterations;
  while (at.converged && done < 1.0 && step >= 1.0 / 4096) {
    const double next = std::min(1.0, done + step);
    hbm::HbmSolution trial =
        hbm::solve_at_frequency(patient_level_system(p, sweep_spec, force * next, harmonics, samples), omega, at.x);
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
  patient.failure += lifted_failure;
  patient.failure += fmt::format("; force homotopy reached {:.4g} of the force", at.converged ? done : 0.0);
  patient.iterations = total;
  return patient;
}

}  // namespace bb
