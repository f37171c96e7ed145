// Everything a finished (or failed) run reports: the input to summary.json and report.md.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checks/check_spec.hpp"
#include "checks/checks.hpp"
#include "study/modal_refinement.hpp"
#include "study/refinement.hpp"

namespace bb {

enum class RunStatus { pass, fail, no_checks, bad_input, solver_failed };
std::string status_name(RunStatus status);
int exit_code(RunStatus status);

struct Plot {
  std::string title;
  std::string file;  // relative to the output folder; empty when not drawn
  std::string note;  // why it was not drawn
  std::string name;  // the file's stem, e.g. "performance_amplitude"; known also when not drawn
};

// A result column written with NaN or inf entries: values that do not apply (no peak found, a
// closed form that does not exist for the row, a run that diverged). Listed in the report so that a
// passing run never hides them; a check that reads one fails.
struct NonFiniteColumn {
  std::string file;  // the CSV, relative to the report folder
  std::string column;
  std::string key_column;
  std::vector<long> keys;  // rows holding a non-finite value
};

struct RunRecord {
  std::filesystem::path case_file;
  std::string case_name;
  std::string title;
  std::string description;
  RunStatus status = RunStatus::bad_input;
  std::string message;                // error message for bad_input / solver_failed
  std::vector<std::string> warnings;  // results to read with care (e.g. a peak next to a failed solve)
  double wall_seconds = 0.0;
  std::string fidelity;  // the settings `--fidelity` chose, e.g. "auto: analysis.harmonics = 5 (est. 3e-4)"; empty: the case's
  std::vector<std::pair<std::string, std::string>> facts;  // inputs and solver statistics
  std::vector<CheckSpec> check_specs;
  std::vector<CheckEntry> checks;
  std::vector<std::string> tables;          // CSV files written
  std::vector<NonFiniteColumn> non_finite;  // their columns with NaN / inf entries
  std::vector<ResultTable> listed_tables;   // shown row by row in the report (tables with text labels)
  std::vector<Plot> plots;
  std::vector<std::string> key_plots;  // names of plots shown under the verdict, before the checks
  std::optional<RefinementResult> study;
  std::string study_note;
  std::vector<Plot> study_plots;
  std::optional<ModalRefinementResult> modal_study;
  std::vector<ResultTable> study_tables;  // other studies: shown as tables under "Study"
};

}  // namespace bb
