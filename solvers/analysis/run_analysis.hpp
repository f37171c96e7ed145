// The analysis a case asks for, run on its model: result tables in memory (no files), and the
// analysis's own outcome for the report. One outcome type per analysis type, in the order of
// AnalysisSpec; OutcomeOf<Spec> names it.
#pragma once
#include <functional>
#include <string>
#include <variant>

#include "analysis/analysis_spec.hpp"
#include "analysis/contact_loop_analysis.hpp"
#include "analysis/contact_modal_analysis.hpp"
#include "analysis/cyclic_modal_analysis.hpp"
#include "analysis/frf_analysis.hpp"
#include "analysis/hbm_analysis.hpp"
#include "analysis/modal_analysis.hpp"
#include "analysis/nonlinear_modal_analysis.hpp"
#include "analysis/rotating_analysis.hpp"
#include "analysis/static_analysis.hpp"
#include "analysis/time_analysis.hpp"
#include "common/work_limits.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

using AnalysisOutcome = std::variant<StaticOutcome, ModalOutcome, FrfOutcome, HbmOutcome, TimeOutcome,
                                     ContactLoopOutcome, RotatingOutcome, ContactModalOutcome, CyclicModalOutcome,
                                     NonlinearModalOutcome>;

template <typename Spec>
struct OutcomeOf;
template <>
struct OutcomeOf<StaticSpec> {
  using type = StaticOutcome;
};
template <>
struct OutcomeOf<ModalSpec> {
  using type = ModalOutcome;
};
template <>
struct OutcomeOf<FrfSpec> {
  using type = FrfOutcome;
};
template <>
struct OutcomeOf<HbmSpec> {
  using type = HbmOutcome;
};
template <>
struct OutcomeOf<TimeSpec> {
  using type = TimeOutcome;
};
template <>
struct OutcomeOf<ContactLoopSpec> {
  using type = ContactLoopOutcome;
};
template <>
struct OutcomeOf<RotatingSpec> {
  using type = RotatingOutcome;
};
template <>
struct OutcomeOf<ContactModalSpec> {
  using type = ContactModalOutcome;
};
template <>
struct OutcomeOf<CyclicModalSpec> {
  using type = CyclicModalOutcome;
};
template <>
struct OutcomeOf<NonlinearModalSpec> {
  using type = NonlinearModalOutcome;
};
static_assert(std::variant_size_v<AnalysisOutcome> == std::variant_size_v<AnalysisSpec>,
              "one outcome per analysis type");

struct AnalysisResults {
  ResultTables tables;  // every table of the run, held here only: the outcome's own are moved in
  AnalysisOutcome outcome;
  // A solver failure found once the tables were built (a time analysis's peak resting on a
  // frequency without a steady state): the tables stand, the case has no verdict. Empty: none.
  std::string failure;
};

// Calls fn(spec, outcome) with the matching alternatives of both.
template <typename Fn>
decltype(auto) visit_analysis(const AnalysisSpec& spec, const AnalysisResults& results, Fn&& fn) {
  return std::visit(
      [&](const auto& s) -> decltype(auto) {
        using Spec = std::decay_t<decltype(s)>;
        return fn(s, std::get<typename OutcomeOf<Spec>::type>(results.outcome));
      },
      spec);
}

// Runs the analysis. `progress` receives the progress lines of long sweeps (none when empty).
// Throws InputError for a spec the model cannot serve (unknown points, sets) or whose estimated
// work or memory exceeds `limits` (before any solve), SolverError when a solver fails in a way the
// analysis does not report in its tables. Modes and Craig-Bampton reductions go through the model
// cache in `cache`, when given.
AnalysisResults run_analysis(const AnalysisSpec& spec, const Model& model, const HbmProgress& progress = {},
                             const WorkLimits& limits = {}, const ModelCacheSettings* cache = nullptr);

// The same, but a failure found once the tables were built is returned in `failure` with them,
// not thrown: a run that writes its tables keeps what was solved.
AnalysisResults run_analysis_keeping_tables(const AnalysisSpec& spec, const Model& model,
                                            const HbmProgress& progress = {}, const WorkLimits& limits = {},
                                            const ModelCacheSettings* cache = nullptr);

}  // namespace bb
