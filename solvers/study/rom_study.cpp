#include "study/rom_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/frf_analysis.hpp"

namespace bb {

ResultTable run_rom_study(const FrfSpec& spec, const RomStudySpec& study, const Model& model,
                          const StudyProgress& progress, const ModelCacheSettings* cache) {
  FrfSpec frf = spec;
  frf.pairs.reset();  // the study compares frequencies by index: no labels
  frf.force_levels.clear();
  frf.roms.clear();
  std::vector<std::string> set_of_variant;
  for (const auto& [set, masters] : study.master_sets)
    for (int m : study.modes) {
      RomSpec rom;
      rom.name = fmt::format("{}_{}", set, m);
      rom.masters = masters;
      rom.modes = m;
      frf.roms.push_back(rom);
      set_of_variant.push_back(set);
    }
  // Progress per model built (the full one and each variant's reduction): the sweep after them is cheap.
  const FrfOutcome o = run_frf(model, frf, progress, cache);
  const Eigen::VectorXd& full = o.full_modal->frequencies_hz;
  const ResultTable& full_peaks = o.tables.at("peaks_full");
  const double n_frequencies = static_cast<double>(o.sweep.frequency_hz.size());

  ResultTable t;
  t.name = "rom_study";
  t.columns = {"variant",        "master_points",   "modes",          "rom_dofs",    "max_freq_error",
               "rms_freq_error", "peak_freq_error", "peak_amp_error", "reduction_s", "solve_us_per_frequency"};
  t.values.resize(static_cast<Eigen::Index>(o.roms.size()), static_cast<Eigen::Index>(t.columns.size()));
  for (size_t v = 0; v < o.roms.size(); ++v) {
    const RomOutcome& r = o.roms[v];
    const auto n =
        std::min<Eigen::Index>({static_cast<Eigen::Index>(study.compare_modes), r.frequencies_hz.size(), full.size()});
    double max_error = 0.0, sum2 = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const double e = std::abs(r.frequencies_hz[k] / full[k] - 1.0);
      max_error = std::max(max_error, e);
      sum2 += e * e;
    }
    // The first peak of each response (key 100 r + 1), the worst of them.
    const ResultTable& peaks = o.tables.at("peaks_" + r.name);
    double peak_f = 0.0, peak_a = 0.0;
    for (Eigen::Index i = 0; i < full_peaks.values.rows(); ++i) {
      const long key = std::lround(full_peaks.values(i, 0));
      if (key % 100 != 1) continue;
      const int row = peaks.row_of_key(key);
      if (row < 0) {
        peak_f = peak_a = INFINITY;  // the reduced model misses a peak the full mesh has
        continue;
      }
      peak_f = std::max(peak_f, std::abs(peaks.values(row, 1) / full_peaks.values(i, 1) - 1.0));
      peak_a = std::max(peak_a, std::abs(peaks.values(row, 2) / full_peaks.values(i, 2) - 1.0));
    }
    const CraigBamptonTiming& c = r.timing;
    const auto row = static_cast<Eigen::Index>(v);
    t.values.row(row) << static_cast<double>(v + 1), static_cast<double>(frf.roms[v].masters.size()),
        static_cast<double>(frf.roms[v].modes), static_cast<double>(r.model.size()), max_error,
        std::sqrt(sum2 / static_cast<double>(std::max<Eigen::Index>(n, 1))), peak_f, peak_a,
        c.constraint_modes_seconds + c.fixed_interface_seconds + c.projection_seconds,
        1e6 * r.sweep_seconds / n_frequencies;
  }
  t.add_text_column("master_set", set_of_variant);
  return t;
}

}  // namespace bb
