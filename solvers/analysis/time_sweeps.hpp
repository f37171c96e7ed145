// The tables of a time analysis built from its levels (time_tables.cpp); the sweeps themselves are
// the forced-response layer's (forced/time_sweep.hpp).
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <utility>
#include <vector>

#include "analysis/time_analysis.hpp"
#include "forced/hbm_level.hpp"

namespace bb {

// frf, peaks, peaks_linear, peaks_hbm (compare_harmonics) and time_cost from o.levels on
// `frequencies`; a peak resting on a frequency without a steady state sets o.failure (the first).
void add_sweep_tables(TimeOutcome& o, const TimeSpec& spec, const std::vector<double>& frequencies,
                      const std::optional<std::pair<Eigen::Index, Eigen::Index>>& pair);

// history, hysteresis_<contact> and hysteresis_summary from o.record.
void add_history_tables(TimeOutcome& o, const TimeSpec& spec);

}  // namespace bb
