#include "study/time_study.hpp"

#include <algorithm>
#include <cmath>

namespace bb {

ResultTable run_time_step_study(const Model& model, const TimeSpec& spec, const TimeStepStudySpec& study,
                                const StudyProgress& progress, const ModelCacheSettings* cache) {
  struct Variant {
    int steps;
    double tolerance;
    TimeOutcome outcome;
  };
  std::vector<Variant> variants;
  const int total = static_cast<int>(study.steps_per_period.size() * study.steady_tolerances.size());
  if (progress) progress(0, total);
  for (int n : study.steps_per_period)
    for (double t : study.steady_tolerances) {
      TimeSpec s = spec;
      s.steps_per_period = n;
      s.steady_tolerance = t;
      s.history_hz.reset();
      s.compare_harmonics = 0;
      s.require_steady_peaks = false;  // a coarse variant's unsteady peak is the error this study measures
      s.system.force_levels = {spec.system.force_levels.front()};
      variants.push_back({n, t, run_time(model, s, {}, cache)});
      if (progress) progress(static_cast<int>(variants.size()), total);
    }
  // The reference: most steps per period, then the smallest tolerance.
  const auto ref = std::max_element(variants.begin(), variants.end(), [](const Variant& a, const Variant& b) {
    return a.steps != b.steps ? a.steps < b.steps : a.tolerance > b.tolerance;
  });
  const ResultTable& ref_peaks = ref->outcome.tables.at("peaks");
  std::vector<std::string> kinds;
  for (const std::string& c : ref_peaks.columns)
    if (c.ends_with("_amp_m")) kinds.push_back(c.substr(0, c.size() - 6));
  ResultTable t;
  t.name = "time_step_study";
  t.columns = {"variant", "steps_per_period", "steady_tolerance"};
  for (const std::string& k : kinds) t.columns.insert(t.columns.end(), {k + "_hz_error", k + "_amp_error"});
  t.columns.insert(t.columns.end(), {"max_amp_error", "steps", "mean_cycles", "not_steady", "seconds"});
  t.values.resize(static_cast<Eigen::Index>(variants.size()), static_cast<Eigen::Index>(t.columns.size()));
  for (size_t v = 0; v < variants.size(); ++v) {
    const TimeOutcome& o = variants[v].outcome;
    const ResultTable& peaks = o.tables.at("peaks");
    std::vector<double> row = {static_cast<double>(v + 1), static_cast<double>(variants[v].steps),
                               variants[v].tolerance};
    for (const std::string& k : kinds) {
      const int f = *peaks.column_index(k + "_hz"), a = *peaks.column_index(k + "_amp_m");
      row.push_back(peaks.values(0, f) / ref_peaks.values(0, f) - 1);
      row.push_back(peaks.values(0, a) / ref_peaks.values(0, a) - 1);
    }
    const TimeLevel& level = o.levels.front();
    const TimeLevel& ref_level = ref->outcome.levels.front();
    double worst = 0.0, cycles = 0.0, not_steady = 0.0;
    for (Eigen::Index i = 0; i < level.amplitude.rows(); ++i)
      worst = std::max(worst, std::abs(level.amplitude(i, 0) / ref_level.amplitude(i, 0) - 1));
    for (size_t i = 0; i < level.cycles.size(); ++i) {
      cycles += level.cycles[i] / static_cast<double>(level.cycles.size());
      not_steady += level.steady[i] ? 0 : 1;
    }
    row.insert(row.end(), {worst, static_cast<double>(level.steps), cycles, not_steady, level.seconds});
    for (size_t c = 0; c < row.size(); ++c)
      t.values(static_cast<Eigen::Index>(v), static_cast<Eigen::Index>(c)) = row[c];
  }
  return t;
}

}  // namespace bb
