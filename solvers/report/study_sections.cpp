#include "report/study_sections.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "report/number_format.hpp"

namespace bb {
namespace {

// Every row of `table` as a Markdown table, numbers to 5 significant digits.
void write_table_rows(std::ostream& out, const ResultTable& table) {
  std::vector<std::string> header;
  for (const std::string& c : table.columns) header.push_back(column_header(c));
  header.insert(header.end(), table.text_columns.begin(), table.text_columns.end());
  std::string rule = "|";
  for (size_t c = 0; c < header.size(); ++c) rule += "---|";
  out << fmt::format("| {} |\n{}\n", fmt::join(header, " | "), rule);
  for (Eigen::Index r = 0; r < table.values.rows(); ++r) {
    std::vector<std::string> cells = {std::to_string(std::lround(table.values(r, 0)))};
    for (Eigen::Index c = 1; c < table.values.cols(); ++c) cells.push_back(format_number(table.values(r, c)));
    for (const auto& column : table.text) cells.push_back(column[static_cast<size_t>(r)]);
    out << fmt::format("| {} |\n", fmt::join(cells, " | "));
  }
}

void write_plots(std::ostream& out, const std::vector<Plot>& list) {
  for (const Plot& p : list) out << plot_markdown(p) << "\n\n";
}

}  // namespace

std::string plot_markdown(const Plot& p) {
  return p.file.empty() ? fmt::format("*{}: not drawn ({})*", p.title, p.note)
                        : fmt::format("![{}]({})", p.title, p.file);
}

std::string column_header(const std::string& column) {
  const std::string unit = unit_of_column(column);
  return unit.empty() ? column : fmt::format("{} [{}]", column, unit);
}

void write_study_sections(std::ostream& out, const RunRecord& run) {
  if (run.study) {
    const RefinementResult& s = *run.study;
    out << "## Refinement study (accuracy vs cost)\n\n";
    if (!run.study_note.empty()) out << run.study_note << "\n\n";
    out << fmt::format(
        "Timoshenko beam tip deflection {:.6e} m (bending alone {:.6e} m); Richardson limit of the finite-element "
        "sequence {:.6e} m (order {:.2f}), which differs from Timoshenko by {:.2f}%.\n\n",
        s.beam_deflection, s.bending_only, s.extrapolated, s.extrapolation_order,
        100.0 * (s.extrapolated - s.beam_deflection) / s.beam_deflection);
    const RefinementRow& own = s.rows.front();
    out << fmt::format(
        "On the case's own mesh (level {}, {} x {}) the probe is {:+.2f}% off the converged finite-element answer and "
        "{:+.2f}% off Timoshenko.\n\n",
        own.level, own.nx, own.ny, 100 * own.error_vs_limit, 100 * own.error_vs_beam);
    out << "| level | nx x ny | free DOFs | probe [m] | error vs Timoshenko | error vs limit | observed order | "
           "assembly [s] | factor+solve [s] |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const RefinementRow& r : s.rows)
      out << fmt::format("| {} | {} x {} | {} | {:.6e} | {:+.3f}% | {:+.4f}% | {} | {:.4f} | {:.4f} |\n", r.level, r.nx,
                         r.ny, r.n_free_dofs, r.probe, 100 * r.error_vs_beam, 100 * r.error_vs_limit,
                         r.observed_order > 0 ? fmt::format("{:.2f}", r.observed_order) : std::string("-"),
                         r.assembly_seconds, r.solve_seconds);
    out << '\n';
    write_plots(out, run.study_plots);
  }
  if (run.modal_study) {
    const ModalRefinementResult& m = *run.modal_study;
    const ModalRefinementRow& ref = m.rows[static_cast<size_t>(m.reference_row)];
    out << "## Mesh convergence of the first frequencies (accuracy vs cost)\n\n";
    if (!run.study_note.empty()) out << run.study_note << "\n\n";
    out << fmt::format(
        "Errors are relative to the finest mesh of the study ({} at refinement {}, {} free DOFs), mode by "
        "mode in frequency order, over the first {} modes.\n\n",
        element_name(ref.element), ref.refinement, ref.n_free_dofs, m.modes);
    out << "| element | refinement | free DOFs | f1 [Hz] | f" << m.modes
        << " [Hz] | max error | rms error | assembly [s] | eigensolve [s] |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const ModalRefinementRow& r : m.rows)
      out << fmt::format("| {} | {} | {} | {:.3f} | {:.2f} | {:.3f}% | {:.3f}% | {:.2f} | {:.2f} |\n",
                         element_name(r.element), r.refinement, r.n_free_dofs, r.frequencies_hz.front(),
                         r.frequencies_hz.back(), 100 * r.max_error, 100 * r.rms_error, r.assembly_seconds,
                         r.solve_seconds);
    out << '\n';
    write_plots(out, run.study_plots);
  }
  for (const ResultTable& t : run.study_tables) {
    out << fmt::format("## Study: {} (accuracy vs cost)\n\n", t.name);
    if (!run.study_note.empty()) out << run.study_note << "\n\n";
    write_table_rows(out, t);
    out << '\n';
    write_plots(out, run.study_plots);
  }
}

}  // namespace bb
