#include "report/writers.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/user_text.hpp"
#include "report/output_folder.hpp"

namespace bb {
namespace {

std::ofstream open_for_writing(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out.precision(17);
  return out;
}

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

// Every string of `j`, keys too, through printable(): summary.json shows user bytes as the
// terminal and report.md do (\xHH), and its writer cannot fail on them.
nlohmann::json printable_json(const nlohmann::json& j) {
  if (j.is_string()) return printable(j.get_ref<const std::string&>(), true);
  if (j.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const nlohmann::json& e : j) out.push_back(printable_json(e));
    return out;
  }
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [k, v] : j.items()) out[printable(k)] = printable_json(v);
    return out;
  }
  return j;
}

// "3, 7, 9" or "1, 2, 3, 4, 5, ... (40 rows)".
std::string key_list(const std::vector<long>& keys) {
  constexpr size_t kShown = 12;
  if (keys.size() <= kShown) return fmt::format("{}", fmt::join(keys, ", "));
  return fmt::format("{}, ... ({} rows)", fmt::join(keys.begin(), keys.begin() + kShown, ", "), keys.size());
}

// The checks that read an entry of a non-finite column (each such entry fails).
std::string readers_of(const RunRecord& run, const NonFiniteColumn& n) {
  std::set<std::string> names;
  for (const CheckEntry& e : run.checks)
    for (const CheckSpec& spec : run.check_specs)
      if (spec.name == e.group && spec.result + ".csv" == n.file && e.column == n.column &&
          std::find(n.keys.begin(), n.keys.end(), e.computed_key) != n.keys.end())
        names.insert(spec.name);
  return names.empty() ? std::string("none") : fmt::format("{} (failed)", fmt::join(names, "; "));
}

void write_non_finite(std::ostream& out, const RunRecord& run) {
  if (run.non_finite.empty()) return;
  out << "### Entries without a value\n\n"
         "These columns hold NaN or inf entries, written as `nan` / `inf`: values that do not apply to the row (no "
         "peak found, no closed form, a variant that diverged). A check that reads one fails.\n\n"
         "| file | column | rows (by key) | read by a check |\n|---|---|---|---|\n";
  for (const NonFiniteColumn& n : run.non_finite)
    out << fmt::format("| {} | {} | {} = {} | {} |\n", n.file, n.column, n.key_column, key_list(n.keys),
                       readers_of(run, n));
  out << '\n';
}

std::string sci(double v) { return std::isfinite(v) ? fmt::format("{:.4e}", v) : std::string("inf"); }

// A result table row by row, with its text labels and, where a check compared a row, the
// reference value, the signed relative error, whether every check of that row passed and the
// tightest tolerance among them (relative to the reference).
// Every row of `table` as a markdown table, numbers to 4 significant digits.
void write_table_rows(std::ostream& out, const ResultTable& table) {
  std::vector<std::string> header = table.columns;
  header.insert(header.end(), table.text_columns.begin(), table.text_columns.end());
  std::string rule = "|";
  for (size_t c = 0; c < header.size(); ++c) rule += "---|";
  out << fmt::format("| {} |\n{}\n", fmt::join(header, " | "), rule);
  for (Eigen::Index r = 0; r < table.values.rows(); ++r) {
    std::vector<std::string> cells = {std::to_string(std::lround(table.values(r, 0)))};
    for (Eigen::Index c = 1; c < table.values.cols(); ++c) cells.push_back(fmt::format("{:.4g}", table.values(r, c)));
    for (const auto& column : table.text) cells.push_back(column[static_cast<size_t>(r)]);
    out << fmt::format("| {} |\n", fmt::join(cells, " | "));
  }
}

