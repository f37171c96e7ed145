// Plots of time-domain forced responses: the stepped-sine FRF against the harmonic balance at the
// same frequencies (thesis Figs 3.68-3.71), hysteresis loops (Figs 3.80, 3.85-3.87), contact forces
// and displacement histories over the recorded periods.
#pragma once
#include <filesystem>
#include <string>

#include "analysis/time_analysis.hpp"
#include "report/run_record.hpp"
#include "results/table.hpp"

namespace bb {

// Response `response` of every level, time integration (points) and harmonic balance (lines).
Plot plot_time_frf(const TimeOutcome& time, size_t response, const std::filesystem::path& out_dir,
                   const std::string& stem);

// Tangential force against relative tangential displacement of every contact over the recorded periods.
Plot plot_hysteresis(const TimeOutcome& time, const std::filesystem::path& out_dir, const std::string& stem);

// Normal and tangential force of every contact against time over the recorded periods.
Plot plot_contact_forces(const TimeOutcome& time, const std::filesystem::path& out_dir, const std::string& stem);

// Time-step study (study/time_study.hpp): largest amplitude error over the grid against the cost,
// one line per steady-state tolerance, points labelled by the steps per period.
Plot plot_time_step_study(const ResultTable& study, const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
