#include "analysis/run_analysis.hpp"

#include <fmt/format.h>

#include "analysis/mode_pairs.hpp"
#include "analysis/stress_tables.hpp"
#include "analysis/work_estimate.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

// An outcome whose tables the analysis built into it: moved into the results, held there only.
template <class Outcome>
AnalysisResults results_of(Outcome o, std::string failure = {}) {
  ResultTables tables = std::move(o.tables);
  return {std::move(tables), std::move(o), std::move(failure)};
}

// What every analysis may use besides its spec.
struct RunContext {
  const Model& model;
  const HbmProgress& progress;
  const WorkLimits& limits;
  const ModelCacheSettings* cache;
};

AnalysisResults run(const StaticSpec& spec, const RunContext& c) {
  ResultTables tables;
  StaticOutcome o = run_static(c.model, spec, tables);
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const ModalSpec& spec, const RunContext& c) {
  if (spec.pairs) check_mode_pair_sets(c.model, *spec.pairs);
  ModalOutcome o{solve_modal(c.model, spec.modes, spec.options, c.cache), {}};
  const ModalResult& modal = o.modal;
  ResultTable frequencies = frequency_table(modal.frequencies_hz);
  if (spec.pairs) add_mode_labels(frequencies, label_mode_pairs(c.model, modal, *spec.pairs));
  ResultTables tables;
  tables.emplace("frequencies", std::move(frequencies));
  tables.emplace("modal_participation", participation_table(modal));
  for (int k : spec.stress_modes) {
    if (k > static_cast<int>(modal.shapes.size()))
      throw InputError(
          fmt::format("'analysis.stress_modes': mode {} asked, the analysis found {} modes", k, modal.shapes.size()));
    o.stresses.push_back(
        {k, recover_stresses(c.model.mesh, c.model.section, modal.shapes[static_cast<size_t>(k - 1)])});
    const std::string name = fmt::format("nodal_stresses_mode{}", k);
    tables.emplace(name, nodal_stress_table(name, c.model.mesh, o.stresses.back().field));
  }
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const FrfSpec& spec, const RunContext& c) {
  if (spec.pairs) check_mode_pair_sets(c.model, *spec.pairs);
  return results_of(run_frf(c.model, spec, {}, c.cache));
}

AnalysisResults run(const HbmSpec& spec, const RunContext& c) {
  return results_of(run_hbm(c.model, spec, c.progress, c.cache));
}

AnalysisResults run(const TimeSpec& spec, const RunContext& c) {
  TimeOutcome o = run_time(c.model, spec, c.progress, c.cache);
  std::string failure = o.failure;
  return results_of(std::move(o), std::move(failure));
}

AnalysisResults run(const ContactLoopSpec& spec, const RunContext&) { return results_of(run_contact_loop(spec)); }

AnalysisResults run(const RotatingSpec& spec, const RunContext& c) {
  return results_of(run_rotating(c.model, spec, c.limits));
}

AnalysisResults run(const ContactModalSpec& spec, const RunContext& c) {
  return results_of(run_contact_modal(c.model, spec, c.progress));
}

AnalysisResults run(const CyclicModalSpec& spec, const RunContext& c) {
  CyclicModalOutcome o = run_cyclic_modal(c.model, spec);
  ResultTables tables = cyclic_modal_tables(o);
  return {std::move(tables), std::move(o), {}};
}

AnalysisResults run(const NonlinearModalSpec& spec, const RunContext&) {
  return results_of(run_nonlinear_modal(spec));
}

}  // namespace

AnalysisResults run_analysis_keeping_tables(const AnalysisSpec& spec, const Model& model, const HbmProgress& progress,
                                            const WorkLimits& limits, const ModelCacheSettings* cache) {
  require_within(estimate_work(spec, model), limits);
  const RunContext context{model, progress, limits, cache};
  return std::visit([&](const auto& s) { return run(s, context); }, spec);
}

AnalysisResults run_analysis(const AnalysisSpec& spec, const Model& model, const HbmProgress& progress,
                             const WorkLimits& limits, const ModelCacheSettings* cache) {
  AnalysisResults r = run_analysis_keeping_tables(spec, model, progress, limits, cache);
  if (!r.failure.empty()) throw SolverError(r.failure);
  return r;
}

}  // namespace bb
