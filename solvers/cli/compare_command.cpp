#include "cli/compare_command.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "report/compare_reports.hpp"
#include "report/html_page.hpp"
#include "report/output_folder.hpp"

namespace bb::cli {

int compare_command(const CompareArgs& a) {
  const std::vector<bb::CaseSummary> old_runs = bb::read_report_tree(a.old_dir);
  const std::vector<bb::CaseSummary> new_runs = bb::read_report_tree(a.new_dir);
  const bb::ReportComparison r =
      bb::compare_reports(old_runs, new_runs, {.max_change = a.max_change}, a.old_dir, a.new_dir);
  if (a.out.empty()) {
    std::fputs(r.markdown.c_str(), stdout);
  } else {
    const std::filesystem::path page(a.out);
    // The page (or its HTML twin) inside a report tree could replace a summary it was made from.
    for (const std::string& tree : {a.old_dir, a.new_dir})
      if (bb::lies_within(page, tree))
        throw bb::OutputError(fmt::format("--out {}: lies inside the report tree {}, one of the inputs; write elsewhere",
                                          bb::printable(a.out), bb::printable(tree)));
    if (page.extension() == ".md") bb::require_replaceable_file(std::filesystem::path(page).replace_extension(".html"));
    bb::write_file_atomically(page, r.markdown);
    if (page.extension() == ".md") bb::write_html_twin(page);
  }
  std::fprintf(stderr,
               "compare: %s: %d cases (%d added, %d removed); flipped: %d statuses, %d check entries; moved: "
               "%d values beyond %g%s\n",
               r.changed() ? "changed" : "unchanged", r.cases_compared, r.cases_added, r.cases_removed,
               r.statuses_flipped, r.entries_flipped, r.entries_moved, a.max_change,
               a.out.empty() ? "" : fmt::format("; page: {}", bb::printable(a.out)).c_str());
  return r.changed() ? bb::exit_check_failed : bb::exit_pass;
}

}  // namespace bb::cli
