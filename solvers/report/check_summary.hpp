// The top of a case report, what a reviewer reads first: the verdict with each miss against its
// tolerance, and the checks one row each (their worst entry), every entry folded below.
#pragma once
#include <ostream>
#include <string>

#include "report/run_record.hpp"

namespace bb {

// "**FAIL**: 3 of 126 check entries miss their tolerance, in 2 of 5 checks. ..." and the misses,
// largest share of the tolerance first; for a run without a verdict, its status and message.
void write_verdict(std::ostream& out, const RunRecord& run);

// "## Checks": the pass rule, one row per check (worst entry, computed, reference, error, tolerance,
// share of the tolerance used, drawn as a bar), then every entry in a folded section.
void write_check_table(std::ostream& out, const RunRecord& run);

// The check of `e` (of that name) among run.check_specs, or nullptr (an entry the run adds itself,
// e.g. the fidelity target).
const CheckSpec* spec_of(const RunRecord& run, const CheckEntry& e);
const CheckSpec* spec_of(const RunRecord& run, const std::string& group);

// An entry's error as its tolerance is stated: signed percent of the reference when the check's
// tolerance is relative only, else signed in the column's unit; and that tolerance.
std::string entry_error(const CheckEntry& e, const CheckSpec* spec);
std::string entry_tolerance(const CheckEntry& e, const CheckSpec* spec);

// A text for a Markdown table cell: '|' escaped, line breaks as spaces.
std::string table_cell(const std::string& text);

}  // namespace bb
