// What a report says and where it goes (report/writers, report/output_folder): summary.json is
// written whatever bytes the inputs echo, and a report folder appears complete or not at all,
// never outside the folder it was given.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "pipeline/run_case.hpp"
#include "report/output_folder.hpp"
#include "report/writers.hpp"
#include "results/table.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every entry of `folder`, recursively, as relative paths: what a run left behind.
std::vector<std::string> entries(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(folder)) out.push_back(fs::relative(e.path(), folder));
  std::sort(out.begin(), out.end());
  return out;
}

class ReportText : public test::TempFolderTest {};

TEST_F(ReportText, SummaryJsonIsWrittenWhateverBytesTheInputsEcho) {
  RunRecord run;
  run.case_name = "c";
  run.case_file = dir_ / "rig\xB5.toml";
  run.status = RunStatus::bad_input;
  run.message = "data/nodes.csv:3: column 'x': '\xFF\xFE' is not a number";
  run.warnings = {"a label from a Latin-1 file: \xB5m"};
  run.facts = {{"group \xE9", "\x1b[31mred"}};
  CheckEntry e;
  e.name = "check: 'label \xC3' #1";
  run.checks.push_back(e);
  ASSERT_NO_THROW(write_summary_json(run, dir_ / "summary.json"));
  ASSERT_NO_THROW(write_report_md(run, dir_ / "report.md"));
  const nlohmann::json j = nlohmann::json::parse(read_text(dir_ / "summary.json"));  // valid UTF-8 JSON
  EXPECT_EQ(j["message"], "data/nodes.csv:3: column 'x': '\\xFF\\xFE' is not a number");
  EXPECT_EQ(j["warnings"][0], "a label from a Latin-1 file: \\xB5m");
  EXPECT_EQ(j["facts"]["group \\xE9"], "\\x1B[31mred");
  EXPECT_EQ(j["checks"][0]["name"], "check: 'label \\xC3' #1");
  EXPECT_EQ(j["case_file"], (dir_ / "rig\\xB5.toml").string());
  const std::string md = read_text(dir_ / "report.md");
  EXPECT_NE(md.find("'\\xFF\\xFE' is not a number"), std::string::npos);
  EXPECT_EQ(md.find('\x1b'), std::string::npos);
}

// A refused case writes the refusal only: the tables computed before a check found its unknown
// column are not left beside it to be read as results.
TEST_F(ReportText, ABadInputRunWritesItsReportAndNothingElse) {
  const fs::path case_file = fs::path(BB_SOURCE_DIR) / "tests" / "bad_input" / "unknown_result_column.toml";
  const RunOutcome o = run_case(case_file, {.out_dir = dir_ / "out", .study = false, .plots = false});
  ASSERT_EQ(o.record.status, RunStatus::bad_input);
  EXPECT_EQ(entries(dir_), (std::vector<std::string>{"out", "out/report.md", "out/summary.json"}));
  const nlohmann::json j = nlohmann::json::parse(read_text(dir_ / "out" / "summary.json"));
  EXPECT_TRUE(j["tables"].empty());
  EXPECT_TRUE(j["checks"].empty());
}

class StagedReport : public test::TempFolderTest {};

TEST_F(StagedReport, CommitReplacesTheEarlierReportWhole) {
  const fs::path dest = dir_ / "case";
  fs::create_directories(dest);
  std::ofstream(dest / "summary.json") << "{}";
  std::ofstream(dest / "stale.csv") << "from an earlier run";
  {
    StagedFolder stage(dest);
    EXPECT_EQ(stage.path().parent_path(), dir_) << "the temporary folder is a sibling: the rename is atomic";
    EXPECT_TRUE(stage.path().filename().string().starts_with(".case.tmp-")) << stage.path();
    std::ofstream(stage.path() / "summary.json") << "{\"status\": \"pass\"}";
    EXPECT_EQ(read_text(dest / "summary.json"), "{}") << "nothing reaches the destination before commit()";
    stage.commit();
  }
  EXPECT_EQ(entries(dir_), (std::vector<std::string>{"case", "case/summary.json"}));
  EXPECT_EQ(read_text(dest / "summary.json"), "{\"status\": \"pass\"}");
}

TEST_F(StagedReport, AFolderNeverCommittedIsRemovedAndTheEarlierReportStays) {
  const fs::path dest = dir_ / "case";
  fs::create_directories(dest);
  std::ofstream(dest / "summary.json") << "{}";
  {
    StagedFolder stage(dest);
    std::ofstream(stage.path() / "half.csv") << "1,2";
  }  // an exception on the way would end here too
  EXPECT_EQ(entries(dir_), (std::vector<std::string>{"case", "case/summary.json"}));
}

TEST_F(StagedReport, ANewDestinationAndItsParentsAreCreatedOnCommit) {
  const fs::path dest = dir_ / "a" / "b" / "case";
  StagedFolder stage(dest);
  EXPECT_FALSE(fs::exists(dest));
  stage.commit();
  EXPECT_TRUE(fs::is_directory(dest));
  EXPECT_EQ(entries(dir_ / "a" / "b"), std::vector<std::string>{"case"});
}

std::string output_error(const fs::path& dest) {
  try {
    StagedFolder stage(dest);
  } catch (const OutputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(StagedReport, AFileIsNoDestinationAndTheMessageNamesIt) {
  std::ofstream(dir_ / "file") << "precious";
  EXPECT_NE(output_error(dir_ / "file").find((dir_ / "file").string() + ": exists and is not a folder"),
            std::string::npos);
  EXPECT_NE(output_error(dir_ / "file" / "case").find((dir_ / "file").string() + " exists and is not a folder"),
            std::string::npos);
  EXPECT_EQ(read_text(dir_ / "file"), "precious");
}

TEST_F(StagedReport, AFolderThatIsNotAReportIsNeverReplaced) {
  fs::create_directories(dir_ / "home");
  std::ofstream(dir_ / "home" / "thesis.tex") << "precious";
  EXPECT_NE(output_error(dir_ / "home").find("holds no bladebench report"), std::string::npos);
  EXPECT_EQ(read_text(dir_ / "home" / "thesis.tex"), "precious");
  fs::create_directories(dir_ / "empty");
  EXPECT_EQ(output_error(dir_ / "empty"), "") << "an empty folder may receive a report";
}

TEST_F(StagedReport, DotAndDotDotNameNoFolderOfTheirOwn) {
  EXPECT_NE(output_error(dir_ / ".").find("names no folder of its own"), std::string::npos);
  EXPECT_NE(output_error(dir_ / "x" / "..").find("names no folder of its own"), std::string::npos);
  EXPECT_EQ(output_error(dir_ / "case" / ""), "") << "a trailing separator names the folder";
}

TEST_F(StagedReport, AParentUnderAFileIsRefusedWithItsPath) {
  std::ofstream(dir_ / "file") << "x";
  try {
    prepare_output_parent(dir_ / "file", "--out");
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("--out " + (dir_ / "file").string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(prepare_output_parent(dir_ / "file" / "sub", "--out"), OutputError);
  EXPECT_NO_THROW(prepare_output_parent(dir_ / "new" / "reports", "--out"));
  EXPECT_TRUE(fs::is_directory(dir_ / "new" / "reports"));
}

TEST_F(StagedReport, AFileWrittenAtomicallyLeavesNoTemporary) {
  std::ofstream(dir_ / "index.md") << "old";
  write_file_atomically(dir_ / "index.md", "new");
  EXPECT_EQ(read_text(dir_ / "index.md"), "new");
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"index.md"});
}

}  // namespace
}  // namespace bb
