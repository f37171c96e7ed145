#include "forced/hbm_stepped_sine.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "common/constants.hpp"
#include "common/seconds_since.hpp"
#include "forced/hbm_level_system.hpp"
#include "forced/hbm_response.hpp"

namespace bb {
namespace {

using Eigen::Index;

void record(const PreparedHbm& p, const hbm::HarmonicBalance& system, const hbm::HbmSolution& s,
            const std::vector<hbm::ModelDerivative>& derivatives, HbmSteppedSine& out) {
  const Index row = static_cast<Index>(out.frequency_hz.size()) - 1;
  write_response_row(p, system.recover(s.x, s.omega), 1.0, row, out.amplitude, out.phase_deg, out.excursion);
  if (derivatives.empty()) return;
  const ResponseDlog d = response_dlog(p, system, s.x, s.omega, derivatives);
  for (size_t j = 0; j < derivatives.size(); ++j) {
    out.amplitude_dlog[j].row(row) = d.amplitude.row(static_cast<Index>(j));
    out.phase_dlog_deg[j].row(row) = d.phase_deg.row(static_cast<Index>(j));
  }
}

}  // namespace

HbmSteppedSine run_stepped_sine(const PreparedHbm& p, const HbmSpec& spec, const SteppedSineSpec& sine,
                                const HbmProgress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  HbmSteppedSine out;
  out.name = sine.name;
  out.harmonics = spec.harmonics;
  const size_t n = sine.frequency_hz.size();
  const Index n_resp = static_cast<Index>(p.responses.size());
  out.amplitude.resize(static_cast<Index>(n), n_resp);
  out.phase_deg.resize(static_cast<Index>(n), n_resp);
  out.excursion.resize(static_cast<Index>(n), n_resp);
  std::vector<hbm::ModelDerivative> derivatives;
  if (!spec.sensitivities.empty() && spec.path_sensitivities)
    derivatives = log_derivatives(p, spec, p.model);  // the laws and damping do not depend on the force
  out.amplitude_dlog.assign(derivatives.size(), Eigen::MatrixXd(static_cast<Index>(n), n_resp));
  out.phase_dlog_deg.assign(derivatives.size(), Eigen::MatrixXd(static_cast<Index>(n), n_resp));
  std::optional<hbm::HbmSolution> last;
  double last_force = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double force = sine.force[i], omega = kTwoPi * sine.frequency_hz[i];
    const hbm::HarmonicBalance system = level_system(p, spec, force, spec.harmonics, spec.time_samples);
    out.samples = system.aft_options().samples;
    hbm::HbmSolution s;
    if (last) {
      s = hbm::solve_at_frequency(system, omega, last->x);
      if (!s.converged) {
        const int tried = s.iterations;
        s = first_solution(p, spec, force, spec.harmonics, spec.time_samples, omega, last->x, last_force);
        s.iterations += tried;
      }
    } else {
      s = first_solution(p, spec, force, spec.harmonics, spec.time_samples, omega,
                         damper_seated_start(p, system, omega));
    }
    out.total_iterations += s.iterations;
    if (!s.converged) {
      out.failed_hz.push_back(sine.frequency_hz[i]);
      out.failures.push_back(s.failure);
      continue;
    }
    out.point.push_back(i);
    out.frequency_hz.push_back(sine.frequency_hz[i]);
    out.force.push_back(force);
    out.residual.push_back(s.residual);
    out.iterations.push_back(s.iterations);
    record(p, system, s, derivatives, out);
    if (progress && (i + 1) % 25 == 0)
      progress(fmt::format("stepped sine '{}': {:.3f} Hz at {:g} N, point {} of {}", sine.name, sine.frequency_hz[i],
                           force, i + 1, n));
    last = std::move(s);
    last_force = force;
  }
  const Index kept = static_cast<Index>(out.frequency_hz.size());
  for (Eigen::MatrixXd* m : {&out.amplitude, &out.phase_deg, &out.excursion}) m->conservativeResize(kept, n_resp);
  for (auto* v : {&out.amplitude_dlog, &out.phase_dlog_deg})
    for (Eigen::MatrixXd& m : *v) m.conservativeResize(kept, n_resp);
  out.seconds = seconds_since(t0);
  return out;
}

}  // namespace bb
