// The fidelity frontier of a run (`run --fidelity`): each level's estimated error against its cost.
#pragma once
#include <filesystem>
#include <string>

#include "report/run_record.hpp"
#include "results/table.hpp"
#include "study/fidelity_spec.hpp"

namespace bb {

// Log-log estimated error vs wall time, one series per axis, the chosen run circled and the
// target drawn as a line.
Plot plot_fidelity_frontier(const ResultTable& frontier, const FidelitySpec& fidelity,
                            const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
