// Plots of the nonlinear modes of an hbm analysis (analysis/hbm_nonlinear_modes.hpp): the backbones
// with the sweep's peaks on them, and the modal damping ratio against the modal amplitude.
#pragma once
#include <filesystem>
#include <string>

#include "analysis/hbm_analysis.hpp"
#include "report/run_record.hpp"
#include "results/table.hpp"

namespace bb {

// Frequency against amplitude along each backbone (the compared peak component with `peaks`, else
// the first response), and the sweep's peaks of every level as points.
Plot plot_backbones(const HbmOutcome& hbm, const HbmSpec& spec, const ResultTable& nonlinear_modes,
                    const std::filesystem::path& out_dir, const std::string& stem);

// Modal damping ratio kappa / (2 omega) against the modal amplitude, one line per mode.
Plot plot_modal_damping(const HbmOutcome& hbm, const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
