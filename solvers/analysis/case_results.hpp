// The analysis a case asks for, run on its model, as result tables in memory (no files).
#pragma once
#include <optional>

#include "analysis/contact_loop_analysis.hpp"
#include "analysis/frf_analysis.hpp"
#include "analysis/hbm_analysis.hpp"
#include "analysis/time_analysis.hpp"
#include "analysis/modal_analysis.hpp"
#include "analysis/static_analysis.hpp"
#include "cases/case_spec.hpp"
#include "results/table.hpp"

namespace bb {

struct CaseResults {
  ResultTables tables;
  std::optional<StaticSolution> static_solution;
  std::optional<ModalResult> modal;
  std::optional<FrfOutcome> frf;
  std::optional<HbmOutcome> hbm;
  std::optional<TimeOutcome> time;
  std::optional<ContactLoopOutcome> contact_loop;
};

// `progress` receives the progress lines of long sweeps (none when empty).
CaseResults compute_case_results(const CaseSpec& spec, const Model& model, const HbmProgress& progress = {});

}  // namespace bb
