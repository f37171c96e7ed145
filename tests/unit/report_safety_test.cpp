// What a report says and where it goes (report/writers, report/output_folder): summary.json is
// written whatever bytes the inputs echo, columns with NaN / inf entries are listed, and a report
// folder appears complete or not at all, never outside the folder it was given.
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

using test::read_text;

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

ResultTable table_with_gaps() {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  return table_from_rows("oscillation", {"mode", "modal_hz", "measured_hz", "amplitude_m"},
                         {{1, 100.0, 99.5, 1e-3}, {2, 300.0, nan, 2e-6}, {3, 500.0, inf, nan}});
}

TEST_F(ReportText, ColumnsWithNanOrInfAreListedInTheSummaryAndTheReport) {
  RunRecord run;
  run.status = RunStatus::pass;
  write_result_csv(table_with_gaps(), dir_, run);
  ASSERT_EQ(run.tables, std::vector<std::string>{"oscillation.csv"});
  ASSERT_EQ(run.non_finite.size(), 2u);
  EXPECT_EQ(run.non_finite[0].column, "measured_hz");
  EXPECT_EQ(run.non_finite[0].keys, (std::vector<long>{2, 3}));
  EXPECT_EQ(run.non_finite[1].column, "amplitude_m");
  EXPECT_EQ(run.non_finite[1].keys, std::vector<long>{3});
  EXPECT_NE(read_text(dir_ / "oscillation.csv").find("2,300,nan,"), std::string::npos);

  write_summary_json(run, dir_ / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(read_text(dir_ / "summary.json"));
  ASSERT_EQ(j["non_finite"].size(), 2u);
  EXPECT_EQ(j["non_finite"][0]["file"], "oscillation.csv");
  EXPECT_EQ(j["non_finite"][0]["column"], "measured_hz");
  EXPECT_EQ(j["non_finite"][0]["key_column"], "mode");
  EXPECT_EQ(j["non_finite"][0]["keys"], nlohmann::json::array({2, 3}));

  write_report_md(run, dir_ / "report.md");
  const std::string md = read_text(dir_ / "report.md");
  EXPECT_NE(md.find("Entries without a value"), std::string::npos);
  EXPECT_NE(md.find("| oscillation.csv | measured_hz | mode = 2, 3 | none |"), std::string::npos);
}

// loop_summary.csv of the lift-off loop has no closed-form energy (that closed form is for a constant
// normal load): it holds nan there, and the passing run says so in summary.json.
TEST_F(ReportText, APassingRunListsTheNotApplicableEntriesItWrote) {
  const fs::path case_file = fs::path(BB_SOURCE_DIR) / "cases" / "verification" / "jenkins_loop_lift_off.toml";
  const RunOutcome o = run_case(case_file, {.out_dir = dir_ / "out", .study = false, .plots = false});
  ASSERT_EQ(o.record.status, RunStatus::pass) << o.record.message;
  ASSERT_TRUE(o.written);
  const nlohmann::json j = nlohmann::json::parse(read_text(dir_ / "out" / "summary.json"));
  bool listed = false;
  for (const nlohmann::json& n : j["non_finite"])
    listed = listed || (n["file"] == "loop_summary.csv" && n["column"] == "closed_form_energy_j");
  EXPECT_TRUE(listed) << j["non_finite"].dump();
  EXPECT_NE(read_text(dir_ / "out" / "loop_summary.csv").find(",nan,"), std::string::npos);
  EXPECT_EQ(entries(dir_).front(), "out") << "no temporary folder left beside the report";
}

// A case refused before its solve writes the refusal only.
TEST_F(ReportText, ABadInputRunWritesItsReportAndNothingElse) {
  const fs::path case_file = fs::path(BB_SOURCE_DIR) / "tests" / "bad_input" / "negative_tolerance.toml";
  const RunOutcome o = run_case(case_file, {.out_dir = dir_ / "out", .study = false, .plots = false});
  ASSERT_EQ(o.record.status, RunStatus::bad_input);
  EXPECT_EQ(entries(dir_), (std::vector<std::string>{"out", "out/report.html", "out/report.md", "out/summary.json"}));
  const nlohmann::json j = nlohmann::json::parse(read_text(dir_ / "out" / "summary.json"));
  EXPECT_TRUE(j["tables"].empty());
  EXPECT_TRUE(j["checks"].empty());
}

// A check that cannot be evaluated on the solved tables (an unknown column) makes the run bad input,
// but the solve is not thrown away: its tables are written beside the refusal, and no check passes.
TEST_F(ReportText, ACheckThatCannotBeEvaluatedAfterTheSolveKeepsTheTables) {
  const fs::path case_file = fs::path(BB_SOURCE_DIR) / "tests" / "bad_input" / "unknown_result_column.toml";
  const RunOutcome o = run_case(case_file, {.out_dir = dir_ / "out", .study = false, .plots = false});
  ASSERT_EQ(o.record.status, RunStatus::bad_input);
  EXPECT_NE(o.record.message.find("the result tables are written"), std::string::npos) << o.record.message;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "nodal_displacements.csv"));
  const nlohmann::json j = nlohmann::json::parse(read_text(dir_ / "out" / "summary.json"));
  EXPECT_EQ(j["status"], "bad_input");
  EXPECT_FALSE(j["tables"].empty());
  EXPECT_TRUE(j["checks"].empty());
}

TEST_F(ReportText, TheReportNamesTheCheckThatReadANonFiniteEntry) {
  RunRecord run;
  write_result_csv(table_with_gaps(), dir_, run);
  CheckSpec spec;
  spec.name = "second mode";
  spec.result = "oscillation";
  run.check_specs.push_back(spec);
  CheckEntry e;
  e.group = "second mode";
  e.column = "measured_hz";
  e.key = e.computed_key = 2;
  run.checks.push_back(e);
  write_report_md(run, dir_ / "report.md");
  EXPECT_NE(
      read_text(dir_ / "report.md").find("| oscillation.csv | measured_hz | mode = 2, 3 | second mode (failed) |"),
      std::string::npos);
}

TEST_F(ReportText, ATableNameThatIsAPathIsNeverWritten) {
  RunRecord run;
  ResultTable t = table_with_gaps();
  t.name = "../escape";
  EXPECT_THROW(write_result_csv(t, dir_ / "out", run), std::logic_error);
  EXPECT_FALSE(fs::exists(dir_ / "escape.csv"));
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
