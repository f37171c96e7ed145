#include "pipeline/run_study.hpp"

#include <fmt/format.h>

#include <memory>
#include <optional>

#include "common/progress_clock.hpp"
#include "report/frf_plots.hpp"
#include "report/hbm_plots.hpp"
#include "report/plots.hpp"
#include "report/rotating_plots.hpp"
#include "report/time_plots.hpp"
#include "report/writers.hpp"
#include "study/hbm_study.hpp"
#include "study/modal_refinement.hpp"
#include "study/refinement.hpp"
#include "study/rom_study.hpp"
#include "study/rotating_fidelity.hpp"
#include "study/time_study.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// A study's variants as progress lines with the time left; empty when `line` is.
StudyProgress study_progress(const HbmProgress& line, const std::string& what) {
  if (!line) return {};
  auto clock = std::make_shared<std::optional<ProgressClock>>();
  return [line, what, clock](int done, int total) {
    if (!*clock) clock->emplace(total);
    (*clock)->finished(done);
    line(fmt::format("study ({}): {}", what, (*clock)->status()));
  };
}

struct StudyRun {
  const CaseSpec& spec;
  const Model& model;
  const AnalysisResults& results;
  const fs::path& out;
  bool plots;
  RunRecord& run;
  const HbmProgress& line;
  const WorkLimits& limits;
  const ModelCacheSettings* cache;

  void operator()(const RefinementStudySpec& s) const {
    run.study = run_refinement_study(spec.model, s, study_progress(line, "mesh refinement"));
    run.study_note = s.note;
    if (!plots) return;
    run.study_plots.push_back(plot_refinement_error(*run.study, out, "study_error"));
    run.study_plots.push_back(plot_refinement_cost(*run.study, out, "study_cost"));
  }
  void operator()(const ModalRefinementStudySpec& s) const {
    run.modal_study = run_modal_refinement_study(spec.model, std::get<ModalSpec>(spec.analysis), s,
                                                 study_progress(line, "modal refinement"), cache);
    run.study_note = s.note;
    if (plots) run.study_plots.push_back(plot_modal_refinement(*run.modal_study, out, "study_modal"));
  }
  void operator()(const RomStudySpec& s) const {
    table(run_rom_study(std::get<FrfSpec>(spec.analysis), s, model, study_progress(line, "reduced models"), cache),
          s.note, "rom_study", "study_rom", plot_rom_study);
  }
  void operator()(const HbmHarmonicsStudySpec& s) const {
    const HbmOutcome& hbm = std::get<HbmOutcome>(results.outcome);
    table(run_hbm_harmonics_study(std::get<HbmSpec>(spec.analysis), hbm.prepared, s,
                                  study_progress(line, "harmonics x force levels")),
          s.note, "hbm_harmonics_study", "study_harmonics", plot_hbm_harmonics_study);
  }
  void operator()(const TimeStepStudySpec& s) const {
    table(run_time_step_study(model, std::get<TimeSpec>(spec.analysis), s, study_progress(line, "time steps"), cache),
          s.note, "time_step_study", "study_time_steps", plot_time_step_study);
  }

  void operator()(const RotatingFidelityStudySpec& s) const {
    table(run_rotating_fidelity_study(model, std::get<RotatingSpec>(spec.analysis), s,
                                      study_progress(line, "rotating model levels"), limits),
          s.note, "rotating_fidelity_study", "study_rotating_fidelity", plot_rotating_fidelity);
  }

  // A study whose result is one table: listed in the report, written as CSV, drawn.
  template <typename Plot>
  void table(ResultTable t, const std::string& note, const std::string& name, const std::string& plot_name,
             Plot plot) const {
    run.study_tables.push_back(std::move(t));
    run.study_note = note;
    write_result_csv(run.study_tables.back(), out, run, name + ".csv");
    if (plots) run.study_plots.push_back(plot(run.study_tables.back(), out, plot_name));
  }
};

}  // namespace

void run_study(const StudySpec& study, const CaseSpec& spec, const Model& model, const AnalysisResults& results,
               const fs::path& out, bool plots, RunRecord& run, const HbmProgress& progress, const WorkLimits& limits,
               const ModelCacheSettings* cache) {
  std::visit(StudyRun{spec, model, results, out, plots, run, progress, limits, cache}, study);
}

}  // namespace bb
