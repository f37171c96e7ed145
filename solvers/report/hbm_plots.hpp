// Plots of nonlinear forced responses: the response at every force level (thesis Fig 3.61), the
// same per newton with the free and fully stuck limits (Figs 3.62-3.63), the damper performance
// curves (Figs 3.64-3.67) and the contact state map at the peaks.
#pragma once
#include <filesystem>
#include <string>

#include "analysis/hbm_analysis.hpp"
#include "report/run_record.hpp"
#include "results/table.hpp"

namespace bb {

// Response `response` (index into the analysis's responses) at each level; per newton of the first
// force with the linear limits when `per_newton`.
Plot plot_hbm_levels(const HbmOutcome& hbm, size_t response, bool per_newton, const std::filesystem::path& out_dir,
                     const std::string& stem);

// Peak frequency (`quantity` = "hz") or amplitude per newton ("amp_per_n") of every peak kind
// against CF / Fe (or Fe without a damper); with the reference's columns of the same names (key
// "level") when `reference` is not empty.
Plot plot_hbm_performance(const HbmOutcome& hbm, const std::string& quantity, const std::filesystem::path& reference,
                          const std::filesystem::path& out_dir, const std::string& stem);

// Fraction of the period each contact sticks and is lifted off at the peaks of `kind` ("IP", "OOP",
// "peak") against CF / Fe (or Fe).
Plot plot_contact_states(const HbmOutcome& hbm, const std::string& kind, const std::filesystem::path& out_dir,
                         const std::string& stem);

// Harmonics study (study/hbm_study.hpp): relative error of each peak amplitude against the cost
// of its sweep, one line per force level and peak kind, labelled by H.
Plot plot_hbm_harmonics_study(const ResultTable& study, const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
