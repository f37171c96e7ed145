// The accuracy-against-cost studies of a run (`--study`), as the last sections of its report, and the
// Markdown pieces the case report writes the same way (column headers with units, plots).
#pragma once
#include <ostream>
#include <string>

#include "report/run_record.hpp"

namespace bb {

// "## Refinement study", "## Mesh convergence ...", "## Study: <table>", each with its plots.
void write_study_sections(std::ostream& out, const RunRecord& run);

// A column's name with the unit its suffix implies: "frequency_hz [Hz]", "damping_ratio".
std::string column_header(const std::string& column);

// A plot as a Markdown image, or "*title: not drawn (why)*" (one line, no paragraph break).
std::string plot_markdown(const Plot& p);

}  // namespace bb
