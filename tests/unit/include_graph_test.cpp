// The architecture of solvers/ as a test: folders are layers, and an #include from one folder into
// another is a dependency. The dependency graph between folders must have no cycle, a folder includes
// only folders that solvers/README.md lists above it, the case-file layer is a leaf that only the
// pipeline and the command line use, and the physics library never includes the harness.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
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

// The folders in the order solvers/README.md draws its layers: the first word of every line of its
// first code block that starts in the first column.
std::vector<std::string> readme_layers() {
  std::ifstream in(fs::path(BB_SOURCE_DIR) / "solvers" / "README.md");
  std::vector<std::string> layers;
  std::string line;
  int fences = 0;
  while (std::getline(in, line) && fences < 2) {
    if (line.rfind("```", 0) == 0) {
      ++fences;
    } else if (fences == 1 && !line.empty() && line[0] != ' ') {
      layers.push_back(line.substr(0, line.find(' ')));
    }
  }
  return layers;
}

// The harness's folders, as solvers/CMakeLists.txt splits the libraries (BB_HARNESS_FOLDERS), and cli.
std::set<std::string> harness_folders() {
  std::ifstream in(fs::path(BB_SOURCE_DIR) / "solvers" / "CMakeLists.txt");
  const std::regex list(R"re(^set\(BB_HARNESS_FOLDERS ([a-z_ ]+)\))re");
  std::set<std::string> out{"cli"};
  std::string line;
  std::smatch m;
  while (std::getline(in, line))
    if (std::regex_search(line, m, list)) {
      std::istringstream words(m[1].str());
      for (std::string w; words >> w;) out.insert(w);
    }
  return out;
}

TEST(Architecture, EveryFolderIncludesOnlyFoldersAboveItInTheReadme) {
  const std::vector<std::string> layers = readme_layers();
  ASSERT_GT(layers.size(), 20u);
  const auto rank = [&](const std::string& folder) {
    return std::find(layers.begin(), layers.end(), folder) - layers.begin();
  };
  const auto missing = static_cast<std::ptrdiff_t>(layers.size());
  for (const auto& [folder, edges] : folder_graph()) {
    if (rank(folder) == missing) {
      ADD_FAILURE() << folder << "/ is missing from solvers/README.md's layer list";
      continue;
    }
    for (const auto& [to, file] : edges)
      if (rank(to) > rank(folder))
        ADD_FAILURE() << folder << "/ includes " << to << "/ (" << file << "), which solvers/README.md lists below it";
  }
}

TEST(Architecture, ThePhysicsLibraryNeverIncludesTheHarness) {
  const std::set<std::string> harness = harness_folders();
  ASSERT_GT(harness.size(), 5u);
  for (const auto& [folder, edges] : folder_graph()) {
    if (harness.count(folder)) continue;
    for (const auto& [to, file] : edges)
      if (harness.count(to))
        ADD_FAILURE() << "physics folder " << folder << "/ includes the harness's " << to << "/ (" << file << ")";
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
