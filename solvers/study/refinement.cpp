#include "study/refinement.hpp"

#include <cmath>

#include "analysis/static_analysis.hpp"
#include "model/build_model.hpp"
#include "study/timoshenko.hpp"

namespace bb {

RefinementResult run_refinement_study(const ModelSpec& spec, const RefinementStudySpec& s,
                                      const StudyProgress& progress) {
  RefinementResult out;
  const RectangularBeam beam{s.beam_length,
                             s.beam_height,
                             spec.section.thickness,
                             spec.section.youngs_modulus,
                             spec.section.poisson_ratio,
                             s.shear_coefficient};
  out.beam_deflection = timoshenko_tip_deflection(beam, s.beam_load);
  out.bending_only = euler_bernoulli_tip_deflection(beam, s.beam_load);

  const int total = static_cast<int>(s.levels.size());
  if (progress) progress(0, total);
  for (int level : s.levels) {
    ModelSpec refined = spec;
    refined.mesh.mapped.nx *= level;
    refined.mesh.mapped.ny *= level;
    for (LoadSpec& l : refined.loads) {
      if (s.load_split) l.load.split = *s.load_split;
      if (s.load_set) l.load.set = *s.load_set;
    }
    const Model model = build_model(refined);
    const StaticSolution sol = solve_static(model);
    const std::vector<int>& probe = model.node_sets.at(s.probe_set);
    double mean = 0.0;
    for (int n : probe) mean += sol.displacements(n, s.probe_direction);
    mean /= static_cast<double>(probe.size());
    RefinementRow row;
    row.level = level;
    row.nx = refined.mesh.mapped.nx;
    row.ny = refined.mesh.mapped.ny;
    row.n_free_dofs = sol.n_free_dofs;
    row.probe = mean;
    row.error_vs_beam = (mean - out.beam_deflection) / out.beam_deflection;
    row.assembly_seconds = sol.assembly_seconds;
    row.solve_seconds = sol.solve_seconds;
    out.rows.push_back(row);
    if (progress) progress(static_cast<int>(out.rows.size()), total);
  }
  // Observed order from three consecutive levels: p = log(d_{k-1} / d_k) / log(r), d_k = u_k - u_{k-1}.
  for (size_t k = 2; k < out.rows.size(); ++k) {
    const double d1 = out.rows[k - 1].probe - out.rows[k - 2].probe;
    const double d2 = out.rows[k].probe - out.rows[k - 1].probe;
    const double r = static_cast<double>(out.rows[k].level) / out.rows[k - 1].level;
    const double r_prev = static_cast<double>(out.rows[k - 1].level) / out.rows[k - 2].level;
    if (d1 != 0.0 && d2 != 0.0 && d1 * d2 > 0 && std::abs(r - r_prev) < 1e-12 && r > 1)
      out.rows[k].observed_order = std::log(d1 / d2) / std::log(r);
  }
  const RefinementRow& last = out.rows.back();
  const RefinementRow& prev = out.rows[out.rows.size() - 2];
  const double r = static_cast<double>(last.level) / prev.level;
  out.extrapolation_order = last.observed_order > 0 ? last.observed_order : 2.0;
  out.extrapolated = last.probe + (last.probe - prev.probe) / (std::pow(r, out.extrapolation_order) - 1.0);
  for (RefinementRow& row : out.rows) row.error_vs_limit = (row.probe - out.extrapolated) / out.extrapolated;
  return out;
}

}  // namespace bb
