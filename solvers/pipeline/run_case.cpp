#include "pipeline/run_case.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "analysis/run_analysis.hpp"
#include "cases/case_settings.hpp"
#include "cases/case_spec.hpp"
#include "cases/parse_calibration.hpp"
#include "checks/checks.hpp"
#include "checks/mode_matching.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "identify/fit_points.hpp"
#include "model/build_model.hpp"
#include "pipeline/run_fidelity.hpp"
#include "pipeline/run_study.hpp"
#include "report/analysis_files.hpp"
#include "report/vtk_files.hpp"
#include "report/analysis_plots.hpp"
#include "report/describe_analysis.hpp"
#include "report/fidelity_plots.hpp"
#include "report/html_page.hpp"
#include "report/output_folder.hpp"
#include "report/plots.hpp"
#include "report/writers.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// Long sweeps report progress on a terminal only (one line, rewritten in place).
HbmProgress terminal_progress() {
  if (!isatty(STDERR_FILENO)) return {};
  return [](const std::string& line) { std::fprintf(stderr, "\r\033[K%s", line.c_str()); };
}

// The run's fidelity: the frontier table, its plot, the facts, and in automatic mode an entry that
// fails when the estimated error misses the target.
void report_fidelity(const FidelitySpec& f, FidelityMode mode, const FidelityChoice& choice, const fs::path& out,
                     bool plots, RunRecord& run) {
  const char* mode_name = fidelity_mode_name(mode);
  run.fidelity = fmt::format("{}: {}", mode_name, choice.settings);
  if (mode == FidelityMode::automatic) run.fidelity += fmt::format(" (est. {:.2g})", choice.estimated_error);
  run.facts.emplace_back("fidelity", fmt::format("--fidelity {}: {}", mode_name, choice.settings));
  if (mode == FidelityMode::automatic) {
    run.facts.emplace_back(
        "fidelity target",
        fmt::format("{:.3g} on {} of {} (the sum over the {} axes of each one's error, extrapolated from its "
                    "differences between levels); estimated error {:.3g}{}",
                    f.target, fmt::join(f.columns, ", "), f.result, f.axes.size(), choice.estimated_error,
                    choice.met ? "" : ": NOT MET"));
    CheckEntry e;
    e.group = "Fidelity target";
    e.name = fmt::format("Fidelity target: estimated error of {} ({})", f.result, choice.settings);
    e.column = "estimated_error";
    e.computed = choice.estimated_error;
    e.abs_error = choice.estimated_error;
    e.rel_error = choice.estimated_error;
    e.tolerance = f.target;
    e.relation = CheckSpec::Relation::at_most;
    e.pass = choice.met;
    run.checks.push_back(e);
    if (!choice.met) {
      const double estimate = choice.estimated_error;
      const char* why = std::isnan(estimate)       ? " (an axis at its finest level has too few levels to extrapolate)"
                        : std::isfinite(estimate)  ? ""
                        : !choice.failures.empty() ? " (a finer level's solve failed, so its difference is unknown)"
                                                   : " (the differences between levels do not fall as a power law)";
      run.warnings.push_back(
          fmt::format("the fidelity target {:.3g} is not met: the estimated error at the levels reached is {:.3g}{}",
                      f.target, estimate, why));
    }
  }
  for (const std::string& failure : choice.failures)
    run.warnings.push_back(fmt::format("fidelity: a level passed over because its solve failed ({})", failure));
  if (!f.note.empty()) run.facts.emplace_back("fidelity note", f.note);
  write_result_csv(choice.frontier, out, run);
  run.listed_tables.push_back(choice.frontier);
  if (plots) run.plots.push_back(plot_fidelity_frontier(choice.frontier, f, out, "fidelity_frontier"));
}

