#include "study/hbm_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bb {

ResultTable run_hbm_harmonics_study(const HbmSpec& spec, const PreparedHbm& prepared,
                                    const HbmHarmonicsStudySpec& study, const StudyProgress& progress) {
  const int h_ref = *std::max_element(study.harmonics.begin(), study.harmonics.end());
  const size_t kinds = prepared.ip_oop ? 2 : 1;
  HbmSpec s = spec;
  s.time_samples = study.time_samples;
  struct Row {
    int harmonics;
    size_t level;
    HbmLevel result;
  };
  std::vector<Row> rows;
  const int total = static_cast<int>(study.harmonics.size() * study.force_levels.size());
  if (progress) progress(0, total);
  for (int h : study.harmonics)
    for (size_t l = 0; l < study.force_levels.size(); ++l) {
      rows.push_back({h, l, sweep_hbm_level(prepared, s, study.force_levels[l], h)});
      if (progress) progress(static_cast<int>(rows.size()), total);
    }

  ResultTable t;
  t.name = "hbm_harmonics_study";
  t.columns = {"variant", "harmonics", "fe_n"};
  const std::vector<std::string> names =
      prepared.ip_oop ? std::vector<std::string>{"ip", "oop"} : std::vector<std::string>{"peak"};
  for (const std::string& k : names)
    for (const char* c : {"_hz", "_amp_m", "_hz_error", "_amp_error"}) t.columns.push_back(k + c);
  for (const char* c : {"unknowns", "newton_iterations", "failed_points", "seconds"}) t.columns.push_back(c);
  t.values.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(t.columns.size()));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Index n_contact_dofs = [&] {
    const hbm::HarmonicBalance system(prepared.model, {});
    return static_cast<Eigen::Index>(system.contact_dofs().size());
  }();
  for (size_t r = 0; r < rows.size(); ++r) {
    const Row& row = rows[r];
    const Row* ref = nullptr;
    for (const Row& other : rows)
      if (other.harmonics == h_ref && other.level == row.level) ref = &other;
    std::vector<double> v = {100.0 * row.harmonics + static_cast<double>(row.level + 1),
                             static_cast<double>(row.harmonics), study.force_levels[row.level]};
    for (size_t k = 0; k < kinds; ++k) {
      const auto ok = [&](const HbmLevel& l) { return k < l.peaks.size() && l.peaks[k].solution.converged; };
      if (!ok(row.result)) {
        v.insert(v.end(), {nan, nan, nan, nan});
        continue;
      }
      const HbmPeak& p = row.result.peaks[k];
      const bool has_ref = ref && ok(ref->result);
      v.insert(v.end(),
               {p.frequency_hz, p.amplitude, has_ref ? p.frequency_hz / ref->result.peaks[k].frequency_hz - 1 : nan,
                has_ref ? p.amplitude / ref->result.peaks[k].amplitude - 1 : nan});
    }
    v.insert(v.end(), {static_cast<double>(n_contact_dofs * (2 * row.harmonics + 1)),
                       static_cast<double>(row.result.path.corrector_iterations),
                       static_cast<double>(row.result.path.rejected_steps), row.result.seconds});
    for (size_t c = 0; c < v.size(); ++c) t.values(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = v[c];
  }
  return t;
}

}  // namespace bb
