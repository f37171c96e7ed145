// report.md of one run, in the order a reviewer reads it: verdict, key plots, checks, description,
// inputs, then the long tables (folded), the other plots and the studies.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/user_text.hpp"
#include "report/check_summary.hpp"
#include "report/number_format.hpp"
#include "report/study_sections.hpp"
#include "report/writers.hpp"

namespace bb {
namespace {

// Tables longer than this are folded; longer than kInlineRows, only linked as their CSV.
constexpr Eigen::Index kShownRows = 12;
constexpr Eigen::Index kInlineRows = 400;
constexpr size_t kShownFacts = 25;

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

// A result table with text labels, row by row, with each checked row's reference, signed error and
// verdict (the tightest tolerance of the checks that read it); folded when long.
void write_listed_table(std::ostream& out, const RunRecord& run, const ResultTable& table) {
  std::vector<const CheckEntry*> entries;  // checks of this table
  for (const CheckEntry& e : run.checks)
    if (const CheckSpec* spec = spec_of(run, e); spec && spec->result == table.name) entries.push_back(&e);
  const Eigen::Index rows = table.values.rows();
  out << fmt::format("## {}\n\n", table.name == "frequencies" ? std::string("Modes") : table.name);
  if (rows > kInlineRows) {
    out << fmt::format("{} rows: [`{}.csv`]({}.csv).\n\n", rows, table.name, table.name);
    return;
  }
  if (rows > kShownRows)
    out << fmt::format("{} rows; full precision in [`{}.csv`]({}.csv).\n\n<details><summary>{}: {} rows</summary>\n\n",
                       rows, table.name, table.name, table.name, rows);
  std::vector<std::string> header;
  for (const std::string& c : table.columns) header.push_back(column_header(c));
  header.insert(header.end(), table.text_columns.begin(), table.text_columns.end());
  if (!entries.empty()) header.insert(header.end(), {"reference", "error", "checks"});
  std::string rule = "|";
  for (size_t c = 0; c < header.size(); ++c) rule += "---|";
  out << fmt::format("| {} |\n{}\n", fmt::join(header, " | "), rule);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const long key = std::lround(table.values(r, 0));
    std::vector<std::string> cells = {std::to_string(key)};
    for (Eigen::Index c = 1; c < table.values.cols(); ++c) cells.push_back(format_number(table.values(r, c)));
    for (const auto& column : table.text) cells.push_back(table_cell(column[static_cast<size_t>(r)]));
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
        cells.push_back(format_quantity(first->reference, unit_of_column(first->column)));
        cells.push_back(format_percent((first->computed - first->reference) / scale));
        cells.push_back(
            fmt::format("{} (tolerance {})", pass ? "pass" : "**FAIL**", format_percent(tightest / scale).substr(1)));
      } else {
        cells.insert(cells.end(), {"-", "-", "-"});
      }
    }
    out << fmt::format("| {} |\n", fmt::join(cells, " | "));
  }
  out << (rows > kShownRows ? "\n</details>\n\n" : "\n");
}

bool is_key(const RunRecord& run, const Plot& p) {
  return std::find(run.key_plots.begin(), run.key_plots.end(), p.name) != run.key_plots.end();
}

void write_facts(std::ostream& out, const RunRecord& run) {
  if (run.facts.empty()) return;
  out << "## Inputs and solver\n\n";
  const bool fold = run.facts.size() > kShownFacts;
  if (fold) out << fmt::format("<details><summary>Inputs and solver: {} items</summary>\n\n", run.facts.size());
  out << "| item | value |\n|---|---|\n";
  for (const auto& [k, v] : run.facts) out << fmt::format("| {} | {} |\n", table_cell(k), table_cell(v));
  out << (fold ? "\n</details>\n\n" : "\n");
}

}  // namespace

void write_report_md(const RunRecord& run, const std::filesystem::path& file) {
  std::ostringstream out;  // written through printable() at the end
  out << fmt::format("# {}\n\n", run.title);
  write_verdict(out, run);
  out << fmt::format("Case `{}`, file `{}`, status `{}`.\n\n", run.case_name, run.case_file.string(),
                     status_name(run.status));
  if (!run.message.empty()) out << fmt::format("> {}\n\n", run.message);
  for (const std::string& w : run.warnings) out << fmt::format("> **Warning:** {}\n\n", w);
  // In one paragraph: two key plots stand side by side in the HTML page (its style sheet).
  std::string key;
  for (const std::string& name : run.key_plots)
    for (const Plot& p : run.plots)
      if (p.name == name) key += plot_markdown(p) + '\n';
  if (!key.empty()) out << key << '\n';
  write_check_table(out, run);
  if (!run.description.empty()) out << "## Description and assumptions\n\n" << run.description << "\n\n";
  write_facts(out, run);
  for (const ResultTable& table : run.listed_tables) write_listed_table(out, run, table);
  if (!run.tables.empty()) {
    out << "## Result tables\n\n";
    for (const std::string& t : run.tables) out << fmt::format("- [`{}`]({})\n", t, t);
    out << '\n';
  }
  write_non_finite(out, run);
  bool heading = false;
  for (const Plot& p : run.plots) {
    if (is_key(run, p)) continue;
    if (!heading) out << (run.key_plots.empty() ? "## Plots\n\n" : "## Other plots\n\n");
    heading = true;
    out << plot_markdown(p) << "\n\n";
  }
  write_study_sections(out, run);
  std::ofstream report(file);
  if (!report) throw std::runtime_error("cannot write " + file.string());
  report << printable(out.str(), true);
  if (!report) throw std::runtime_error("failed writing " + file.string());
}

}  // namespace bb
