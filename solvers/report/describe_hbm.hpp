// The facts an hbm analysis adds to its report (describe_analysis.hpp dispatches to it).
#pragma once
#include <string>

#include "analysis/hbm_analysis.hpp"
#include "cache/cache_use.hpp"
#include "report/run_record.hpp"

namespace bb {

// Whether a reduction or a set of modes was computed here or came from the model cache.
void describe_cache(const std::string& what, const CacheUse& use, RunRecord& run);

void describe(const HbmSpec& spec, const HbmOutcome& hbm, RunRecord& run);

// The modal damping ratio, or the ratios given per mode with what they cover (frf and hbm alike).
std::string describe_modal_ratios(const FrfDamping& d);

// "name: kn .. N/m, kt .. N/m, mu .." per point contact (the damper's, then the case's, with its law
// when it is not a single Jenkins slider), "; "-separated; empty without contacts.
std::string describe_contacts(const PreparedHbm& p, const HbmSpec& spec);

// The excitation's levels as a run fact: force levels, or a base motion's accelerations and harmonics.
void describe_levels(const HbmSpec& spec, RunRecord& run);

}  // namespace bb
