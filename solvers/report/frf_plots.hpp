// Plots of linear forced responses: amplitude against frequency for every model that has a given
// response (full mesh vs reduced models in one figure, as the thesis's Fig 3.26), and the
// response at several force levels (Fig 3.25).
#pragma once
#include <filesystem>
#include <string>

#include "analysis/frf_analysis.hpp"
#include "report/run_record.hpp"
#include "results/table.hpp"

namespace bb {

// Amplitude of response `output` (e.g. "T2.x") of every model that has it; log scale in y, the
// full mesh's natural frequencies as dotted lines when known.
Plot plot_frf(const FrfOutcome& frf, const std::string& output, const std::filesystem::path& out_dir,
              const std::string& stem);

// The first model's first response at each force level of the linearity sweep.
Plot plot_force_levels(const FrfOutcome& frf, const std::filesystem::path& out_dir, const std::string& stem);

// Reduced-model study: max error of the first frequencies and FRF peak frequency error against
// the number of fixed-interface modes, one line per master set (log scale in y).
Plot plot_rom_study(const ResultTable& study, const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
