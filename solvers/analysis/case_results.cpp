#include "analysis/case_results.hpp"

#include "analysis/mode_pairs.hpp"

namespace bb {

CaseResults compute_case_results(const CaseSpec& spec, const Model& model, const HbmProgress& progress) {
  CaseResults out;
  if (spec.analysis.type == AnalysisType::static_linear) {
    out.static_solution = solve_static(model);
    out.tables.emplace("nodal_displacements", nodal_displacement_table(model.mesh, out.static_solution->displacements));
  } else if (spec.analysis.type == AnalysisType::contact_loop) {
    out.contact_loop = run_contact_loop(spec.analysis.contact_loop);
    out.tables = out.contact_loop->tables;
  } else if (spec.analysis.type == AnalysisType::time) {
    out.time = run_time(model, spec.analysis.time, progress);
    out.tables = out.time->tables;
  } else if (spec.analysis.type == AnalysisType::hbm) {
    out.hbm = run_hbm(model, spec.analysis.hbm, progress);
    out.tables = out.hbm->tables;
  } else if (spec.analysis.type == AnalysisType::frf) {
    out.frf = run_frf(model, spec.analysis.frf, spec.analysis.pairs);
    out.tables = out.frf->tables;
  } else {
    out.modal = solve_modal(model, spec.analysis.modes, spec.analysis.modal);
    ResultTable frequencies = frequency_table(out.modal->frequencies_hz);
    if (spec.analysis.pairs) add_mode_labels(frequencies, label_mode_pairs(model, *out.modal, *spec.analysis.pairs));
    out.tables.emplace("frequencies", std::move(frequencies));
    out.tables.emplace("modal_participation", participation_table(*out.modal));
  }
  return out;
}

}  // namespace bb
