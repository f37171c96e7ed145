// What changed between two validation runs (`bladebench compare OLD NEW`): per case, statuses that
// flipped and the run-time ratio; per check entry, the change of its computed value and of the share
// of its tolerance it uses, and verdicts that flipped. Read from the runs' summary.json files only.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace bb {

struct EntrySummary {
  std::string name;    // unique within its case
  std::string column;  // the compared result column (its unit)
  double computed = 0.0;
  double reference = 0.0;
  double tolerance = 0.0;
  double used = 0.0;  // share of the tolerance (NaN when summary.json has none)
  bool pass = false;
};

struct CaseSummary {
  std::string name;  // the report folder's name
  std::string status;
  double wall_seconds = 0.0;
  std::vector<EntrySummary> entries;
};

// Every run of a report tree: `root/summary.json` (one case's folder) or `root/<case>/summary.json`
// (a validate --out folder), ordered by name. InputError naming the path when `root` is not a
// folder or holds no summary, or naming the file and key of a summary that cannot be read.
std::vector<CaseSummary> read_report_tree(const std::filesystem::path& root);

struct CompareOptions {
  // A value moves when it changes by more than this share of the larger of its old size and its
  // tolerance: below the tolerance's scale a change is noise, not a result that moved.
  double max_change = 1e-6;
};

struct ReportComparison {
  int cases_compared = 0;
  int cases_added = 0;
  int cases_removed = 0;
  int statuses_flipped = 0;
  int entries_flipped = 0;  // pass <-> fail
  int entries_moved = 0;    // computed value beyond max_change
  int entries_removed = 0;  // in OLD, not in NEW
  int entries_added = 0;
  double old_seconds = 0.0;  // of the cases in both
  double new_seconds = 0.0;
  std::string markdown;  // the page: summary, one row per case, then the entries that flipped or moved
  // A change a merge must explain: a flipped status or verdict, a moved value, a removed case or entry.
  bool changed() const;
};

ReportComparison compare_reports(const std::vector<CaseSummary>& old_runs, const std::vector<CaseSummary>& new_runs,
                                 const CompareOptions& options, const std::string& old_label,
                                 const std::string& new_label);

}  // namespace bb
