// The accuracy-against-cost studies of a run (`--study`), as the last sections of its report.
#pragma once
#include <ostream>
#include <string>

#include "report/run_record.hpp"

namespace bb {

// "## Refinement study", "## Mesh convergence ...", "## Study: <table>", each with its plots.
void write_study_sections(std::ostream& out, const RunRecord& run);

// A column's name with the unit its suffix implies: "frequency_hz [Hz]", "damping_ratio".
std::string column_header(const std::string& column);

}  // namespace bb
