#include "cli/compare_models_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "common/errors.hpp"
#include "identify/model_comparison.hpp"
#include "pipeline/calibrate_case.hpp"
#include "report/calibration_report.hpp"
#include "report/model_comparison_report.hpp"
#include "report/output_folder.hpp"

namespace bb::cli {

namespace fs = std::filesystem;

namespace {

// One refit per fitted curve, that curve held out too (its own outcome only scored, not written).
void leave_one_out(const std::string& case_file, const CalibrationOutcome& full, const CompareModelsArgs& a,
                   ModelScore& score) {
  const std::vector<std::string> sets = fitted_sets(full);
  if (sets.size() < 2)
    throw InputError(
        fmt::format("compare-models --leave-one-out: {} fits {} data set(s); leaving one out needs "
                    "two or more",
                    case_file, sets.size()));
  std::vector<CalibrationOutcome> folds;
  for (const std::string& set : sets) {
    const auto t0 = std::chrono::steady_clock::now();
    CalibrationStartEdits edits;
    edits.settings.push_back(fold_hold_out_setting(full, set));
    folds.push_back(calibrate_case(case_file, {}, a.limits, a.cache, edits));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr, "  without '%s': %s, cost %.6g in %.1f s\n", set.c_str(),
                 folds.back().converged ? "converged" : "NOT converged", folds.back().final_cost, wall);
  }
  score_leave_one_out(score, folds, sets);
}

}  // namespace

int compare_models_command(const CompareModelsArgs& a) {
  if (a.cases.size() < 2) throw InputError("compare-models: give at least two case files, one per model form");
  std::set<std::string> names;
  for (const std::string& c : a.cases)
    if (!names.insert(fs::path(c).stem().string()).second)
      throw InputError(fmt::format("compare-models: two cases named '{}': each model is named by its file",
                                   fs::path(c).stem().string()));
  StagedFolder stage(a.out);
  std::vector<CalibrationOutcome> outcomes;
  std::vector<ModelScore> scores;
  for (const std::string& c : a.cases) {
    const auto t0 = std::chrono::steady_clock::now();
    outcomes.push_back(calibrate_case(c, {}, a.limits, a.cache));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string name = fs::path(c).stem().string();
    write_calibration_outputs(outcomes.back(), c, wall, stage.path() / name, !a.no_plots);
    scores.push_back(score_calibration(name, outcomes.back()));
    std::fprintf(stderr, "%s: %s, cost %.6g in %.1f s\n", c.c_str(),
                 outcomes.back().converged ? "converged" : "NOT converged", outcomes.back().final_cost, wall);
    if (a.leave_one_out) leave_one_out(c, outcomes.back(), a, scores.back());
  }
  std::vector<const CalibrationOutcome*> pointers;
  for (const CalibrationOutcome& o : outcomes) pointers.push_back(&o);
  try {
    rank_models(scores, pointers);
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("compare-models: {}", e.what()));
  }
  write_model_comparison(scores, pointers, stage.path(), !a.no_plots);
  stage.commit();
  bool converged = true;
  for (const ModelScore& s : scores) {
    std::fprintf(stderr,
                 "  rank %d: %s  held-out rms %.3g sigma, leave-one-out rms %.3g sigma, BIC %.4g, "
                 "cross-check %d of %d\n",
                 s.rank, s.name.c_str(), s.held_out_rms, s.leave_one_out_rms, s.bic, s.cross_check_passed,
                 s.cross_check_entries);
    converged = converged && s.converged && s.folds_converged == s.folds;
  }
  std::fprintf(stderr, "compare-models: %s\n", (fs::path(a.out) / "report.md").string().c_str());
  return converged ? exit_pass : exit_solver_failed;
}

}  // namespace bb::cli
