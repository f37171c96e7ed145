// Every force level of a harmonic-balance analysis: on spec.threads workers in one process, or,
// when a run's ranks share one case under mpirun, level i on rank i % ranks. Either way each level
// starts from the previous level's first solution (forced/level_relay.hpp) and the levels are
// those of the serial run, bit for bit, on every rank.
#pragma once
#include <vector>

#include "forced/hbm_level.hpp"

namespace bb {

// A level that throws stops none of the others; the exception of the first such level (in level
// order) is rethrown once all have ended, as the serial run would have stopped there.
std::vector<HbmLevel> sweep_levels(const PreparedHbm& prepared, const HbmSpec& spec, const HbmProgress& progress);

}  // namespace bb
