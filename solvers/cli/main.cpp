// bladebench command line: run and validate cases. Exit codes in common/errors.hpp.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>

#include "cases/case_spec.hpp"
#include "cli/run_case.hpp"
#include "identify/calibrate_case.hpp"
#include "identify/calibration_report.hpp"
#include "identify/synthetic_data.hpp"
#include "analysis/case_results.hpp"
#include "common/errors.hpp"
#include "report/calculix_export.hpp"
#include "report/writers.hpp"

namespace fs = std::filesystem;

namespace {

int failed_count(const bb::RunRecord& r) {
  return static_cast<int>(std::count_if(r.checks.begin(), r.checks.end(), [](const bb::CheckEntry& e) { return !e.pass; }));
}

void print_outcome(const bb::RunOutcome& o, const std::string& prefix) {
  const bb::RunRecord& r = o.record;
  std::fprintf(stderr, "%s%s: %s (%zu checks, %d failed, %.3f s) -> %s\n", prefix.c_str(), r.case_name.c_str(),
               bb::status_name(r.status).c_str(), r.checks.size(), failed_count(r), r.wall_seconds,
               (o.out_dir / "report.md").string().c_str());
  if (!r.message.empty()) std::fprintf(stderr, "  error: %s\n", r.message.c_str());
  for (const bb::CheckEntry& e : r.checks)
    if (!e.pass)
      std::fprintf(stderr, "  FAIL %s: computed %.9g, reference %.9g, |error| %.3g > tolerance %.3g\n", e.name.c_str(),
                   e.computed, e.reference, e.abs_error, e.tolerance);
}

int worst(int a, int b) { return std::max(a, b); }

// A subcommand's body: bad input -> exit 2, any other failure -> exit 3, the message on stderr.
int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const bb::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return bb::exit_bad_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return bb::exit_solver_failed;
  }
}

