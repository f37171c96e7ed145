// Time-domain forced response (thesis section 3.4): the model of a harmonic-balance analysis
// (analysis/hbm_level.hpp: reduced or lumped model, contacts, rigid damper seated by CF)
// integrated by Newmark with the implicit predictor-corrector contact (timeint/newmark.hpp) to the
// steady state at each frequency of a grid (stepped sine), each frequency starting from the
// previous one's final state; time histories and hysteresis loops at one frequency; and the
// harmonic balance at the same frequencies, for cross-validation.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "forced/hbm_level.hpp"
#include "forced/time_spec.hpp"
#include "forced/time_sweep.hpp"
#include "results/table.hpp"
#include "timeint/steady_state.hpp"

namespace bb {

struct TimeOutcome {
  ResultTables tables;
  PreparedHbm prepared;
  std::vector<TimeLevel> levels;
  std::optional<TimeHistoryRecord> record;
  double seconds = 0.0;
  // The first peak that rests on a frequency without a steady state (or periodic solution); its
  // row holds NaN for that peak, and the run has no verdict. Empty: every peak stands.
  std::string failure;
};

// Throws as prepare_hbm; a frequency that does not reach the steady state, or a Newmark step that
// fails, is reported in the tables (steady = 0, with the change or the message), never thrown; a
// peak resting on one is `failure`. The reduction goes through the model cache in `cache`, when given.
TimeOutcome run_time(const Model& model, const TimeSpec& spec, const HbmProgress& progress = {},
                     const ModelCacheSettings* cache = nullptr);

}  // namespace bb