void write_listed_table(std::ostream& out, const RunRecord& run, const ResultTable& table) {
  std::vector<const CheckEntry*> entries;  // checks of this table
  for (const CheckEntry& e : run.checks)
    for (const CheckSpec& spec : run.check_specs)
      if (spec.name == e.group && spec.result == table.name) {
        entries.push_back(&e);
        break;
      }
  out << fmt::format("## {}\n\n", table.name == "frequencies" ? std::string("Modes") : table.name);
  std::vector<std::string> header = table.columns;
  header.insert(header.end(), table.text_columns.begin(), table.text_columns.end());
  if (!entries.empty()) header.insert(header.end(), {"reference", "error", "checks"});
  std::string rule = "|";
  for (size_t c = 0; c < header.size(); ++c) rule += "---|";
  out << fmt::format("| {} |\n{}\n", fmt::join(header, " | "), rule);
  for (Eigen::Index r = 0; r < table.values.rows(); ++r) {
    const long key = std::lround(table.values(r, 0));
    std::vector<std::string> cells = {std::to_string(key)};
    for (Eigen::Index c = 1; c < table.values.cols(); ++c) cells.push_back(fmt::format("{:.6g}", table.values(r, c)));
    for (const auto& column : table.text) cells.push_back(column[static_cast<size_t>(r)]);
    if (!entries.empty()) {
      const CheckEntry* first = nullptr;
      bool pass = true;
      double tightest = INFINITY;  // the smallest tolerance any check applies to this row
      for (const CheckEntry* e : entries)
        if (e->key == key) {
          if (!first) first = e;
          pass = pass && e->pass;
          tightest = std::min(tightest, e->tolerance);
        }
      if (first && first->reference != 0.0) {
        const double scale = std::abs(first->reference);
        cells.push_back(fmt::format("{:.6g}", first->reference));
        cells.push_back(fmt::format("{:+.2f}%", 100.0 * (first->computed - first->reference) / scale));
        cells.push_back(fmt::format("{} (tolerance {:.3g}%)", pass ? "pass" : "**FAIL**", 100.0 * tightest / scale));
      } else {
        cells.insert(cells.end(), {"-", "-", "-"});
      }
    }
    out << fmt::format("| {} |\n", fmt::join(cells, " | "));
  }
  out << '\n';
}

}  // namespace

std::string status_name(RunStatus status) {
  switch (status) {
    case RunStatus::pass:
      return "pass";
    case RunStatus::fail:
      return "fail";
    case RunStatus::no_checks:
      return "no_checks";
    case RunStatus::bad_input:
      return "bad_input";
    case RunStatus::solver_failed:
      return "solver_failed";
  }
  return "?";
}

int exit_code(RunStatus status) {
  switch (status) {
    case RunStatus::pass:
    case RunStatus::no_checks:
      return 0;
    case RunStatus::fail:
      return 1;
    case RunStatus::bad_input:
      return 2;
    case RunStatus::solver_failed:
      return 3;
  }
  return 3;
}

void write_table_csv(const ResultTable& table, const std::filesystem::path& file) {
  std::ofstream out = open_for_writing(file);
  std::vector<std::string> header = table.columns;
  for (const std::string& c : table.text_columns) header.push_back(csv_field(c));
  out << fmt::format("{}\n", fmt::join(header, ","));
  for (Eigen::Index r = 0; r < table.values.rows(); ++r) {
    out << std::lround(table.values(r, 0));
    for (Eigen::Index c = 1; c < table.values.cols(); ++c) out << fmt::format(",{:.12g}", table.values(r, c));
    for (const auto& column : table.text) out << ',' << csv_field(printable(column[static_cast<size_t>(r)], true));
    out << '\n';
  }
  if (!out) throw std::runtime_error("failed writing " + file.string());
}

void write_result_csv(const ResultTable& table, const std::filesystem::path& folder, RunRecord& run,
                      const std::string& file) {
  const std::string name = file.empty() ? table.name + ".csv" : file;
  // Table names made of user names (reduced models, cases) were checked by the case parser.
  if (name.find_first_of(std::string("/\\\0", 3)) != std::string::npos || name.starts_with("."))
    throw std::logic_error(fmt::format("result table '{}' cannot name a file", printable(table.name)));
  write_table_csv(table, folder / name);
  if (file.empty()) run.tables.push_back(name);
  for (Eigen::Index c = 1; c < table.values.cols(); ++c) {
    NonFiniteColumn n{name, table.columns[static_cast<size_t>(c)], table.columns.front(), {}};
    for (Eigen::Index r = 0; r < table.values.rows(); ++r)
      if (!std::isfinite(table.values(r, c))) n.keys.push_back(std::lround(table.values(r, 0)));
    if (!n.keys.empty()) run.non_finite.push_back(std::move(n));
  }
}

