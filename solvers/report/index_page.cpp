// index.md of a validation run: the dashboard of every case.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/user_text.hpp"
#include "report/check_summary.hpp"
#include "report/number_format.hpp"
#include "report/output_folder.hpp"
#include "report/writers.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// A case whose worst entry uses more than this share of its tolerance is a near miss.
constexpr double kNearMiss = 0.8;

// Failed verdicts first (a miss, then runs without a verdict), then passes.
int severity(RunStatus status) {
  switch (status) {
    case RunStatus::fail:
      return 0;
    case RunStatus::solver_failed:
      return 1;
    case RunStatus::bad_input:
      return 2;
    case RunStatus::pass:
      return 3;
    case RunStatus::no_checks:
      return 4;
  }
  return 5;
}

}  // namespace

std::optional<IndexEntry> read_index_entry(const fs::path& out_dir, const fs::path& index_dir) {
  try {
    std::ifstream in(out_dir / "summary.json");
    if (!in) return std::nullopt;
    const nlohmann::json j = nlohmann::json::parse(in);
    IndexEntry e;
    e.case_name = j.at("case").get<std::string>();
    e.report = fs::relative(out_dir / "report.md", index_dir);
    e.wall_seconds = j.at("wall_time_s").get<double>();
    e.message = j.value("message", std::string());
    e.fidelity = j.value("fidelity", std::string());
    const std::string status = j.at("status").get<std::string>();
    for (RunStatus st :
         {RunStatus::pass, RunStatus::fail, RunStatus::no_checks, RunStatus::bad_input, RunStatus::solver_failed})
      if (status_name(st) == status) e.status = st;
    for (const auto& c : j.at("checks")) {
      ++e.checks;
      e.failed += c.at("pass").get<bool>() ? 0 : 1;
    }
    if (e.checks > 0) {
      const auto worst = j.find("worst_tolerance_used");
      // null with checks: a failed entry without a finite error.
      e.worst_used = worst != j.end() && worst->is_number() ? worst->get<double>() : INFINITY;
    }
    if (const auto plots = j.find("key_plots"); plots != j.end() && plots->is_array() && !plots->empty())
      e.key_plot = fs::relative(out_dir / plots->front().get<std::string>(), index_dir);
    return e;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

void write_index_md(std::vector<IndexEntry> entries, const fs::path& file) {
  std::stable_sort(entries.begin(), entries.end(), [](const IndexEntry& a, const IndexEntry& b) {
    if (severity(a.status) != severity(b.status)) return severity(a.status) < severity(b.status);
    const double ua = std::isnan(a.worst_used) ? -INFINITY : a.worst_used;
    const double ub = std::isnan(b.worst_used) ? -INFINITY : b.worst_used;
    return ua > ub;
  });
  int passed = 0, near = 0;
  double total = 0.0;
  for (const IndexEntry& e : entries) {
    passed += exit_code(e.status) == 0 ? 1 : 0;
    near += e.status == RunStatus::pass && e.worst_used > kNearMiss ? 1 : 0;
    total += e.wall_seconds;
  }
  std::ostringstream out;
  out << "# bladebench validation index\n\n";
  out << fmt::format(
      "{} of {} cases passed; {} near miss{} (a passing case whose worst check entry uses more than "
      "{} of its tolerance). Run time of the cases together: {}.\n\n",
      passed, entries.size(), near, near == 1 ? "" : "es", kNearMiss, format_seconds(total));
  out << "Failing cases first, then by the share of its tolerance the worst check entry uses (*used*: above 1 is a "
         "miss).\n\n";
  out << "| case | status | checks | failed | used | run time | fidelity | key plot | note |\n"
         "|---|---|---|---|---|---|---|---|---|\n";
  for (const IndexEntry& e : entries) {
    const std::string thumbnail =
        e.key_plot.empty()
            ? std::string("-")
            : fmt::format("[![{}]({})]({})", e.case_name, e.key_plot.generic_string(), e.report.generic_string());
    out << fmt::format(
        "| [{}]({}) | {} | {} | {} | {} | {} | {} | {} | {} |\n", e.case_name, e.report.generic_string(),
        status_name(e.status), e.checks, e.failed, share_cell(e.worst_used), format_seconds(e.wall_seconds),
        table_cell(e.fidelity.empty() ? std::string("case settings") : e.fidelity), thumbnail, table_cell(e.message));
  }
  write_file_atomically(file, printable(out.str(), true));
}

}  // namespace bb