// The plots [case] key_plots names, each one this run draws (InputError naming the line, with the
// plots it draws, otherwise); none named: the first plot.
std::vector<std::string> key_plots(const CaseSpec& spec, const std::vector<Plot>& plots) {
  if (spec.key_plots.empty()) return plots.empty() ? std::vector<std::string>{} : std::vector{plots.front().name};
  std::vector<std::string> drawn;
  for (const Plot& p : plots) drawn.push_back(p.name);
  for (const std::string& name : spec.key_plots)
    if (std::find(drawn.begin(), drawn.end(), name) == drawn.end())
      throw InputError(fmt::format("{}: [case] key_plots: '{}' is not a plot of this analysis; it draws {}",
                                   spec.key_plots_at.where(), name,
                                   drawn.empty() ? std::string("none") : fmt::format("{}", fmt::join(drawn, ", "))));
  return spec.key_plots;
}

// Throws InputError after the result tables are written when a check cannot be evaluated on
// them (an unknown result column, say): the solved tables are kept, the verdict is bad input.
void analyse(const CaseSpec& spec, const std::optional<CalibrationSpec>& calibration, const Model& model,
             const AnalysisResults& results, const fs::path& out, const RunOptions& options, RunRecord& run,
             bool& results_written) {
  describe_analysis(spec.analysis, results, model, run);
  // Runs of the cases some checks compare with (their analyses only), each run once.
  struct OtherRun {
    Model model;
    AnalysisResults results;
  };
  std::map<fs::path, OtherRun> other_cases;
  auto other_run = [&](const fs::path& file) -> const OtherRun& {
    auto it = other_cases.find(file);
    if (it == other_cases.end()) {
      const CaseSpec other = parse_case_file(file);
      Model other_model = build_model(other.model);
      AnalysisResults other_results =
          run_analysis(other.analysis, other_model, {}, options.limits, cache_or_none(options.cache));
      it = other_cases.emplace(file, OtherRun{std::move(other_model), std::move(other_results)}).first;
    }
    return it->second;
  };
  // Mode pairings by shape (match = "mac"): one per reference case, written as mac_<case>.csv.
  ResultTables tables = results.tables;
  std::map<fs::path, ModeMatch> mode_matches;
  for (const CheckSpec& c : spec.checks) {
    if (c.match != CheckSpec::Match::mac || mode_matches.count(c.reference_case)) continue;
    const OtherRun& other = other_run(c.reference_case);
    const auto* mine = std::get_if<ModalOutcome>(&results.outcome);
    const auto* theirs = std::get_if<ModalOutcome>(&other.results.outcome);
    if (!mine || !theirs)
      throw InputError(
          fmt::format("{}: check '{}': match = \"mac\" pairs the modes of two modal analyses; {} is not one",
                      c.at.where(), c.name, !mine ? "this case" : c.reference_case.filename().string()));
    const ModeMatch m = match_modes_by_shape(model.mesh, mine->modal, other.model.mesh, theirs->modal);
    const std::string name = "mac_" + c.reference_case.stem().string();
    tables.emplace(name, mode_match_table(name, m, mine->modal, theirs->modal));
    run.facts.emplace_back(fmt::format("modes paired by shape with {}", c.reference_case.filename().string()),
                           fmt::format("MAC over the {} nodes the meshes share ({}.csv)", m.common_nodes, name));
    mode_matches.emplace(c.reference_case, m);
  }
  std::vector<std::string> unevaluated;
  for (const CheckSpec& c : spec.checks) {
    // A part the command line removed (--unset) takes its results, and the checks on them, along.
    if (!options.removals.empty() && c.reference_case.empty() && !tables.count(c.result)) {
      run.warnings.push_back(
          fmt::format("check '{}' not evaluated: --unset removed its result '{}'", c.name, c.result));
      continue;
    }
    const ResultTables* reference = c.reference_case.empty() ? nullptr : &other_run(c.reference_case).results.tables;
    std::optional<RowMatch> pairing;
    if (c.match == CheckSpec::Match::mac) {
      const ModeMatch& m = mode_matches.at(c.reference_case);
      pairing.emplace();
      for (size_t j = 0; j < m.computed_of_reference.size(); ++j) {
        const long ref_mode = static_cast<long>(j) + 1;
        const int k = m.computed_of_reference[j];
        if (k >= 0 && m.match_mac[j] >= c.min_mac) pairing->computed_key[ref_mode] = k + 1;
        pairing->note[ref_mode] = k >= 0
                                      ? fmt::format("MAC {:.4f}{}", m.match_mac[j],
                                                    m.match_mac[j] >= c.min_mac ? "" : fmt::format(" < {}", c.min_mac))
                                      : std::string("no mode left to pair");
      }
    }
    try {
      auto entries = evaluate_check(c, tables, reference, pairing ? &*pairing : nullptr);
      run.checks.insert(run.checks.end(), entries.begin(), entries.end());
    } catch (const InputError& e) {
      unevaluated.emplace_back(e.what());
    }
  }
  // The curves a [calibration] would fit must exist, as `calibrate` requires.
  if (calibration) {
    for (const CalibrationData& d : calibration->data) {
      try {
        require_data_columns(d, tables);
      } catch (const InputError& e) {
        unevaluated.emplace_back(e.what());
      }
    }
  }
  for (const auto& [name, table] : tables) {
    write_result_csv(table, out, run);
    if (!table.text_columns.empty()) run.listed_tables.push_back(table);
  }
  results_written = true;
  if (!unevaluated.empty())
    throw InputError(fmt::format("{} (the result tables are written; no check verdict)", fmt::join(unevaluated, "; ")));
  write_analysis_files(spec.analysis, results, out, run);
  if (spec.vtk || options.vtk) write_vtk_files(spec.analysis, results, model, out, run);
  if (options.plots) {
    plot_analysis(spec.analysis, results, model, spec.checks, out, run);
    int i = 0;
    for (const CheckSpec& c : spec.checks)
      run.plots.push_back(plot_check(run.checks, c.name, out, fmt::format("check{}", ++i)));
    run.key_plots = key_plots(spec, run.plots);
  }
  if (options.study && spec.study) {
    const HbmProgress progress = terminal_progress();
    run_study(*spec.study, spec, model, results, out, options.plots, run, progress, options.limits,
              cache_or_none(options.cache));
    if (progress) std::fputs("\r\033[K", stderr);
  }
  bool all_pass = true;
  for (const CheckEntry& e : run.checks) all_pass = all_pass && e.pass;
  run.status = run.checks.empty() ? RunStatus::no_checks : (all_pass ? RunStatus::pass : RunStatus::fail);
}