void write_summary_json(const RunRecord& run, const std::filesystem::path& file) {
  nlohmann::json j;
  j["case"] = run.case_name;
  j["case_file"] = run.case_file.string();
  j["status"] = status_name(run.status);
  j["wall_time_s"] = run.wall_seconds;
  j["fidelity"] = run.fidelity.empty() ? std::string("case settings") : run.fidelity;
  if (!run.message.empty()) j["message"] = run.message;
  if (!run.warnings.empty()) j["warnings"] = run.warnings;
  j["checks"] = nlohmann::json::array();
  for (const CheckEntry& c : run.checks) {
    j["checks"].push_back(
        {{"name", c.name},
         {"computed", c.computed},
         {"reference", c.reference},
         {"abs_error", c.abs_error},
         {"rel_error", std::isfinite(c.rel_error) ? nlohmann::json(c.rel_error) : nlohmann::json(nullptr)},
         {"tolerance", c.tolerance},
         {"pass", c.pass}});
  }
  nlohmann::json facts = nlohmann::json::object();
  for (const auto& [k, v] : run.facts) facts[k] = v;
  j["facts"] = facts;
  j["tables"] = run.tables;
  j["non_finite"] = nlohmann::json::array();
  for (const NonFiniteColumn& n : run.non_finite)
    j["non_finite"].push_back({{"file", n.file}, {"column", n.column}, {"key_column", n.key_column}, {"keys", n.keys}});
  std::ofstream out = open_for_writing(file);
  // printable_json escapes every invalid byte; `replace` is the backstop that keeps dump() from throwing.
  out << printable_json(j).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  if (!out) throw std::runtime_error("failed writing " + file.string());
}

