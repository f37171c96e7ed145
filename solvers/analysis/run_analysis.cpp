#include "analysis/run_analysis.hpp"

#include <fmt/format.h>

#include "analysis/mode_pairs.hpp"
#include "analysis/stress_tables.hpp"
#include "analysis/work_estimate.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

AnalysisResults run(const StaticSpec& spec, const Model& model, const HbmProgress&, const WorkLimits&,
                    const ModelCacheSettings*) {
  ResultTables tables;
  StaticOutcome o = run_static(model, spec, tables);
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const ModalSpec& spec, const Model& model, const HbmProgress&, const WorkLimits&,
                    const ModelCacheSettings* cache) {
  if (spec.pairs) check_mode_pair_sets(model, *spec.pairs);
  ModalOutcome o{solve_modal(model, spec.modes, spec.options, cache), {}};
  const ModalResult& modal = o.modal;
  ResultTable frequencies = frequency_table(modal.frequencies_hz);
  if (spec.pairs) add_mode_labels(frequencies, label_mode_pairs(model, modal, *spec.pairs));
  ResultTables tables;
  tables.emplace("frequencies", std::move(frequencies));
  tables.emplace("modal_participation", participation_table(modal));
  for (int k : spec.stress_modes) {
    if (k > static_cast<int>(modal.shapes.size()))
      throw InputError(
          fmt::format("'analysis.stress_modes': mode {} asked, the analysis found {} modes", k, modal.shapes.size()));
    o.stresses.push_back({k, recover_stresses(model.mesh, model.section, modal.shapes[static_cast<size_t>(k - 1)])});
    const std::string name = fmt::format("nodal_stresses_mode{}", k);
    tables.emplace(name, nodal_stress_table(name, model.mesh, o.stresses.back().field));
  }
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const FrfSpec& spec, const Model& model, const HbmProgress&, const WorkLimits&,
                    const ModelCacheSettings* cache) {
  if (spec.pairs) check_mode_pair_sets(model, *spec.pairs);
  FrfOutcome o = run_frf(model, spec, {}, cache);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const HbmSpec& spec, const Model& model, const HbmProgress& progress, const WorkLimits&,
                    const ModelCacheSettings* cache) {
  HbmOutcome o = run_hbm(model, spec, progress, cache);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const TimeSpec& spec, const Model& model, const HbmProgress& progress, const WorkLimits&,
                    const ModelCacheSettings* cache) {
  TimeOutcome o = run_time(model, spec, progress, cache);
  ResultTables tables = o.tables;
  std::string failure = o.failure;
  return {std::move(tables), std::move(o), std::move(failure)};
}

AnalysisResults run(const ContactLoopSpec& spec, const Model&, const HbmProgress&, const WorkLimits&,
                    const ModelCacheSettings*) {
  ContactLoopOutcome o = run_contact_loop(spec);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const RotatingSpec& spec, const Model& model, const HbmProgress&, const WorkLimits& limits,
                    const ModelCacheSettings*) {
  RotatingOutcome o = run_rotating(model, spec, limits);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const ContactModalSpec& spec, const Model& model, const HbmProgress& progress, const WorkLimits&,
                    const ModelCacheSettings*) {
  ContactModalOutcome o = run_contact_modal(model, spec, progress);
  ResultTables tables = o.tables;
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const CyclicModalSpec& spec, const Model& model, const HbmProgress&, const WorkLimits&,
                    const ModelCacheSettings*) {
  CyclicModalOutcome o = run_cyclic_modal(model, spec);
  ResultTables tables = cyclic_modal_tables(o);
  return {std::move(tables), std::move(o), {}};
}

}  // namespace

AnalysisResults run_analysis_keeping_tables(const AnalysisSpec& spec, const Model& model, const HbmProgress& progress,
                                            const WorkLimits& limits, const ModelCacheSettings* cache) {
  require_within(estimate_work(spec, model), limits);
  return std::visit([&](const auto& s) { return run(s, model, progress, limits, cache); }, spec);
}

AnalysisResults run_analysis(const AnalysisSpec& spec, const Model& model, const HbmProgress& progress,
                             const WorkLimits& limits, const ModelCacheSettings* cache) {
  AnalysisResults r = run_analysis_keeping_tables(spec, model, progress, limits, cache);
  if (!r.failure.empty()) throw SolverError(r.failure);
  return r;
}

}  // namespace bb