// Files under a "data" folder are inputs of cases (CSV meshes, reduced-model sidecars), not cases.
bool in_data_folder(const std::filesystem::path& file, const std::filesystem::path& root) {
  for (const auto& part : std::filesystem::relative(file.parent_path(), root))
    if (part == "data") return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bladebench: validation and benchmark harness for friction-damped turbine blades"};
  app.require_subcommand(1);
  app.footer("Exit codes: 0 all checks pass, 1 a check failed, 2 bad input, 3 solver failure.");

  std::vector<std::string> run_cases;
  std::string run_out;
  bool run_study = false, run_no_plots = false;
  CLI::App* run = app.add_subcommand("run", "Run one or more case files and write their reports");
  run->add_option("CASE", run_cases, "Case file(s) (TOML, see cases/README.md)")->required()->check(CLI::ExistingFile);
  run->add_option("--out", run_out, "Output folder (default reports/<case-name>; with several cases, a parent folder)");
  run->add_flag("--study", run_study, "Also run the case's [study] (mesh refinement, accuracy vs cost)");
  run->add_flag("--no-plots", run_no_plots, "Skip gnuplot figures");

  std::string validate_dir = "cases", validate_out = "reports";
  bool validate_study = false, validate_no_plots = false;
  CLI::App* validate = app.add_subcommand("validate", "Run every case under a folder and write reports/index.md");
  validate->add_option("DIR", validate_dir, "Folder searched recursively for *.toml case files")->check(CLI::ExistingDirectory);
  validate->add_option("--out", validate_out, "Report folder; each case goes to <out>/<case-name>");
  validate->add_flag("--study", validate_study, "Also run every case's [study]");
  validate->add_flag("--no-plots", validate_no_plots, "Skip gnuplot figures");

  std::string calibrate_case_file, calibrate_out;
  CLI::App* calibrate = app.add_subcommand(
      "calibrate", "Identify the case's [calibration] parameters against its checks and measured data (Ceres least squares)");
  calibrate->add_option("CASE", calibrate_case_file, "Case file with a [calibration] section")->required()->check(CLI::ExistingFile);
  calibrate->add_option("--out", calibrate_out, "Output folder (default reports/<case-name>-calibration)");
  bool calibrate_no_plots = false;
  calibrate->add_flag("--no-plots", calibrate_no_plots, "Skip gnuplot figures");

  std::string synth_case_file, synth_table, synth_kind = "frf", synth_out;
  std::vector<std::string> synth_columns;
  bb::SyntheticOptions synth;
  double synth_phase_deg = 0.0;
  CLI::App* synthesize = app.add_subcommand(
      "synthesize", "Run a case and write one of its result tables as measured data with noise (round trips, test planning)");
  synthesize->add_option("CASE", synth_case_file, "Case file run at the parameter values to recover")->required()->check(CLI::ExistingFile);
  synthesize->add_option("--table", synth_table, "Result table to sample (e.g. frf_30, peaks, hysteresis)")->required();
  synthesize->add_option("--kind", synth_kind, "Data kind: peaks, frf or hysteresis")->check(CLI::IsMember({"peaks", "frf", "hysteresis"}));
  synthesize->add_option("--column", synth_columns, "data=result:unit, e.g. amplitude=A.x_amp_m:um (repeat per column)")->required();
  synthesize->add_option("--noise", synth.noise, "Relative sigma of amplitudes and forces")->check(CLI::NonNegativeNumber);
  synthesize->add_option("--frequency-noise", synth.frequency_noise, "Relative sigma of peak frequencies")->check(CLI::NonNegativeNumber);
  synthesize->add_option("--phase-noise-deg", synth_phase_deg, "Sigma of phases [deg]")->check(CLI::NonNegativeNumber);
  synthesize->add_option("--outliers", synth.outliers, "Rows whose amplitude or force is scaled by 1.3")->check(CLI::NonNegativeNumber);
  synthesize->add_option("--seed", synth.seed, "Random seed");
  synthesize->add_option("--every", synth.every, "Keep every n-th row")->check(CLI::PositiveNumber);
  synthesize->add_option("--out", synth_out, "CSV file to write")->required();

  std::string export_case_file, export_out;
  int export_modes = 0;
  CLI::App* export_ccx = app.add_subcommand(
      "export-calculix", "Write the case's model as a CalculiX *FREQUENCY deck (bench/calculix_compare.sh)");
  export_ccx->add_option("CASE", export_case_file, "Case file with a 3D solid mesh")->required()->check(CLI::ExistingFile);
  export_ccx->add_option("--out", export_out, "Deck to write (.inp)")->required();
  export_ccx->add_option("--modes", export_modes, "Modes to ask for (default: the case's analysis.modes)")->check(CLI::PositiveNumber);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : bb::exit_bad_input;
  }

  if (*calibrate) {
    const auto t0 = std::chrono::steady_clock::now();
    const fs::path out = calibrate_out.empty() ? fs::path("reports") / (fs::path(calibrate_case_file).stem().string() + "-calibration")
                                               : fs::path(calibrate_out);
    return guarded([&] {
      const bb::CalibrationOutcome o = bb::calibrate_case(calibrate_case_file, true);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      bb::write_calibration_outputs(o, calibrate_case_file, wall, out, !calibrate_no_plots);
      std::fprintf(stderr, "%s: %s, cost %.6g -> %.6g in %.1f s -> %s\n", calibrate_case_file.c_str(),
                   o.converged ? "converged" : "NOT converged", o.initial_cost, o.final_cost, wall,
                   (out / "report.md").string().c_str());
      for (size_t i = 0; i < o.values.size(); ++i)
        std::fprintf(stderr, "  %s = %.8g (start %.8g, std %.3g)\n", o.spec.parameters[i].path.c_str(), o.values[i],
                     o.spec.parameters[i].start, o.std_devs[i]);
      for (const auto& w : o.warnings) std::fprintf(stderr, "  warning: %s\n", w.c_str());
      for (const bb::CheckEntry& e : o.cross_check)
        if (!e.pass)
          std::fprintf(stderr, "  cross-check FAIL %s: computed %.9g, reference %.9g, |error| %.3g > tolerance %.3g\n", e.name.c_str(),
                       e.computed, e.reference, e.abs_error, e.tolerance);
      if (!o.converged) return bb::exit_solver_failed;
      return o.cross_check_passed() ? bb::exit_pass : bb::exit_check_failed;
    });
  }

  if (*synthesize) {
    return guarded([&] {
      synth.kind = synth_kind == "peaks" ? bb::DataKind::peaks : synth_kind == "frf" ? bb::DataKind::frf : bb::DataKind::hysteresis;
      synth.phase_noise = synth_phase_deg * 3.14159265358979323846 / 180.0;
      for (const std::string& c : synth_columns) {
        const size_t eq = c.find('='), colon = c.rfind(':');
        if (eq == std::string::npos || colon == std::string::npos || colon < eq)
          throw bb::InputError(fmt::format("--column '{}': write data=result:unit", c));
        synth.columns.push_back({c.substr(0, eq), c.substr(eq + 1, colon - eq - 1), c.substr(colon + 1)});
      }
      std::string command = "bladebench";
      for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
      synth.provenance = "generated by: " + command;
      const bb::CaseSpec spec = bb::parse_case_file(synth_case_file);
      const bb::CaseResults results = bb::compute_case_results(spec, bb::build_model(spec));
      const auto t = results.tables.find(synth_table);
      if (t == results.tables.end()) throw bb::InputError(fmt::format("{}: the case computes no table '{}'", synth_case_file, synth_table));
      bb::write_synthetic_data(t->second, synth, synth_out);
      std::fprintf(stderr, "%s: table %s -> %s\n", synth_case_file.c_str(), synth_table.c_str(), synth_out.c_str());
      return bb::exit_pass;
    });
  }

  if (*export_ccx) {
    try {
      const bb::CaseSpec spec = bb::parse_case_file(export_case_file);
      const int modes = export_modes > 0 ? export_modes : spec.analysis.modes.lowest;
      bb::write_calculix_frequency_deck(bb::build_model(spec), modes, export_out);
      std::fprintf(stderr, "%s: CalculiX deck, %d modes -> %s\n", export_case_file.c_str(), modes, export_out.c_str());
      return bb::exit_pass;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return bb::exit_bad_input;
    }
  }

  if (*run) {
    int rc = bb::exit_pass;
    for (const std::string& c : run_cases) {
      bb::RunOptions opt;
      opt.study = run_study;
      opt.plots = !run_no_plots;
      if (!run_out.empty()) opt.out_dir = run_cases.size() == 1 ? fs::path(run_out) : fs::path(run_out) / fs::path(c).stem();
      const bb::RunOutcome o = bb::run_case(c, opt);
      print_outcome(o, "");
      rc = worst(rc, bb::exit_code(o.record.status));
    }
    return rc;
  }

  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(validate_dir))
    if (entry.is_regular_file() && entry.path().extension() == ".toml" && !in_data_folder(entry.path(), validate_dir))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "error: no *.toml case file under %s\n", validate_dir.c_str());
    return bb::exit_bad_input;
  }
  std::vector<bb::IndexEntry> index;
  std::map<std::string, fs::path> seen;
  int rc = bb::exit_pass;
  for (size_t i = 0; i < files.size(); ++i) {
    bb::RunOptions opt;
    opt.study = validate_study;
    opt.plots = !validate_no_plots;
    // Output folder by file stem first; the case name is only known after parsing.
    opt.out_dir = fs::path(validate_out) / files[i].stem();
    const bb::RunOutcome o = bb::run_case(files[i], opt);
    print_outcome(o, fmt::format("[{}/{}] ", i + 1, files.size()));
    int code = bb::exit_code(o.record.status);
    bb::IndexEntry e{o.record.case_name, fs::relative(o.out_dir / "report.md", validate_out), o.record.status,
                     static_cast<int>(o.record.checks.size()), failed_count(o.record), o.record.wall_seconds,
                     o.record.message};
    if (auto [it, fresh] = seen.emplace(files[i].stem().string(), files[i]); !fresh) {
      e.status = bb::RunStatus::bad_input;
      e.message = fmt::format("two case files share the name '{}': {} and {}", files[i].stem().string(),
                              it->second.string(), files[i].string());
      std::fprintf(stderr, "  error: %s\n", e.message.c_str());
      code = bb::exit_bad_input;
    }
    index.push_back(e);
    rc = worst(rc, code);
  }
  bb::write_index_md(index, fs::path(validate_out) / "index.md");
  std::fprintf(stderr, "%zu cases, index: %s\n", files.size(), (fs::path(validate_out) / "index.md").string().c_str());
  return rc;
}
