#include "report/analysis_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "report/contact_loop_plots.hpp"
#include "report/contact_modal_plots.hpp"
#include "report/contour_plots.hpp"
#include "report/cyclic_plots.hpp"
#include "report/frf_plots.hpp"
#include "report/hbm_plots.hpp"
#include "report/nonlinear_mode_plots.hpp"
#include "report/nonlinear_modal_report.hpp"
#include "report/plots.hpp"
#include "report/rotating_plots.hpp"
#include "report/time_plots.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

struct PlotTarget {
  const Model& model;
  const std::vector<CheckSpec>& checks;
  const fs::path& out;
  RunRecord& run;
  const ResultTables& tables;  // the run's, which hold every outcome's tables
};

Eigen::VectorXd nodal_von_mises(const StressField& field) {
  Eigen::VectorXd v(field.nodal.rows());
  for (Eigen::Index n = 0; n < v.size(); ++n) v[n] = von_mises(field.nodal.row(n));
  return v;
}

void plots(const StaticSpec&, const StaticOutcome& s, const PlotTarget& t) {
  t.run.plots.push_back(plot_deformed_mesh(t.model.mesh, s.solution.displacements, t.out, "deformed", "Deformed mesh"));
  t.run.plots.push_back(plot_nodal_contour(t.model.mesh, nodal_von_mises(s.stresses), "Pa", t.out, "von_mises",
                                           t.model.mesh.dim == 2 ? "von Mises stress (nodal averages)"
                                                                 : "von Mises stress on the surface (nodal averages)"));
}

void plots(const ModalSpec&, const ModalOutcome& outcome, const PlotTarget& t) {
  const ModalResult& modal = outcome.modal;
  for (size_t k = 0; k < std::min<size_t>(4, modal.shapes.size()); ++k)
    t.run.plots.push_back(plot_deformed_mesh(
        t.model.mesh, modal.shapes[k], t.out, fmt::format("mode{}", k + 1),
        fmt::format("Mode {}: {:.4f} Hz", k + 1, modal.frequencies_hz[static_cast<Eigen::Index>(k)])));
  for (const ModeStresses& m : outcome.stresses)
    t.run.plots.push_back(
        plot_nodal_contour(t.model.mesh, nodal_von_mises(m.field), "Pa per unit modal coordinate", t.out,
                           fmt::format("von_mises_mode{}", m.mode),
                           fmt::format("Mode {}: von Mises stress of the mass-normalized shape", m.mode)));
}

void plots(const FrfSpec&, const FrfOutcome& frf, const PlotTarget& t) {
  std::vector<std::string> outputs;  // each response once, in order of appearance
  for (const FrfCurveSet& c : frf.curves)
    for (const std::string& o : c.outputs)
      if (std::find(outputs.begin(), outputs.end(), o) == outputs.end()) outputs.push_back(o);
  for (const std::string& o : outputs) t.run.plots.push_back(plot_frf(frf, o, t.out, "frf_" + o));
  if (!frf.level_forces.empty()) t.run.plots.push_back(plot_force_levels(frf, t.out, "force_levels"));
}

void plots(const ContactLoopSpec&, const ContactLoopOutcome& loop, const PlotTarget& t) {
  t.run.plots.push_back(plot_contact_loop(loop, t.out, "hysteresis"));
}

void plots(const TimeSpec&, const TimeOutcome& time, const PlotTarget& t) {
  for (size_t r = 0; r < time.prepared.response_names.size(); ++r)
    t.run.plots.push_back(plot_time_frf(time, r, t.out, "frf_" + time.prepared.response_names[r]));
  if (time.record && time.record->history.steps > 0 && !time.prepared.contact_names.empty()) {
    t.run.plots.push_back(plot_hysteresis(time, t.out, "hysteresis"));
    t.run.plots.push_back(plot_contact_forces(time, t.out, "contact_forces"));
  }
}

