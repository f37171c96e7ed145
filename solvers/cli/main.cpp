// bladebench command line: run and validate cases, compare report folders, calibrate, synthesize
// data, export decks. Exit codes in common/errors.hpp. Progress goes to the terminal only: the
// library reports through callbacks.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <numbers>
#include <optional>

#include "analysis/run_analysis.hpp"
#include "cache/model_cache_settings.hpp"
#include "cases/case_spec.hpp"
#include "cli/command_options.hpp"
#include "cli/compare_command.hpp"
#include "cli/compare_models_command.hpp"
#include "cli/validate_command.hpp"
#include "common/errors.hpp"
#include "common/progress_clock.hpp"
#include "common/user_text.hpp"
#include "distributed/distributed.hpp"
#include "identify/synthetic_data.hpp"
#include "identify/uff58.hpp"
#include "model/build_model.hpp"
#include "pipeline/calibrate_case.hpp"
#include "pipeline/run_case.hpp"
#include "report/calculix_export.hpp"
#include "report/calibration_report.hpp"
#include "report/html_page.hpp"
#include "report/output_folder.hpp"
#include "report/writers.hpp"

namespace fs = std::filesystem;
using namespace bb::cli;

namespace {

int html_command(const std::string& folder) {
  std::vector<std::string> notes;
  const std::vector<fs::path> pages = bb::write_html_twins(folder, &notes);
  for (const std::string& note : notes) std::fprintf(stderr, "warning: %s\n", note.c_str());
  if (pages.empty())
    throw bb::InputError(fmt::format("{}: no report.md or index.md under this folder", bb::printable(folder)));
  std::printf("%zu pages written (report.html / index.html beside each report.md / index.md under %s)\n", pages.size(),
              bb::printable(folder).c_str());
  return 0;
}

struct RunArgs {
  std::vector<std::string> cases;
  std::string out;
  bool study = false, no_plots = false, vtk = false;
  bb::FidelityMode fidelity = bb::FidelityMode::fixed;
  bb::WorkLimits limits;
  std::vector<std::string> settings, removals;
  std::optional<bb::ModelCacheSettings> cache;
};

// Under mpirun every rank runs the case (its eigensolves shared by all ranks); rank 0 writes the
// report, the others write into a folder of their own that is removed afterwards.
struct RankFolder {
  fs::path path;
  RankFolder() {
    if (bb::distributed::is_root()) return;
    path = fs::temp_directory_path() /
           fmt::format("bladebench-rank{}-{}", bb::distributed::rank(), static_cast<long>(::getpid()));
  }
  ~RankFolder() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

int run_command(const RunArgs& a) {
  // With several cases --out is the parent of their report folders; with one, the folder itself
  // (checked by the run, which then reports where it could not write).
  const RankFolder rank_folder;
  const bool root = rank_folder.path.empty();
  if (root && a.cases.size() > 1 && !a.out.empty()) bb::prepare_output_parent(a.out, "--out");
  int rc = bb::exit_pass;
  for (const std::string& c : a.cases) {
    bb::RunOptions opt;
    opt.study = a.study;
    opt.plots = root && !a.no_plots;
    opt.vtk = a.vtk;
    opt.fidelity = a.fidelity;
    opt.limits = a.limits;
    opt.cache = a.cache;
    opt.settings = a.settings;
    opt.removals = a.removals;
    if (!a.out.empty()) opt.out_dir = a.cases.size() == 1 ? fs::path(a.out) : fs::path(a.out) / fs::path(c).stem();
    if (!root) opt.out_dir = rank_folder.path / fs::path(c).stem();
    const bb::RunOutcome o = bb::run_case(c, opt);
    if (root) print_outcome(o, "");
    if (root && bb::distributed::size() > 1 && bb::distributed::shared_work_count() == 0)
      std::fprintf(stderr,
                   "  warning: %d MPI ranks, but this case shares no work over them (no eigensolver = \"slepc\", no "
                   "force levels to share out): every rank computed the same\n",
                   bb::distributed::size());
    rc = std::max(rc, bb::exit_code(o.record.status));
  }
  return rc;
}

struct CalibrateArgs {
  std::string case_file, out;
  bool no_plots = false;
  bb::WorkLimits limits;  // of each evaluation of the model
  std::optional<bb::ModelCacheSettings> cache;
  bb::CalibrationStartEdits edits;  // --set, --restart-from
};

int calibrate_command(const CalibrateArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  // Under mpirun the ranks share the starts out (identify/least_squares_fit.cpp); each rank's model
  // runs stay on that rank; rank 0 writes.
  bb::distributed::set_shared_solves(bb::distributed::size() == 1);
  const RankFolder rank_folder;
  const bool root = rank_folder.path.empty();
  const fs::path out = !root           ? rank_folder.path
                       : a.out.empty() ? fs::path("reports") / (fs::path(a.case_file).stem().string() + "-calibration")
                                       : fs::path(a.out);
  return guarded([&] {
    // Before the fit, which may take minutes: an unusable --out fails now.
    bb::StagedFolder stage(out, {a.case_file});
    bb::FitProgress progress;
    int last_start = 0;
    std::optional<bb::ProgressClock> clock;  // over the iterations the cap allows, every start
    if (isatty(STDERR_FILENO))
      progress = [&](const bb::FitIteration& s) {
        if (last_start != 0 && s.start != last_start) std::fputc('\n', stderr);
        last_start = s.start;
        if (!clock) clock.emplace(s.starts * (s.max_iterations + 1));
        clock->finished((s.start - 1) * (s.max_iterations + 1) + s.iteration + 1);
        std::fprintf(stderr,
                     "\r\033[K  calibration: start %d of %d, iteration %3d of at most %d  cost %.6e  |gradient| %.3e  "
                     "step %s  %s",
                     s.start, s.starts, s.iteration, s.max_iterations, s.cost, s.gradient_max_norm,
                     s.accepted ? "accepted" : "rejected", clock->bound().c_str());
      };
    const bb::CalibrationOutcome o =
        bb::calibrate_case(a.case_file, progress, a.limits, bb::cache_or_none(a.cache), a.edits);
    if (last_start != 0) std::fputc('\n', stderr);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    bb::write_calibration_outputs(o, a.case_file, wall, stage.path(), !a.no_plots);
    stage.commit();
    const int rc = !o.converged || !o.cross_check_failure.empty() ? bb::exit_solver_failed
                   : o.cross_check_passed()                       ? bb::exit_pass
                                                                  : bb::exit_check_failed;
    if (!root) return rc;
    std::fprintf(stderr, "%s: %s, cost %.6g -> %.6g in %.1f s -> %s\n", a.case_file.c_str(),
                 o.converged ? "converged" : "NOT converged", o.initial_cost, o.final_cost, wall,
                 (out / "report.md").string().c_str());
    for (size_t i = 0; i < o.values.size(); ++i)
      std::fprintf(stderr, "  %s = %.8g (start %.8g, std %.3g)\n", o.spec.parameters[i].path.c_str(), o.values[i],
                   o.spec.parameters[i].start, o.std_devs[i]);
    for (const auto& w : o.warnings) std::fprintf(stderr, "  warning: %s\n", bb::printable(w).c_str());
    for (const bb::CheckEntry& e : o.cross_check)
      if (!e.pass)
        std::fprintf(stderr, "  cross-check FAIL %s: computed %.9g, reference %.9g, |error| %.3g > tolerance %.3g\n",
                     e.name.c_str(), e.computed, e.reference, e.abs_error, e.tolerance);
    return rc;
  });
}

struct SynthesizeArgs {
  std::string case_file, table, kind = "frf", out;
  std::vector<std::string> columns;
  bb::SyntheticOptions options;
  double phase_deg = 0.0;
  std::string command;  // the command line, recorded in the file
  std::optional<bb::ModelCacheSettings> cache;
};

int synthesize_command(SynthesizeArgs a) {
  return guarded([&] {
    a.options.kind = a.kind == "peaks" ? bb::DataKind::peaks
                     : a.kind == "frf" ? bb::DataKind::frf
                                       : bb::DataKind::hysteresis;
    a.options.phase_noise = a.phase_deg * std::numbers::pi / 180.0;
    for (const std::string& c : a.columns) {
      const size_t eq = c.find('='), colon = c.rfind(':');
      if (eq == std::string::npos || colon == std::string::npos || colon < eq)
        throw bb::InputError(fmt::format("--column '{}': write data=result:unit", c));
      a.options.columns.push_back({c.substr(0, eq), c.substr(eq + 1, colon - eq - 1), c.substr(colon + 1)});
    }
    a.options.provenance = "generated by: " + a.command;
    const bb::CaseSpec spec = bb::parse_case_file(a.case_file);
    // Refused before the run: a device, a FIFO or a folder at --out, or the case or a reference it reads.
    std::vector<fs::path> inputs{a.case_file};
    for (const bb::CheckSpec& c : spec.checks) inputs.insert(inputs.end(), {c.reference, c.reference_case});
    bb::require_outside(a.out, inputs, "--out " + bb::printable(a.out));
    bb::require_replaceable_file(a.out);
    const bb::AnalysisResults results =
        bb::run_analysis(spec.analysis, bb::build_model(spec.model), {}, {}, bb::cache_or_none(a.cache));
    const auto t = results.tables.find(a.table);
    if (t == results.tables.end())
      throw bb::InputError(fmt::format("{}: the case computes no table '{}'", a.case_file, a.table));
    if (bb::is_universal_file(a.out) && a.options.kind != bb::DataKind::frf)
      throw bb::InputError(fmt::format("--out {}: a Universal File (dataset 58) holds an FRF: use --kind frf", a.out));
    bb::replace_file(a.out, [&](const fs::path& temp) {
      bb::write_synthetic_data(t->second, a.options, temp);
      if (!bb::is_universal_file(a.out)) return;
      // A Universal File carries no sigma columns: the CSV is written, read back and converted.
      const bb::MeasuredData data = bb::read_measured_data(temp, bb::DataKind::frf);
      bb::write_uff58_frf(data, temp, "bladebench synthesize: " + a.case_file + " table " + a.table);
    });
    std::fprintf(stderr, "%s: table %s -> %s\n", a.case_file.c_str(), a.table.c_str(), a.out.c_str());
    return bb::exit_pass;
  });
}

struct ExportArgs {
  std::string case_file, out;
  int modes = 0;
};

int export_command(const ExportArgs& a) {
  try {
    const bb::CaseSpec spec = bb::parse_case_file(a.case_file);
    const auto* modal = std::get_if<bb::ModalSpec>(&spec.analysis);
    const auto* contact = std::get_if<bb::ContactModalSpec>(&spec.analysis);
    if (const auto* cyclic = std::get_if<bb::CyclicModalSpec>(&spec.analysis)) {
      const int families = a.modes > 0 ? a.modes : cyclic->families;
      const bb::CalculixCyclic c{
          cyclic->sectors, cyclic->left, cyclic->right,
          cyclic->nodal_diameters.empty() ? 0 : cyclic->nodal_diameters.front(),
          cyclic->nodal_diameters.empty() ? cyclic->sectors / 2 : cyclic->nodal_diameters.back()};
      bb::write_calculix_frequency_deck(bb::build_model(spec.model), 2 * families, a.out, nullptr, &c);
      std::fprintf(stderr,
                   "%s: CalculiX cyclic-symmetry deck, nodal diameters %d..%d, %d modes each (every family "
                   "twice) -> %s\n",
                   a.case_file.c_str(), c.nd_min, c.nd_max, 2 * families, a.out.c_str());
      return bb::exit_pass;
    }
    const int modes = a.modes > 0 ? a.modes
                      : modal     ? modal->modes.lowest
                      : contact   ? contact->modes
                                  : bb::ModeSelection{}.lowest;
    if (contact) {
      // The state point of the grid (default: the largest interference at the last FKN).
      const auto i =
          static_cast<size_t>(contact->state_interference >= 0 ? contact->state_interference
                                                               : static_cast<int>(contact->interferences.size()) - 1);
      const auto j = static_cast<size_t>(
          contact->state_penalty >= 0 ? contact->state_penalty : static_cast<int>(contact->penalty_factors.size()) - 1);
      const bb::CalculixContact c{contact->interferences[i], contact->penalty_factors[j], contact->tangential_ratio,
                                  contact->sticking, contact->roughness};
      bb::write_calculix_frequency_deck(bb::build_model(spec.model), modes, a.out, &c);
      std::fprintf(stderr, "%s: CalculiX deck with contact at interference %g m, FKN %g, %d modes -> %s\n",
                   a.case_file.c_str(), c.interference, c.penalty_factor, modes, a.out.c_str());
      return bb::exit_pass;
    }
    bb::write_calculix_frequency_deck(bb::build_model(spec.model), modes, a.out);
    std::fprintf(stderr, "%s: CalculiX deck, %d modes -> %s\n", a.case_file.c_str(), modes, a.out.c_str());
    return bb::exit_pass;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", bb::printable(e.what()).c_str());
    return bb::exit_bad_input;
  }
}

// The model cache (cache/model_cache.hpp) of the subcommands that compute, handed to each.
struct CacheArgs {
  std::string dir;
  bool off = false;
};

void add_cache_options(CLI::App* command, CacheArgs& args) {
  command->add_option("--cache-dir", args.dir,
                      "Model cache folder (default $BLADEBENCH_CACHE_DIR, else $XDG_CACHE_HOME/bladebench, else "
                      "~/.cache/bladebench)");
  command->add_flag("--no-cache", args.off, "Build every reduced model here; read and write no cache");
}

std::optional<bb::ModelCacheSettings> model_cache(const CacheArgs& args) {
  if (args.off || bb::distributed::size() > 1) return std::nullopt;  // every rank must solve what the others solve
  const std::optional<fs::path> folder = args.dir.empty() ? bb::default_model_cache_folder() : fs::path(args.dir);
  if (!folder) return std::nullopt;
  return bb::ModelCacheSettings{*folder};
}

// The subcommand on every MPI rank. run, validate and calibrate use the ranks (one case shared, the
// cases or the starts shared out); every other subcommand runs on rank 0 while the others wait. The exit code is the
// worst over the ranks, the same on each. Without mpirun: the command.
int command_on_ranks(bool uses_ranks, const std::function<int()>& body) {
  const int ranks = bb::distributed::size();
  if (ranks == 1) return body();
  if (!uses_ranks) {
    bb::distributed::set_shared_solves(false);
    if (bb::distributed::is_root())
      std::fprintf(stderr, "warning: this command runs on one MPI rank; the other %d ranks wait\n", ranks - 1);
  }
  int rc = uses_ranks || bb::distributed::is_root() ? body() : bb::exit_pass;
  std::vector<int> worst{rc};
  try {
    bb::distributed::max_over_ranks(worst);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    bb::distributed::abort_all(bb::exit_solver_failed);
  }
  return worst[0];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bladebench: validation and benchmark harness for friction-damped turbine blades"};
  app.require_subcommand(1);
  app.footer("Exit codes: 0 all checks pass, 1 a check failed, 2 bad input, 3 solver failure.");

  RunArgs run_args;
  CLI::App* run = app.add_subcommand("run", "Run one or more case files and write their reports");
  run->add_option("CASE", run_args.cases, "Case file(s) (TOML, see cases/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  run->add_option("--out", run_args.out,
                  "Output folder (default reports/<case-name>; with several cases, a parent folder)");
  run->add_flag("--study", run_args.study, "Also run the case's [study] (mesh refinement, accuracy vs cost)");
  run->add_flag("--no-plots", run_args.no_plots, "Skip gnuplot figures");
  run->add_flag("--vtk", run_args.vtk, "Also write the fields on the mesh for ParaView (vtk/*.vtu), as [case] vtk = true");
  run->add_option("--set", run_args.settings,
                  "dotted.key=VALUE (TOML value) replacing the case file's setting, e.g. --set analysis.harmonics=7; "
                  "repeatable; the report warns that it ran at it");
  run->add_option("--unset", run_args.removals,
                  "dotted.key removed from the case file (a key or a whole table, e.g. analysis.nonlinear_modes); "
                  "repeatable");
  add_fidelity_option(run, run_args.fidelity);
  add_limit_options(run, run_args.limits);
  CacheArgs cache_args;
  add_cache_options(run, cache_args);

  ValidateArgs validate_args;
  CLI::App* validate = app.add_subcommand("validate", "Run every case under a folder and write reports/index.md");
  validate->add_option("DIR", validate_args.dir, "Folder searched recursively for *.toml case files")
      ->check(CLI::ExistingDirectory);
  validate->add_option("--out", validate_args.out, "Report folder; each case goes to <out>/<case-name>");
  validate->add_flag("--study", validate_args.study, "Also run every case's [study]");
  validate->add_flag("--no-plots", validate_args.no_plots, "Skip gnuplot figures");
  add_fidelity_option(validate, validate_args.fidelity);
  add_limit_options(validate, validate_args.limits);
  validate
      ->add_option("-j,--jobs", validate_args.jobs,
                   "Cases run at once, each in its own process (default 1; the machine's cores: the fastest)")
      ->check(CLI::Range(1, 256));
  add_cache_options(validate, cache_args);

  CalibrateArgs calibrate_args;
  CLI::App* calibrate = app.add_subcommand(
      "calibrate",
      "Identify the case's [calibration] parameters against its checks and measured data (Ceres least squares)");
  calibrate->add_option("CASE", calibrate_args.case_file, "Case file with a [calibration] section")
      ->required()
      ->check(CLI::ExistingFile);
  calibrate->add_option("--out", calibrate_args.out, "Output folder (default reports/<case-name>-calibration)");
  calibrate->add_flag("--no-plots", calibrate_args.no_plots, "Skip gnuplot figures");
  calibrate->add_option("--set", calibrate_args.edits.settings,
                        "dotted.key=VALUE (TOML value) replacing the case file's setting, as run --set (a calibration "
                        "parameter's: its start); repeatable");
  calibrate->add_option("--restart-from", calibrate_args.edits.restart_from,
                        "calibrated.toml or restart.toml of an earlier fit: every parameter starts from its value "
                        "there (after --set)");
  add_limit_options(calibrate, calibrate_args.limits);
  add_cache_options(calibrate, cache_args);

  SynthesizeArgs synth;
  CLI::App* synthesize = app.add_subcommand(
      "synthesize",
      "Run a case and write one of its result tables as measured data with noise (round trips, test planning)");
  synthesize->add_option("CASE", synth.case_file, "Case file run at the parameter values to recover")
      ->required()
      ->check(CLI::ExistingFile);
  synthesize->add_option("--table", synth.table, "Result table to sample (e.g. frf_30, peaks, hysteresis)")->required();
  synthesize->add_option("--kind", synth.kind, "Data kind: peaks, frf or hysteresis")
      ->check(CLI::IsMember({"peaks", "frf", "hysteresis"}));
  synthesize->add_option("--column", synth.columns, "data=result:unit, e.g. amplitude=A.x_amp_m:um (repeat per column)")
      ->required();
  synthesize->add_option("--noise", synth.options.noise, "Relative sigma of amplitudes and forces")
      ->check(input_number(false));
  synthesize
      ->add_option("--force-noise", synth.options.force_noise,
                   "Relative sigma of an frf file's force column (a response-controlled curve's measured force)")
      ->check(input_number(false));
  synthesize->add_option("--frequency-noise", synth.options.frequency_noise, "Relative sigma of peak frequencies")
      ->check(input_number(false));
  synthesize->add_option("--phase-noise-deg", synth.phase_deg, "Sigma of phases [deg]")->check(input_number(false));
  synthesize->add_option("--outliers", synth.options.outliers, "Rows whose amplitude or force is scaled by 1.3")
      ->check(input_number(false));
  synthesize->add_option("--seed", synth.options.seed, "Random seed");
  synthesize->add_option("--every", synth.options.every, "Keep every n-th row")->check(CLI::PositiveNumber);
  synthesize->add_option("--out", synth.out, "CSV file to write")->required();
  add_cache_options(synthesize, cache_args);

  ExportArgs export_args;
  CLI::App* export_ccx = app.add_subcommand(
      "export-calculix", "Write the case's model as a CalculiX *FREQUENCY deck (bench/calculix_compare.sh)");
  export_ccx->add_option("CASE", export_args.case_file, "Case file with a 3D solid mesh")
      ->required()
      ->check(CLI::ExistingFile);
  export_ccx->add_option("--out", export_args.out, "Deck to write (.inp)")->required();
  export_ccx
      ->add_option("--modes", export_args.modes,
                   "Modes to ask for (default: the case's analysis.modes; a cyclic_modal case: families per nodal "
                   "diameter)")
      ->check(CLI::PositiveNumber);

  std::string html_folder;
  CLI::App* html = app.add_subcommand(
      "html", "Write report.html beside every report.md and index.md under a folder (reports from an older build)");
  html->add_option("DIR", html_folder, "Report folder, searched recursively")
      ->required()
      ->check(CLI::ExistingDirectory);

  CompareArgs compare_args;
  CLI::App* compare =
      app.add_subcommand("compare",
                         "What changed between two report folders (validate --out): exit 1 when a status or a check "
                         "verdict flips or a value moves");
  compare->add_option("OLD", compare_args.old_dir, "Report folder of the earlier run")->required();
  compare->add_option("NEW", compare_args.new_dir, "Report folder of the later run")->required();
  compare
      ->add_option("--max-change", compare_args.max_change,
                   "A value moves when it changes by more than this share of the larger of its size and its "
                   "tolerance (default 1e-6)")
      ->check(input_number(false));
  compare->add_option("--out", compare_args.out,
                      "Page to write (Markdown, with its HTML twin); default: standard output");

  CompareModelsArgs models_args;
  CLI::App* compare_models = app.add_subcommand(
      "compare-models", "Calibrate several model forms on the same data and rank them by held-out error and AIC/BIC");
  compare_models->add_option("CASES", models_args.cases, "Case files with a [calibration] section, one per model")
      ->required()
      ->check(CLI::ExistingFile);
  compare_models->add_option("--out", models_args.out, "Output folder (default reports/model-comparison)");
  compare_models->add_flag("--no-plots", models_args.no_plots, "Skip gnuplot figures");
  compare_models->add_flag("--leave-one-out", models_args.leave_one_out,
                           "Also refit each model once per fitted curve, that curve held out, and rank by the "
                           "predicted curves' rms");
  add_limit_options(compare_models, models_args.limits);
  add_cache_options(compare_models, cache_args);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : bb::exit_bad_input;
  }
  try {
    if (!bb::distributed::start_if_launched()) return bb::exit_pass;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", bb::printable(e.what()).c_str());
    return bb::exit_solver_failed;
  }
  run_args.cache = validate_args.cache = calibrate_args.cache = synth.cache = model_cache(cache_args);
  const int rc = command_on_ranks(*run || *validate || *calibrate, [&] {
    if (*calibrate) return calibrate_command(calibrate_args);
    if (*synthesize) {
      synth.command = "bladebench";
      for (int i = 1; i < argc; ++i) synth.command += std::string(" ") + argv[i];
      return synthesize_command(synth);
    }
    if (*export_ccx) return export_command(export_args);
    if (*html) return guarded([&] { return html_command(html_folder); });
    if (*compare) return guarded([&] { return compare_command(compare_args); });
    if (*compare_models) {
      models_args.cache = bb::cache_or_none(calibrate_args.cache);
      return guarded([&] { return compare_models_command(models_args); });
    }
    if (*run) return guarded([&] { return run_command(run_args); });
    return guarded([&] { return validate_command(validate_args); });
  });
  bb::distributed::finish();
  return rc;
}
