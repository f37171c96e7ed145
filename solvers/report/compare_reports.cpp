#include "report/compare_reports.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "report/check_summary.hpp"
#include "report/number_format.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// Rows of the entries table shown before the rest is folded.
constexpr size_t kShownEntries = 60;

double number_or_nan(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : NAN;
}

CaseSummary read_summary(const fs::path& file, const std::string& name) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot read", printable(file.string())));
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    throw InputError(fmt::format("{}: not a bladebench summary (not a JSON object)", printable(file.string())));
  CaseSummary s;
  s.name = name;
  try {
    s.status = j.at("status").get<std::string>();
    s.wall_seconds = j.at("wall_time_s").get<double>();
    std::map<std::string, int> seen;  // entry names made unique by their repeat number
    for (const nlohmann::json& c : j.at("checks")) {
      EntrySummary e;
      e.name = c.at("name").get<std::string>();
      if (const int n = seen[e.name]++; n > 0) e.name += fmt::format(" (#{})", n + 1);
      e.column = c.value("column", std::string());
      e.computed = number_or_nan(c, "computed");
      e.reference = number_or_nan(c, "reference");
      e.tolerance = number_or_nan(c, "tolerance");
      e.used = number_or_nan(c, "tolerance_used");
      e.pass = c.at("pass").get<bool>();
      s.entries.push_back(std::move(e));
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a bladebench summary: {}", printable(file.string()), e.what()));
  }
  return s;
}

bool moved(double before, double after, double tolerance, double max_change) {
  if (std::isnan(before) || std::isnan(after)) return std::isnan(before) != std::isnan(after);
  if (before == after) return false;
  const double scale = std::max(std::abs(before), std::isfinite(tolerance) ? tolerance : 0.0);
  return !(std::abs(after - before) <= max_change * scale);
}

std::string relative_change(double before, double after) {
  if (before == after) return "0";
  if (before == 0.0 || !std::isfinite(before) || !std::isfinite(after)) return "-";
  return format_percent((after - before) / std::abs(before));
}

struct EntryRow {
  std::string case_name, entry, before, after, change, used, verdict;
  double size = 0.0;  // for ordering: flips and removals first, then moves by size, additions last
};

// The changes of one case in both runs: its entries' rows into `rows`, its counts into `r`; returns
// its row of the cases table.
std::string compare_case(const CaseSummary& before, const CaseSummary& after, const CompareOptions& options,
                         ReportComparison& r, std::vector<EntryRow>& rows) {
  const std::string& name = after.name;
  ++r.cases_compared;
  r.old_seconds += before.wall_seconds;
  r.new_seconds += after.wall_seconds;
  const bool flipped_status = before.status != after.status;
  r.statuses_flipped += flipped_status ? 1 : 0;
  std::map<std::string, const EntrySummary*> old_entries;
  for (const EntrySummary& e : before.entries) old_entries[e.name] = &e;
  int flipped = 0, moved_here = 0;
  for (const EntrySummary& e : after.entries) {
    const auto o = old_entries.find(e.name);
    if (o == old_entries.end()) {
      ++r.entries_added;
      rows.push_back({name, table_cell(e.name), "-", format_quantity(e.computed, unit_of_column(e.column)), "added",
                      format_share(e.used), e.pass ? "pass" : "**FAIL**", -1.0});
      continue;
    }
    const EntrySummary& b = *o->second;
    old_entries.erase(o);
    const bool flip = b.pass != e.pass;
    const bool move = moved(b.computed, e.computed, std::max(b.tolerance, e.tolerance), options.max_change) ||
                      moved(b.reference, e.reference, std::max(b.tolerance, e.tolerance), options.max_change);
    if (!flip && !move) continue;
    flipped += flip ? 1 : 0;
    moved_here += move ? 1 : 0;
    // Ordered by the share of the tolerance the move spends (a tolerance below a thousandth of the
    // value counts as that: one-sided checks may have none): a residual near zero that doubles
    // matters less than a frequency that moves by a tenth of its tolerance.
    const double scale = std::max(std::max(b.tolerance, e.tolerance), 1e-3 * std::abs(b.computed));
    const double change = std::abs(e.computed - b.computed);
    const double size = flip ? INFINITY : scale > 0.0 ? change / scale : change;
    const std::string unit = unit_of_column(e.column);
    rows.push_back(
        {name, table_cell(e.name), format_quantity(b.computed, unit), format_quantity(e.computed, unit),
         relative_change(b.computed, e.computed) +
             (b.reference != e.reference ? fmt::format(" (reference {} -> {})", format_quantity(b.reference, unit),
                                                       format_quantity(e.reference, unit))
                                         : std::string()),
         fmt::format("{} -> {}", format_share(b.used), format_share(e.used)),
         flip ? fmt::format("**{} -> {}**", b.pass ? "pass" : "fail", e.pass ? "pass" : "fail")
              : (e.pass ? "pass" : "**FAIL**"),
         size});
  }
  for (const auto& [entry_name, b] : old_entries) {
    ++r.entries_removed;
    rows.push_back({name, table_cell(entry_name), format_quantity(b->computed, unit_of_column(b->column)), "-",
                    "**removed**", format_share(b->used), "-", INFINITY});
  }
  r.entries_flipped += flipped;
  r.entries_moved += moved_here;
  const std::string ratio =
      before.wall_seconds > 0.0 ? fmt::format("{:.2f}", after.wall_seconds / before.wall_seconds) : std::string("-");
  return fmt::format("| {} | {} | {} | {} | {} -> {} | {} |\n", name,
                     flipped_status ? fmt::format("**{} -> {}**", before.status, after.status) : after.status, flipped,
                     moved_here, format_seconds(before.wall_seconds), format_seconds(after.wall_seconds), ratio);
}