void plots(const HbmSpec& spec, const HbmOutcome& h, const PlotTarget& t) {
  for (size_t r = 0; r < h.prepared.response_names.size(); ++r)
    t.run.plots.push_back(plot_hbm_levels(h, r, false, t.out, "frf_levels_" + h.prepared.response_names[r]));
  t.run.plots.push_back(plot_hbm_levels(h, 0, true, t.out, "frf_per_newton_" + h.prepared.response_names[0]));
  fs::path reference;  // the thesis's peaks, when a check compares with them
  for (const CheckSpec& c : t.checks)
    if (c.result == "peaks" && !c.reference.empty() && reference.empty()) reference = c.reference;
  t.run.plots.push_back(plot_hbm_performance(h, "hz", reference, t.out, "performance_frequency"));
  t.run.plots.push_back(plot_hbm_performance(h, "amp_per_n", reference, t.out, "performance_amplitude"));
  for (const char* kind : {"IP", "OOP", "peak"})
    if ((std::string(kind) == "peak") != h.prepared.ip_oop.has_value())
      t.run.plots.push_back(plot_contact_states(h, kind, t.out, fmt::format("contact_states_{}", kind)));
  if (spec.nonlinear_modes) {
    t.run.plots.push_back(plot_backbones(h, spec, t.tables.at("nonlinear_modes"), t.out, "nonlinear_mode_backbones"));
    t.run.plots.push_back(plot_modal_damping(h, t.out, "nonlinear_mode_damping"));
  }
}

void plots(const RotatingSpec& spec, const RotatingOutcome& o, const PlotTarget& t) {
  for (size_t s = 0; s < o.history_sets.size(); ++s)
    for (int d = 0; d < std::min(o.dim, 2);
         ++d) {  // x and y, as the thesis (the z motion of a blade turning about z is nil)
      const std::string stem = fmt::format("history_{}_u{}", o.history_sets[s], "xyz"[d]);
      t.run.plots.push_back(plot_rotating_history(o, t.tables, s, d, t.out, stem));
      // The first few periods of the first rotating mode, where the oscillation can be seen.
      const double f1 = o.modes_at_speed.frequencies_hz.size() > 0 ? o.modes_at_speed.frequencies_hz[0] : 0.0;
      if (f1 > 0 && spec.end_time > 20.0 / f1)
        t.run.plots.push_back(plot_rotating_history(o, t.tables, s, d, t.out, stem + "_zoom", 20.0 / f1));
    }
  t.run.plots.push_back(plot_campbell(o, spec.engine_orders, t.out, "campbell"));
  t.run.plots.push_back(plot_nodal_contour(t.model.mesh, nodal_von_mises(o.steady_stresses), "Pa", t.out,
                                           "steady_von_mises",
                                           "von Mises stress of the steady centrifugal deflection (nodal averages)"));
}

void plots(const ContactModalSpec& spec, const ContactModalOutcome& o, const PlotTarget& t) {
  for (int m = 1; m <= spec.modes; ++m)
    t.run.plots.push_back(plot_contact_mode(o, spec, m, t.out, fmt::format("contact_mode{}", m)));
  if (t.tables.count("contact_state"))
    t.run.plots.push_back(plot_contact_pressure(o, t.tables.at("contact_state"), t.out, "contact_pressure"));
}

void plots(const CyclicModalSpec& spec, const CyclicModalOutcome& o, const PlotTarget& t) {
  t.run.plots.push_back(plot_nodal_diameter_map(o, spec, t.out, "nodal_diameter_map"));
  if (o.campbell) t.run.plots.push_back(plot_cyclic_campbell(o, spec, t.out, "campbell"));
  // The first family at the lowest and the highest nodal diameter solved.
  if (o.diameters.empty()) return;
  for (size_t i : {size_t{0}, o.diameters.size() - 1}) {
    t.run.plots.push_back(
        plot_sector_wave(o, t.model.mesh, i, 1, t.out, fmt::format("wave_nd{}", o.diameters[i].nodal_diameter)));
    if (o.diameters.size() == 1) break;
  }
}

void plots(const NonlinearModalSpec& spec, const NonlinearModalOutcome& o, const PlotTarget& t) {
  plot_nonlinear_modal(spec, o, t.tables, t.out, t.run);
}

}  // namespace

void plot_analysis(const AnalysisSpec& spec, const AnalysisResults& results, const Model& model,
                   const std::vector<CheckSpec>& checks, const fs::path& out, RunRecord& run) {
  const PlotTarget target{model, checks, out, run, results.tables};
  visit_analysis(spec, results, [&](const auto& s, const auto& outcome) { plots(s, outcome, target); });
}

}  // namespace bb
