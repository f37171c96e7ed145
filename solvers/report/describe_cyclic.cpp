#include "report/describe_cyclic.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace bb {

void describe(const CyclicModalSpec& spec, const CyclicModalOutcome& o, RunRecord& run) {
  run.facts.emplace_back("analysis",
                         fmt::format("cyclic modal: {} sectors of {:.6g} deg about z, {} families per nodal diameter, "
                                     "faces '{}' / '{}'; Lanczos shift-invert (Spectra + CHOLMOD) per nodal diameter",
                                     spec.sectors, 360.0 / spec.sectors, spec.families, spec.left, spec.right));
  run.facts.emplace_back("sector free DOFs", std::to_string(o.dofs.n_free));
  int counted = 0, found = 0;
  double residual = 0.0;
  for (const NodalDiameterModes& nd : o.diameters) {
    counted += nd.sturm_count >= 0;
    found += nd.lanczos_runs > 1;
    residual = std::max(residual, nd.max_residual);
  }
  run.facts.emplace_back("completeness (Sturm count per nodal diameter)",
                         fmt::format("{} of {} nodal diameters counted, every mode below each count found ({} needed "
                                     "more than one Lanczos run)",
                                     counted, o.diameters.size(), found));
  run.facts.emplace_back("max eigen-residual (backward error)", fmt::format("{:.3e}", residual));
  run.facts.emplace_back("assembly / eigensolves [s]",
                         fmt::format("{:.4f} / {:.4f}", o.assembly_seconds, o.solve_seconds));
  if (o.whole) {
    const WholeStructureCheck& w = *o.whole;
    double worst = 0.0;
    for (Eigen::Index i = 0; i < std::min(w.whole_hz.size(), w.union_hz.size()); ++i)
      worst = std::max(worst, std::abs(w.whole_hz[i] - w.union_hz[i]) / w.whole_hz[i]);
    run.facts.emplace_back(
        "whole structure (N turned copies merged)",
        fmt::format("{} free DOFs, {:.3f} s: {} modes below {:.6g} Hz (Sturm), the nodal diameters' counts sum to {}; "
                    "largest relative difference of the {} frequencies {:.2e}",
                    w.free_dofs, w.seconds, w.whole_count, w.cut_hz, w.sector_count_sum, w.whole_hz.size(), worst));
  }
  if (o.campbell)
    run.facts.emplace_back(
        "Campbell diagram",
        fmt::format("{} speeds to {:g} rpm per nodal diameter: K + Omega^2 (K_sigma1 - M_p), the "
                    "pre-stress of the in-phase centrifugal deflection (largest {:.3g} m at 1 rad/s, "
                    "x Omega^2), no Coriolis; {} engine-order crossings",
                    o.campbell->speeds.size(), spec.speeds_rpm.back(), o.campbell->max_unit_speed_deflection,
                    o.crossings.size()));
  if (!spec.engine_orders.empty())
    run.facts.emplace_back("interference (stationary frequencies, no stiffening)",
                           fmt::format("{} resonances of engine orders {} up to {:g} rpm", o.resonances.size(),
                                       fmt::join(spec.engine_orders, ", "), spec.max_speed_rpm));
}

}  // namespace bb