// The page: what changed in one line, the cases table, then the entries that flipped, moved or came
// or went (long lists folded).
std::string comparison_page(const ReportComparison& r, const std::string& cases, const std::vector<EntryRow>& rows,
                            const CompareOptions& options, const std::string& old_label, const std::string& new_label) {
  std::ostringstream md;
  md << "# bladebench: what changed\n\n";
  md << fmt::format(
      "Old runs: `{}`; new runs: `{}`. A value moves when it changes by more than {} of the larger of "
      "its old size and its tolerance.\n\n",
      old_label, new_label, format_number(options.max_change));
  md << fmt::format(
      "**{}**: {} case{} compared ({} added, {} removed); {} status{} flipped; check entries: {} verdict{} flipped, "
      "{} value{} moved, {} removed, {} added. Run time of the cases in both: {} -> {} (ratio {}).\n\n",
      r.changed() ? "CHANGED" : "UNCHANGED", r.cases_compared, r.cases_compared == 1 ? "" : "s", r.cases_added,
      r.cases_removed, r.statuses_flipped, r.statuses_flipped == 1 ? "" : "es", r.entries_flipped,
      r.entries_flipped == 1 ? "" : "s", r.entries_moved, r.entries_moved == 1 ? "" : "s", r.entries_removed,
      r.entries_added, format_seconds(r.old_seconds), format_seconds(r.new_seconds),
      r.old_seconds > 0.0 ? fmt::format("{:.2f}", r.new_seconds / r.old_seconds) : std::string("-"));
  md << "## Cases\n\n| case | status | entries flipped | values moved | run time | ratio |\n|---|---|---|---|---|---|\n"
     << cases << '\n';
  if (!rows.empty()) {
    md << "## Check entries that flipped, moved, or came or went\n\nFlips and removals first, then the moves by the "
          "share of the tolerance they spend, then additions. *Used*: the share of its tolerance the entry uses, old "
          "-> new.\n\n";
    auto header = [&md] {
      md << "| case | entry | old | new | change | used | verdict |\n|---|---|---|---|---|---|---|\n";
    };
    header();
    for (size_t i = 0; i < rows.size(); ++i) {
      if (i == kShownEntries) {
        md << fmt::format("\n<details><summary>{} more entries</summary>\n\n", rows.size() - kShownEntries);
        header();
      }
      const EntryRow& e = rows[i];
      md << fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", e.case_name, e.entry, e.before, e.after, e.change,
                        e.used, e.verdict);
    }
    if (rows.size() > kShownEntries) md << "\n</details>\n";
    md << '\n';
  }
  return md.str();
}

}  // namespace

std::vector<CaseSummary> read_report_tree(const fs::path& root) {
  std::error_code ec;
  if (!fs::is_directory(root, ec))
    throw InputError(fmt::format("{}: not a folder (compare takes two report folders, e.g. two `validate --out`)",
                                 printable(root.string())));
  std::vector<CaseSummary> runs;
  // A summary.json that is a link loop or a device is named, not thrown as a filesystem error.
  const auto summary_in = [](const fs::path& folder) {
    const std::string why = file_problem(folder / "summary.json");
    if (!why.empty() && why != "no such file" && why != "it is a directory")
      throw InputError(fmt::format("{}: cannot open ({})", printable((folder / "summary.json").string()), why));
    return why.empty();
  };
  if (summary_in(root))
    return {read_summary(root / "summary.json", fs::absolute(root).lexically_normal().filename().string())};
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_directory(ec) && summary_in(entry.path()))
      runs.push_back(read_summary(entry.path() / "summary.json", entry.path().filename().string()));
  if (runs.empty())
    throw InputError(fmt::format("{}: not a report tree: no summary.json in it or in any folder directly under it",
                                 printable(root.string())));
  std::sort(runs.begin(), runs.end(), [](const CaseSummary& a, const CaseSummary& b) { return a.name < b.name; });
  return runs;
}

bool ReportComparison::changed() const {
  return cases_removed > 0 || statuses_flipped > 0 || entries_flipped > 0 || entries_moved > 0 || entries_removed > 0;
}

ReportComparison compare_reports(const std::vector<CaseSummary>& old_runs, const std::vector<CaseSummary>& new_runs,
                                 const CompareOptions& options, const std::string& old_label,
                                 const std::string& new_label) {
  ReportComparison r;
  std::map<std::string, const CaseSummary*> old_by_name, new_by_name;
  for (const CaseSummary& c : old_runs) old_by_name[c.name] = &c;
  for (const CaseSummary& c : new_runs) new_by_name[c.name] = &c;
  std::string cases;  // one row per case
  std::vector<EntryRow> rows;
  for (const auto& [name, before] : old_by_name)
    if (!new_by_name.count(name)) {
      ++r.cases_removed;
      cases += fmt::format("| {} | {} -> **removed** | - | - | - | - |\n", name, before->status);
    }
  for (const auto& [name, after] : new_by_name) {
    const auto it = old_by_name.find(name);
    if (it == old_by_name.end()) {
      ++r.cases_added;
      cases += fmt::format("| {} | added: {} | - | - | - | - |\n", name, after->status);
      continue;
    }
    cases += compare_case(*it->second, *after, options, r, rows);
  }
  std::stable_sort(rows.begin(), rows.end(), [](const EntryRow& a, const EntryRow& b) { return a.size > b.size; });
  r.markdown = printable(comparison_page(r, cases, rows, options, old_label, new_label), true);
  return r;
}

}  // namespace bb
