// Output files of a run: result CSVs, summary.json, report.md. User text reaches them only through
// printable() (common/user_text.hpp), so no input byte can make a writer fail or a report lie.
#pragma once
#include <cmath>
#include <filesystem>
#include <optional>
#include <vector>

#include "report/run_record.hpp"
#include "results/table.hpp"

namespace bb {

// Header row = column names; the key column is written as an integer, NaN and inf as nan and inf.
void write_table_csv(const ResultTable& table, const std::filesystem::path& file);
// Writes `folder/<table.name>.csv` (or `folder/<file>`) and records in `run` its file name (in
// run.tables unless a file name is given: a study table) and its columns with NaN / inf entries.
void write_result_csv(const ResultTable& table, const std::filesystem::path& folder, RunRecord& run,
                      const std::string& file = {});
void write_summary_json(const RunRecord& run, const std::filesystem::path& file);
void write_report_md(const RunRecord& run, const std::filesystem::path& file);

struct IndexEntry {
  std::string case_name;
  std::filesystem::path report;  // relative to the index
  RunStatus status = RunStatus::solver_failed;
  int checks = 0;
  int failed = 0;
  double wall_seconds = 0.0;
  std::string message;
  std::string fidelity;            // RunRecord::fidelity
  double worst_used = NAN;         // the largest share of its tolerance a check entry uses; NaN: no checks
  std::filesystem::path key_plot;  // the first key plot, relative to the index; empty: none
};
// The entry of a run from the summary.json in `out_dir`, paths relative to `index_dir`; nullopt
// when there is none or it cannot be read.
std::optional<IndexEntry> read_index_entry(const std::filesystem::path& out_dir,
                                           const std::filesystem::path& index_dir);
// The index as a dashboard: failing cases first, then by the share of the tolerance used (near
// misses next), each with its worst share drawn as a bar and its key plot as a thumbnail.
void write_index_md(std::vector<IndexEntry> entries, const std::filesystem::path& file);

}  // namespace bb
