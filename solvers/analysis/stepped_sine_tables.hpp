// The tables of an hbm analysis's stepped sines (forced/hbm_stepped_sine.hpp): frf_<name> with the
// force of each point, and stepped_sine_cost.
#pragma once
#include <vector>

#include "forced/hbm_stepped_sine.hpp"
#include "results/table.hpp"

namespace bb {

// frf_<name>: per converged point in the order stepped: point (1-based in the spec), frequency_hz,
// force_n, then the columns of a level's frf table (amplitudes, phases, largest excursions,
// residual, iterations, sensitivities). stepped_sine_cost: per stepped sine its points, failures,
// iterations and seconds, with its name and first failure as text.
void add_stepped_sine_tables(const PreparedHbm& p, const HbmSpec& spec, const std::vector<HbmSteppedSine>& sines,
                             ResultTables& tables);

}  // namespace bb
