// The architecture of solvers/ as a test: folders are layers, and an #include from one folder into
// another is a dependency. The dependency graph between folders must have no cycle, and the case-file
// layer is a leaf that only the pipeline and the command line use (solvers/README.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace bb {
namespace {

namespace fs = std::filesystem;

using Graph = std::map<std::string, std::map<std::string, std::string>>;  // folder -> folder -> an example file

// Folder-to-folder includes of every source under solvers/ (quoted includes name "folder/file").
Graph folder_graph() {
  const fs::path root = fs::path(BB_SOURCE_DIR) / "solvers";
  const std::regex include(R"re(^\s*#\s*include\s*"([A-Za-z0-9_]+)/[^"]+")re");
  Graph g;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".hpp" && ext != ".cpp")) continue;
    const std::string from = fs::relative(entry.path(), root).begin()->string();
    std::ifstream in(entry.path());
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, include) && m[1] != from)
        g[from].emplace(m[1], fs::relative(entry.path(), root).string());
  }
  return g;
}

// A cycle through `node`, as "a -> b -> a", or empty.
std::string find_cycle(const Graph& g, const std::string& node, std::vector<std::string>& path,
                       std::set<std::string>& done) {
  if (std::find(path.begin(), path.end(), node) != path.end()) {
    std::string cycle;
    for (auto it = std::find(path.begin(), path.end(), node); it != path.end(); ++it) cycle += *it + " -> ";
    return cycle + node;
  }
  if (done.count(node)) return {};
  path.push_back(node);
  if (const auto it = g.find(node); it != g.end())
    for (const auto& [next, file] : it->second)
      if (std::string c = find_cycle(g, next, path, done); !c.empty())
        return c + " (" + node + " -> " + next + " in " + file + ")";
  path.pop_back();
  done.insert(node);
  return {};
}

TEST(Architecture, FolderIncludesFormNoCycle) {
  const Graph g = folder_graph();
  ASSERT_GT(g.size(), 10u);
  std::set<std::string> done;
  for (const auto& [folder, edges] : g) {
    std::vector<std::string> path;
    const std::string cycle = find_cycle(g, folder, path, done);
    EXPECT_TRUE(cycle.empty()) << "include cycle between folders: " << cycle;
  }
}

TEST(Architecture, OnlyThePipelineAndTheCommandLineUseTheCaseFileLayer) {
  for (const auto& [folder, edges] : folder_graph())
    if (folder != "pipeline" && folder != "cli" && edges.count("cases"))
      ADD_FAILURE() << folder << "/ includes cases/ (" << edges.at("cases")
                    << "): move the spec it needs next to its consumer";
}

}  // namespace
}  // namespace bb