// A case refused before its tables are written reports the refusal and nothing that looks like a
// result: what was written before the error was found goes with its temporary folder, and the
// record forgets it. (A check that cannot be evaluated after the solve keeps the tables.)
void drop_results(RunRecord& run) {
  run.checks.clear();
  run.tables.clear();
  run.non_finite.clear();
  run.listed_tables.clear();
  run.plots.clear();
  run.study.reset();
  run.modal_study.reset();
  run.study_tables.clear();
  run.study_plots.clear();
}

}  // namespace

RunOutcome run_case(const fs::path& case_file, const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  RunOutcome outcome;
  RunRecord& run = outcome.record;
  run.case_file = case_file;
  run.case_name = case_file.stem().string();
  run.title = run.case_name;
  outcome.out_dir = options.out_dir.value_or(fs::path("reports") / run.case_name);
  // Everything is written to a temporary sibling of the report folder, moved into place at the end.
  std::optional<StagedFolder> stage;
  std::vector<fs::path> inputs{case_file};  // what the report folder must not hold (it replaces it whole)
  bool results_written = false;
  try {
    toml::table case_table = read_case_table(case_file);
    apply_settings(case_table, options.settings, options.removals);
    for (const std::string& setting : options.settings)
      run.warnings.push_back(fmt::format("--set {}: the case ran at this setting, not the file's", setting));
    for (const std::string& key : options.removals)
      run.warnings.push_back(fmt::format("--unset {}: the case ran without it", key));
    const CaseSpec spec = parse_case_table(case_table, case_file);
    // A bad [calibration] or data file, or a reference that cannot be read, fails here, before any
    // solve, in `run` as in `calibrate`.
    const std::optional<CalibrationSpec> calibration = parse_calibration(case_table, case_file, spec);
    require_linked_cases(case_file, spec, calibration);
    run.case_name = spec.name;
    run.title = spec.title;
    run.description = spec.description;
    run.check_specs = spec.checks;
    outcome.out_dir = options.out_dir.value_or(fs::path("reports") / spec.name);
    for (const CheckSpec& c : spec.checks) inputs.insert(inputs.end(), {c.reference, c.reference_case});
    stage.emplace(outcome.out_dir, inputs);
    const HbmProgress progress = terminal_progress();
    std::optional<FidelityChoice> choice;
    if (options.fidelity != FidelityMode::fixed && !spec.fidelity)
      run.warnings.push_back("--fidelity: the case has no [fidelity] section; it ran at its own settings");
    if (options.fidelity != FidelityMode::fixed && spec.fidelity)
      choice.emplace(run_with_fidelity(spec, options.fidelity, progress, options.limits, cache_or_none(options.cache)));
    const CaseSpec& used = choice ? choice->spec : spec;
    const Model model = choice ? std::move(choice->model) : build_model(spec.model);
    describe_model(used.model, std::holds_alternative<ContactLoopSpec>(used.analysis), model, run);
    try {
      const AnalysisResults results = choice
                                          ? std::move(choice->results)
                                          : run_analysis_keeping_tables(used.analysis, model, progress, options.limits,
                                                                        cache_or_none(options.cache));
      if (progress) std::fputs("\r\033[K", stderr);
      if (choice) report_fidelity(*spec.fidelity, options.fidelity, *choice, stage->path(), options.plots, run);
      analyse(used, calibration, model, results, stage->path(), options, run, results_written);
      // What was solved is written; a result that failed after its tables were built leaves the
      // case without a verdict.
      if (!results.failure.empty()) {
        run.checks.clear();
        throw SolverError(results.failure);
      }
    } catch (const InputError& e) {
      // Errors found by the solvers concern the model as a whole: name the case they came from.
      const std::string what = e.what();
      throw InputError(what.starts_with(case_file.string()) ? what : fmt::format("{}: {}", case_file.string(), what));
    }
  } catch (const InputError& e) {
    run.status = RunStatus::bad_input;
    run.message = printable(e.what());
  } catch (const SolverError& e) {
    run.status = RunStatus::solver_failed;
    run.message = printable(e.what());
  } catch (const std::exception& e) {
    run.status = RunStatus::solver_failed;
    run.message = printable(fmt::format("internal error: {}", e.what()));
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (run.status == RunStatus::bad_input && !results_written) {
    stage.reset();
    drop_results(run);
  }
  try {
    if (!stage) stage.emplace(outcome.out_dir, inputs);
    write_report_md(run, stage->path() / "report.md");
    write_html_twin(stage->path() / "report.md");
    write_summary_json(run, stage->path() / "summary.json");
    stage->commit();
    outcome.written = true;
  } catch (const OutputError& e) {
    // Nowhere to write: the message (also of an earlier error) goes to the terminal only.
    const std::string what = printable(e.what());
    if (run.message != what)
      run.message = run.message.empty() ? what : fmt::format("{}; and no report: {}", run.message, what);
    run.status = RunStatus::bad_input;
  } catch (const std::exception& e) {
    run.status = RunStatus::solver_failed;
    run.message = printable(fmt::format("could not write the report: {}", e.what()));
  }
  return outcome;
}

}  // namespace bb