void write_report_md(const RunRecord& run, const std::filesystem::path& file) {
  std::ostringstream out;  // written through printable() at the end
  out << fmt::format("# {}\n\n", run.title);
  out << fmt::format("Case `{}` (`{}`): **{}** in {:.3f} s.\n\n", run.case_name, run.case_file.string(),
                     status_name(run.status), run.wall_seconds);
  if (!run.message.empty()) out << fmt::format("> {}\n\n", run.message);
  for (const std::string& w : run.warnings) out << fmt::format("> **Warning:** {}\n\n", w);
  if (!run.description.empty()) out << run.description << "\n\n";
  if (!run.facts.empty()) {
    out << "## Inputs and solver\n\n| item | value |\n|---|---|\n";
    for (const auto& [k, v] : run.facts) out << fmt::format("| {} | {} |\n", k, v);
    out << '\n';
  }
  if (!run.check_specs.empty()) {
    out << "## Checks\n\nAn entry passes when |computed - reference| <= abs_tol + rel_tol * |reference| (expect `=`), "
           "or, one-sided,\n"
           "when computed <= reference + tolerance (`<=`) or computed >= reference - tolerance (`>=`).\n\n";
    out << "| check | reference | expect | source | abs_tol | rel_tol | entries | failed | max abs error | max rel "
           "error |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const CheckSpec& spec : run.check_specs) {
      int n = 0, failed = 0;
      double max_abs = 0.0, max_rel = 0.0;
      for (const CheckEntry& e : run.checks) {
        if (e.group != spec.name) continue;
        ++n;
        failed += e.pass ? 0 : 1;
        max_abs = std::max(max_abs, e.abs_error);
        if (std::isfinite(e.rel_error) && e.reference != 0.0) max_rel = std::max(max_rel, e.rel_error);
      }
      const std::string reference =
          !spec.reference_case.empty() && spec.reference_result.empty()
              ? fmt::format("{}, numbered by the modes of {}", spec.reference.filename().string(),
                            spec.reference_case.filename().string())
          : !spec.reference_case.empty()
              ? fmt::format("result {} of {}", spec.reference_result, spec.reference_case.filename().string())
          : spec.reference_result.empty() ? spec.reference.filename().string()
                                          : "result " + spec.reference_result;
      const std::string paired = spec.match == CheckSpec::Match::mac
                                     ? fmt::format(", modes paired by shape (MAC >= {})", spec.min_mac)
                                 : spec.match == CheckSpec::Match::label
                                     ? fmt::format(", rows paired by label ({})", fmt::join(spec.labels, ", "))
                                     : "";
      out << fmt::format("| {} | `{}`{} | {} | {} | {} | {} | {} | {} | {} | {} |\n", spec.name, reference, paired,
                         relation_symbol(spec.relation), spec.source.empty() ? "-" : spec.source, sci(spec.abs_tol),
                         sci(spec.rel_tol), n, failed, sci(max_abs), sci(max_rel));
    }
    out << "\n<details><summary>Every entry</summary>\n\n";
    out << "| entry | computed | reference | abs error | rel error | tolerance | pass "
           "|\n|---|---|---|---|---|---|---|\n";
    for (const CheckEntry& e : run.checks)
      out << fmt::format("| {} | {:.9e} | {:.9e} | {} | {} | {} | {} |\n", e.name, e.computed, e.reference,
                         sci(e.abs_error), sci(e.rel_error), sci(e.tolerance), e.pass ? "pass" : "**FAIL**");
    out << "\n</details>\n\n";
  }
  for (const ResultTable& table : run.listed_tables) write_listed_table(out, run, table);
  if (!run.tables.empty()) {
    out << "## Result tables\n\n";
    for (const std::string& t : run.tables) out << fmt::format("- [`{}`]({})\n", t, t);
    out << '\n';
  }
  write_non_finite(out, run);
  auto plots = [&out](const std::vector<Plot>& list) {
    for (const Plot& p : list) {
      if (p.file.empty()) {
        out << fmt::format("*{}: not drawn ({})*\n\n", p.title, p.note);
      } else {
        out << fmt::format("![{}]({})\n\n", p.title, p.file);
      }
    }
  };
  if (!run.plots.empty()) {
    out << "## Plots\n\n";
    plots(run.plots);
  }
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
    plots(run.study_plots);
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
    for (const Plot& p : run.study_plots)
      out << (p.file.empty() ? fmt::format("*{}: not drawn ({})*\n\n", p.title, p.note)
                             : fmt::format("![{}]({})\n\n", p.title, p.file));
  }
  for (const ResultTable& t : run.study_tables) {
    out << fmt::format("## Study: {} (accuracy vs cost)\n\n", t.name);
    if (!run.study_note.empty()) out << run.study_note << "\n\n";
    write_table_rows(out, t);
    out << '\n';
    plots(run.study_plots);
  }
  std::ofstream report = open_for_writing(file);
  report << printable(out.str(), true);
  if (!report) throw std::runtime_error("failed writing " + file.string());
}

void write_index_md(const std::vector<IndexEntry>& entries, const std::filesystem::path& file) {
  std::ostringstream out;
  int passed = 0;
  for (const auto& e : entries) passed += exit_code(e.status) == 0 ? 1 : 0;
  out << "# bladebench validation index\n\n";
  out << fmt::format("{} of {} cases passed.\n\n", passed, entries.size());
  out << "| case | status | checks | failed | wall time [s] | fidelity | note |\n|---|---|---|---|---|---|---|\n";
  for (const auto& e : entries)
    out << fmt::format("| [{}]({}) | {} | {} | {} | {:.3f} | {} | {} |\n", e.case_name, e.report.generic_string(),
                       status_name(e.status), e.checks, e.failed, e.wall_seconds,
                       e.fidelity.empty() ? std::string("case settings") : e.fidelity, e.message);
  write_file_atomically(file, printable(out.str(), true));
}

}  // namespace bb
