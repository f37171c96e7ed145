#include "cli/validate_command.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>

#include "cache/model_cache_settings.hpp"
#include "cli/command_options.hpp"
#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "distributed/distributed.hpp"
#include "pipeline/child_runs.hpp"
#include "report/html_page.hpp"
#include "report/output_folder.hpp"
#include "report/writers.hpp"

namespace bb::cli {

namespace fs = std::filesystem;

namespace {

// Files under a "data" folder are inputs of cases (CSV meshes, reduced-model sidecars), not cases.
bool in_data_folder(const fs::path& file, const fs::path& root) {
  for (const auto& part : fs::relative(file.parent_path(), root))
    if (part == "data") return true;
  return false;
}

// `bladebench run` of one case as validate would run it in-process, for a child process.
std::vector<std::string> child_command(const ValidateArgs& a, const fs::path& file, const fs::path& out_dir) {
  std::vector<std::string> c = {
      fs::read_symlink("/proc/self/exe").string(), "run", file.string(), "--out", out_dir.string(), "--fidelity",
      bb::fidelity_mode_name(a.fidelity)};
  if (a.study) c.emplace_back("--study");
  if (a.no_plots) c.emplace_back("--no-plots");
  append_limit_args(a.limits, c);
  if (a.cache) {
    c.emplace_back("--cache-dir");
    c.push_back(a.cache->folder.string());
  } else {
    c.emplace_back("--no-cache");
  }
  return c;
}

// A child's run read back from the summary.json it wrote; nullopt when it wrote none for this run.
std::optional<bb::IndexEntry> entry_of_child(const fs::path& out_dir, const fs::path& index_dir,
                                             const bb::ChildResult& r) {
  if (r.exit_code < 0) return std::nullopt;
  std::optional<bb::IndexEntry> e = bb::read_index_entry(out_dir, index_dir);
  // An older summary (this run failed before writing its own) must not pass for this run.
  if (e && bb::exit_code(e->status) != r.exit_code) return std::nullopt;
  return e;
}

// "3 passed", "1 failed", "2 bad input": a status as the final line of validate says it.
std::string status_verb(bb::RunStatus status) {
  switch (status) {
    case bb::RunStatus::pass:
      return "passed";
    case bb::RunStatus::fail:
      return "failed";
    case bb::RunStatus::no_checks:
      return "without checks";
    case bb::RunStatus::bad_input:
      return "bad input";
    case bb::RunStatus::solver_failed:
      return "solver failed";
  }
  return "?";
}

}  // namespace

int validate_command(const ValidateArgs& a) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(a.dir)) {
    if (entry.path().extension() != ".toml" || in_data_folder(entry.path(), a.dir)) continue;
    // A case file that is a link loop (or a device) is named, not thrown as a filesystem error.
    if (const std::string why = bb::file_problem(entry.path()); why.empty())
      files.push_back(entry.path());
    else if (why != "it is a directory")
      throw bb::InputError(fmt::format("{}: cannot open ({})", bb::printable(entry.path().string()), why));
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "error: no *.toml case file under %s\n", a.dir.c_str());
    return bb::exit_bad_input;
  }
  // Two case files with one stem would write one report folder: refuse before running any, so that
  // neither report is overwritten by the other.
  std::map<std::string, fs::path> stems;
  for (const fs::path& f : files)
    if (auto [it, fresh] = stems.emplace(f.stem().string(), f); !fresh)
      throw bb::InputError(
          fmt::format("two case files share the name '{}': {} and {} (validate writes one report "
                      "folder per case file name)",
                      bb::printable(f.stem().string()), bb::printable(it->second.string()), bb::printable(f.string())));
  if (bb::distributed::is_root()) bb::prepare_output_parent(a.out, "--out");
  // Under mpirun the ranks share the cases out (each case's eigensolves on its own rank).
  const int ranks = bb::distributed::size(), rank = bb::distributed::rank();
  if (ranks > 1) {
    std::vector<int> ready{0};
    bb::distributed::max_over_ranks(ready);  // the output folder exists before any rank writes into it
    bb::distributed::set_shared_solves(false);
    if (bb::distributed::is_root() && static_cast<size_t>(ranks) > files.size())
      std::fprintf(stderr, "warning: %d ranks for %zu cases: %zu ranks have nothing to run\n", ranks, files.size(),
                   static_cast<size_t>(ranks) - files.size());
  }
  const std::vector<size_t> mine = bb::distributed::share_of_rank(files.size(), rank);
  std::vector<std::pair<size_t, bb::IndexEntry>> done;  // (file, entry) in the order runs finish
  int rc = bb::exit_pass;
  auto record = [&](size_t i, bb::IndexEntry e, int code) {
    done.emplace_back(i, e);
    rc = std::max(rc, code);
  };
  if (a.jobs > 1) {
    // Longest first, by the wall time of each case's previous report (none yet: first of all), so
    // that a long case does not start last and run alone.
    std::vector<double> previous(files.size(), std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < files.size(); ++i) {
      std::ifstream in(fs::path(a.out) / files[i].stem() / "summary.json");
      const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
      if (!j.is_discarded() && j.contains("wall_time_s") && j["wall_time_s"].is_number())
        previous[i] = j["wall_time_s"].get<double>();
    }
    std::vector<size_t> order = mine;
    std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return previous[x] > previous[y]; });
    std::vector<std::vector<std::string>> commands;
    for (size_t i : order) commands.push_back(child_command(a, files[i], fs::path(a.out) / files[i].stem()));
    size_t finished = 0;
    bb::run_children(commands, a.jobs, [&](size_t started, const bb::ChildResult& r) {
      const size_t i = order[started];
      const fs::path out_dir = fs::path(a.out) / files[i].stem();
      // The child's own verdict lines, whole, under this run's counter.
      std::fprintf(stderr, "[%zu/%zu] %s", ++finished, mine.size(), bb::printable(r.output, true).c_str());
      std::optional<bb::IndexEntry> e = entry_of_child(out_dir, a.out, r);
      if (!e) {
        e.emplace();
        e->case_name = files[i].stem().string();
        e->report = fs::relative(out_dir / "report.md", a.out);
        e->status = r.exit_code == bb::exit_bad_input ? bb::RunStatus::bad_input : bb::RunStatus::solver_failed;
        e->message = r.signal ? fmt::format("the run was killed by signal {} ({})", r.signal, strsignal(r.signal))
                              : fmt::format("the run exited with code {} and no report", r.exit_code);
        std::fprintf(stderr, "  error: %s: %s\n", files[i].string().c_str(), e->message.c_str());
      }
      record(i, *e, bb::exit_code(e->status));
    });
  } else {
    for (size_t n = 0; n < mine.size(); ++n) {
      const size_t i = mine[n];
      bb::RunOptions opt;
      opt.study = a.study;
      opt.plots = !a.no_plots;
      opt.fidelity = a.fidelity;
      opt.limits = a.limits;
      opt.cache = a.cache;
      // Output folder by file stem first; the case name is only known after parsing.
      opt.out_dir = fs::path(a.out) / files[i].stem();
      const bb::RunOutcome o = bb::run_case(files[i], opt);
      print_outcome(o, fmt::format("[{}/{}] ", n + 1, mine.size()));
      // The entry as its summary.json says, as for a child process; from memory when none was written.
      std::optional<bb::IndexEntry> e;
      if (o.written) e = bb::read_index_entry(o.out_dir, a.out);
      if (!e) {
        e.emplace();
        e->case_name = o.record.case_name;
        e->report = fs::relative(o.out_dir / "report.md", a.out);
        e->status = o.record.status;
        e->checks = static_cast<int>(o.record.checks.size());
        e->failed = failed_count(o.record);
        e->wall_seconds = o.record.wall_seconds;
        e->message = o.record.message;
        e->fidelity = o.record.fidelity;
      }
      record(i, *e, bb::exit_code(o.record.status));
    }
  }
  if (ranks > 1) {
    // Every rank's exit codes; the root reads the other ranks' cases from their summary.json.
    std::vector<int> codes(files.size(), -1);
    for (const auto& [i, e] : done) codes[i] = bb::exit_code(e.status);
    bb::distributed::max_over_ranks(codes);
    if (!bb::distributed::is_root()) return *std::max_element(codes.begin(), codes.end());
    for (size_t i = 0; i < files.size(); ++i) {
      if (bb::distributed::owner_of(i) == rank) continue;
      const fs::path out_dir = fs::path(a.out) / files[i].stem();
      std::optional<bb::IndexEntry> e = bb::read_index_entry(out_dir, a.out);
      if (e && bb::exit_code(e->status) != codes[i]) e.reset();
      if (!e) {
        e.emplace();
        e->case_name = files[i].stem().string();
        e->report = fs::relative(out_dir / "report.md", a.out);
        e->status = codes[i] == bb::exit_bad_input ? bb::RunStatus::bad_input : bb::RunStatus::solver_failed;
        e->message = fmt::format("the run on MPI rank {} exited with code {} and no report",
                                 bb::distributed::owner_of(i), codes[i]);
      }
      record(i, *e, codes[i]);
    }
  }
  std::sort(done.begin(), done.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<bb::IndexEntry> index;
  for (auto& [i, e] : done) index.push_back(std::move(e));
  bb::write_index_md(index, fs::path(a.out) / "index.md");
  bb::write_html_twin(fs::path(a.out) / "index.md");
  // The verdict a CI log is read for: every status that occurred, in the enum's order.
  std::map<bb::RunStatus, int> by_status;
  for (const bb::IndexEntry& e : index) ++by_status[e.status];
  std::string verdict;
  for (const auto& [status, count] : by_status)
    verdict += fmt::format("{}{} {}", verdict.empty() ? "" : ", ", count, status_verb(status));
  std::fprintf(stderr, "%zu cases: %s; index: %s\n", files.size(), verdict.c_str(),
               (fs::path(a.out) / "index.md").string().c_str());
  return rc;
}

}  // namespace bb::cli
