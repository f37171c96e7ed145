// `bladebench compare OLD NEW`: what changed between two validation runs, as a Markdown (and HTML)
// page and an exit code for CI: 0 unchanged, 1 changed, 2 a folder that is not a report tree.
#pragma once
#include <string>

namespace bb::cli {

struct CompareArgs {
  std::string old_dir, new_dir;
  std::string out;  // the page (Markdown; its HTML twin beside it when it ends in .md); empty: standard output
  double max_change = 1e-6;
};

int compare_command(const CompareArgs& a);

}  // namespace bb::cli
