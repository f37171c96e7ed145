// The facts a cyclic modal analysis adds to its report (describe_analysis.hpp dispatches to it).
#pragma once
#include "analysis/cyclic_modal_analysis.hpp"
#include "report/run_record.hpp"

namespace bb {

void describe(const CyclicModalSpec& spec, const CyclicModalOutcome& o, RunRecord& run);

}  // namespace bb
