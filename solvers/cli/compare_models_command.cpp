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

int compare_models_command(const CompareModelsArgs& a) {
  if (a.cases.size() < 2) throw InputError("compare-models: give at least two case files, one per model form");
  std::set<std::string> names;
  for (const std::string& c : a.cases)
    if (!names.insert(fs::path(c).stem().string()).second)
      throw InputError(fmt::format("compare-models: two cases named '{}': each model is named by its file", fs::path(c).stem().string()));
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
    std::fprintf(stderr, "%s: %s, cost %.6g in %.1f s\n", c.c_str(), outcomes.back().converged ? "converged" : "NOT converged",
                 outcomes.back().final_cost, wall);
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
    std::fprintf(stderr, "  rank %d: %s  held-out rms %.3g sigma, BIC %.4g, cross-check %d of %d\n", s.rank,
                 s.name.c_str(), s.held_out_rms, s.bic, s.cross_check_passed, s.cross_check_entries);
    converged = converged && s.converged;
  }
  std::fprintf(stderr, "compare-models: %s\n", (fs::path(a.out) / "report.md").string().c_str());
  return converged ? exit_pass : exit_solver_failed;
}

}  // namespace bb::cli
