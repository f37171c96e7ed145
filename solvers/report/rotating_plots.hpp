// Figures of a rotating analysis: the displacement histories of each node set in the rotating
// frame (as the thesis's Figs 2.15-2.18, 2.24-2.27, 2.35-2.36) and the Campbell diagram with its
// engine-order lines.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/rotating_analysis.hpp"
#include "report/run_record.hpp"
#include "results/table.hpp"

namespace bb {

// One figure per set and direction: u(t) with the steady static deflection as a dashed line; with
// zoom > 0 only the first `zoom` seconds. `tables`: the run's (its deflection and histories).
Plot plot_rotating_history(const RotatingOutcome& o, const ResultTables& tables, size_t set, int direction,
                           const std::filesystem::path& out_dir, const std::string& stem, double zoom = 0.0);
Plot plot_campbell(const RotatingOutcome& o, const std::vector<int>& engine_orders,
                   const std::filesystem::path& out_dir, const std::string& stem);

// The rotating fidelity study: each level's errors against its cost, log-log, labelled.
Plot plot_rotating_fidelity(const ResultTable& study, const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
