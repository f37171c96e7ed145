#include "forced/hbm_response_control.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>

#include "common/constants.hpp"
#include "common/seconds_since.hpp"
#include "forced/hbm_level_system.hpp"
#include "forced/hbm_response.hpp"
#include "hbm/response_control.hpp"

namespace bb {
namespace {

using Eigen::Index;
using Complex = std::complex<double>;

// Every DOF's harmonics at the force F (the unit system's recovery is linear in the harmonic load).
Eigen::MatrixXd recover_at(const hbm::HarmonicBalance& unit, const Eigen::VectorXd& x, double omega, Complex force) {
  Eigen::MatrixXd q = unit.recover(x, omega);
  const Eigen::MatrixXd load_only = unit.recover(Eigen::VectorXd::Zero(x.size()), omega);
  for (Index d = 0; d < q.rows(); ++d) {
    const Complex add = (force - 1.0) * Complex(load_only(d, 1), -load_only(d, 2));
    q(d, 1) += add.real();
    q(d, 2) -= add.imag();
  }
  return q;
}

struct Solver {
  const PreparedHbm& p;
  const ResponseControlSpec& c;
  const hbm::HarmonicBalance& unit;

  hbm::ControlledSolution at(double hz, const std::optional<hbm::ControlledStart>& start) const {
    const double omega = kTwoPi * hz;
    return hbm::solve_controlled(unit, omega, {p.responses[c.response], c.held_displacement(omega)}, start);
  }
};

// Golden section on |F| between frequencies a < b around the smallest point, from its solution.
void refine_minimum(const Solver& solver, double a, double b, const hbm::ControlledStart& start, HbmControlled& out) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  hbm::ControlledStart from = start;
  const auto force_at = [&](double hz) {
    const hbm::ControlledSolution s = solver.at(hz, from);
    if (!s.solution.converged) return std::numeric_limits<double>::infinity();
    from = {s.solution.x, s.force};
    return std::abs(s.force);
  };
  double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = force_at(x1), f2 = force_at(x2);
  while (b - a > 1e-7 * b) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = force_at(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = force_at(x2);
    }
  }
  const double hz = 0.5 * (a + b);
  const hbm::ControlledSolution s = solver.at(hz, from);
  if (!s.solution.converged || !(std::abs(s.force) <= out.min_force)) return;  // keep the grid's smallest
  out.min_force = std::abs(s.force);
  out.min_frequency_hz = hz;
  out.min_phase_deg = -std::arg(s.force) * kDegPerRad;
  out.min_interior = true;
}

}  // namespace

HbmControlled run_response_control(const PreparedHbm& p, const HbmSpec& spec, const ResponseControlSpec& c,
                                   const HbmProgress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  HbmControlled out;
  out.name = c.name;
  out.harmonics = spec.harmonics;
  const hbm::HarmonicBalance unit = level_system(p, spec, 1.0, spec.harmonics, spec.time_samples);
  out.samples = unit.aft_options().samples;
  const Solver solver{p, c, unit};
  const size_t n = c.frequency_hz.size();
  const Index n_resp = static_cast<Index>(p.responses.size());
  out.amplitude.resize(static_cast<Index>(n), n_resp);
  out.phase_deg.resize(static_cast<Index>(n), n_resp);
  out.excursion.resize(static_cast<Index>(n), n_resp);
  std::vector<hbm::ControlledStart> solutions;  // of the converged points, for the refinement
  std::optional<hbm::ControlledStart> last;
  for (size_t i = 0; i < n; ++i) {
    const double hz = c.frequency_hz[i], omega = kTwoPi * hz;
    const hbm::ControlledSolution s = solver.at(hz, last);
    out.total_iterations += s.solution.iterations;
    if (!s.solution.converged) {
      out.failed_hz.push_back(hz);
      out.failures.push_back(s.solution.failure);
      continue;
    }
    const Index row = static_cast<Index>(out.frequency_hz.size());
    out.point.push_back(i);
    out.frequency_hz.push_back(hz);
    out.held_m.push_back(c.held_displacement(omega));
    out.force.push_back(std::abs(s.force));
    out.force_phase_deg.push_back(std::arg(s.force) * kDegPerRad);
    out.residual.push_back(s.solution.residual);
    out.iterations.push_back(s.solution.iterations);
    write_response_row(p, recover_at(unit, s.solution.x, omega, s.force), s.force, row, out.amplitude, out.phase_deg,
                       out.excursion);
    last = hbm::ControlledStart{s.solution.x, s.force};
    solutions.push_back(*last);
    if (progress && (i + 1) % 25 == 0)
      progress(fmt::format("response control '{}': {:.3f} Hz, force {:.4g} N, point {} of {}", c.name, hz,
                           std::abs(s.force), i + 1, n));
  }
  const Index kept = static_cast<Index>(out.frequency_hz.size());
  for (Eigen::MatrixXd* m : {&out.amplitude, &out.phase_deg, &out.excursion}) m->conservativeResize(kept, n_resp);
  if (kept > 0) {
    size_t k = 0;
    for (size_t i = 1; i < out.force.size(); ++i)
      if (out.force[i] < out.force[k]) k = i;
    out.min_force = out.force[k];
    out.min_frequency_hz = out.frequency_hz[k];
    out.min_phase_deg = -out.force_phase_deg[k];
    if (k > 0 && k + 1 < out.force.size())
      refine_minimum(solver, std::min(out.frequency_hz[k - 1], out.frequency_hz[k + 1]),
                     std::max(out.frequency_hz[k - 1], out.frequency_hz[k + 1]), solutions[k], out);
  }
  out.seconds = seconds_since(t0);
  return out;
}

}  // namespace bb
