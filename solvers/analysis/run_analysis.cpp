#include "analysis/run_analysis.hpp"

#include "analysis/mode_pairs.hpp"

namespace bb {
namespace {

AnalysisResults run(const StaticSpec&, const Model& model, const HbmProgress&) {
  StaticSolution s = solve_static(model);
  ResultTables tables;
  tables.emplace("nodal_displacements", nodal_displacement_table(model.mesh, s.displacements));
  return {std::move(tables), std::move(s)};
}

AnalysisResults run(const ModalSpec& spec, const Model& model, const HbmProgress&) {
  if (spec.pairs) check_mode_pair_sets(model, *spec.pairs);
  ModalResult modal = solve_modal(model, spec.modes, spec.options);
  ResultTable frequencies = frequency_table(modal.frequencies_hz);
  if (spec.pairs) add_mode_labels(frequencies, label_mode_pairs(model, modal, *spec.pairs));
  ResultTables tables;
  tables.emplace("frequencies", std::move(frequencies));
  tables.emplace("modal_participation", participation_table(modal));
  return {std::move(tables), std::move(modal)};
}

AnalysisResults run(const FrfSpec& spec, const Model& model, const HbmProgress&) {
  if (spec.pairs) check_mode_pair_sets(model, *spec.pairs);
  FrfOutcome o = run_frf(model, spec);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o)};
}

AnalysisResults run(const HbmSpec& spec, const Model& model, const HbmProgress& progress) {
  HbmOutcome o = run_hbm(model, spec, progress);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o)};
}

AnalysisResults run(const TimeSpec& spec, const Model& model, const HbmProgress& progress) {
  TimeOutcome o = run_time(model, spec, progress);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o)};
}

AnalysisResults run(const ContactLoopSpec& spec, const Model&, const HbmProgress&) {
  ContactLoopOutcome o = run_contact_loop(spec);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o)};
}

AnalysisResults run(const RotatingSpec& spec, const Model& model, const HbmProgress&) {
  RotatingOutcome o = run_rotating(model, spec);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o)};
}

}  // namespace

AnalysisResults run_analysis(const AnalysisSpec& spec, const Model& model, const HbmProgress& progress) {
  return std::visit([&](const auto& s) { return run(s, model, progress); }, spec);
}

}  // namespace bb
