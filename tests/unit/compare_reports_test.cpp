// `bladebench compare`: what counts as a change between two validation runs.
#include "report/compare_reports.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "common/errors.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

CaseSummary run(const std::string& name, const std::string& status, std::vector<EntrySummary> entries) {
  return {name, status, 2.0, std::move(entries)};
}

EntrySummary entry(const std::string& name, double computed, bool pass = true) {
  return {name, "frequency_hz", computed, 100.0, 1.0, std::abs(computed - 100.0), pass};
}

TEST(CompareReports, IdenticalRunsAreUnchanged) {
  const std::vector<CaseSummary> runs = {run("a", "pass", {entry("f1", 100.2)}), run("b", "fail", {})};
  const ReportComparison r = compare_reports(runs, runs, {}, "old", "new");
  EXPECT_FALSE(r.changed());
  EXPECT_EQ(r.cases_compared, 2);
  EXPECT_NE(r.markdown.find("**UNCHANGED**"), std::string::npos) << r.markdown;
}

TEST(CompareReports, AValueMovesBeyondTheStatedShareOfItsSizeOrTolerance) {
  const std::vector<CaseSummary> before = {run("a", "pass", {entry("f1", 100.2), entry("f2", 100.3)})};
  // f1 moves by 1e-3 Hz (1e-5 of its size), f2 by 1e-5 Hz (1e-7: below 1e-6 of size and tolerance).
  const std::vector<CaseSummary> after = {run("a", "pass", {entry("f1", 100.201), entry("f2", 100.30001)})};
  const ReportComparison r = compare_reports(before, after, {.max_change = 1e-6}, "old", "new");
  EXPECT_TRUE(r.changed());
  EXPECT_EQ(r.entries_moved, 1);
  EXPECT_NE(r.markdown.find("| a | f1 |"), std::string::npos) << r.markdown;
  EXPECT_EQ(r.markdown.find("| a | f2 |"), std::string::npos) << r.markdown;
  EXPECT_FALSE(compare_reports(before, after, {.max_change = 1e-4}, "old", "new").changed());
}

TEST(CompareReports, ANoiseLevelValueMovesOnlyAgainstItsTolerance) {
  // An energy balance of 1e-15 against a tolerance of 1e-6: a change to 3e-15 is not a result that moved.
  EntrySummary e{"balance", "error", 1e-15, 0.0, 1e-6, 1e-9, true};
  EntrySummary f = e;
  f.computed = 3e-15;
  const ReportComparison r = compare_reports({run("a", "pass", {e})}, {run("a", "pass", {f})}, {}, "old", "new");
  EXPECT_FALSE(r.changed());
}

TEST(CompareReports, FlipsAndRemovalsAreChangesAndAnAddedCaseIsNot) {
  const std::vector<CaseSummary> before = {run("a", "pass", {entry("f1", 100.2), entry("f2", 100.2)}),
                                           run("gone", "pass", {})};
  const std::vector<CaseSummary> after = {run("a", "fail", {entry("f1", 100.2, false)}), run("new", "pass", {})};
  const ReportComparison r = compare_reports(before, after, {}, "old", "new");
  EXPECT_TRUE(r.changed());
  EXPECT_EQ(r.statuses_flipped, 1);
  EXPECT_EQ(r.entries_flipped, 1);
  EXPECT_EQ(r.entries_removed, 1);
  EXPECT_EQ(r.cases_removed, 1);
  EXPECT_EQ(r.cases_added, 1);
  EXPECT_NE(r.markdown.find("**pass -> fail**"), std::string::npos) << r.markdown;
  EXPECT_NE(r.markdown.find("pass -> **removed**"), std::string::npos) << r.markdown;
  EXPECT_FALSE(
      compare_reports({run("a", "pass", {})}, {run("a", "pass", {}), run("new", "pass", {})}, {}, "o", "n").changed());
}

class ReportTree : public test::TempFolderTest {};

TEST_F(ReportTree, IsReadFromTheSummariesOfItsCaseFolders) {
  std::filesystem::create_directories(dir_ / "b");
  std::filesystem::create_directories(dir_ / "a");
  const nlohmann::json summary = {
      {"case", "x"},
      {"status", "pass"},
      {"wall_time_s", 1.5},
      {"checks",
       {{{"name", "c: f 1"}, {"computed", 1.0}, {"reference", 1.0}, {"tolerance", 0.1}, {"pass", true}},
        {{"name", "c: f 1"}, {"computed", nullptr}, {"reference", 2.0}, {"tolerance", 0.1}, {"pass", false}}}}};
  std::ofstream(dir_ / "b" / "summary.json") << summary.dump();
  std::ofstream(dir_ / "a" / "summary.json") << summary.dump();
  const std::vector<CaseSummary> runs = read_report_tree(dir_);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].name, "a");
  ASSERT_EQ(runs[0].entries.size(), 2u);
  EXPECT_EQ(runs[0].entries[1].name, "c: f 1 (#2)") << "repeated names made unique";
  EXPECT_TRUE(std::isnan(runs[0].entries[1].computed));
  EXPECT_EQ(read_report_tree(dir_ / "a").size(), 1u) << "one case's folder is a tree of one";
}

TEST_F(ReportTree, AFolderWithoutSummariesOrABrokenSummaryIsBadInputNamingThePath) {
  std::filesystem::create_directories(dir_ / "cases");
  std::ofstream(dir_ / "cases" / "a.toml") << "[case]\n";
  try {
    read_report_tree(dir_ / "cases");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cases: not a report tree"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_report_tree(dir_ / "missing"), InputError);
  std::filesystem::create_directories(dir_ / "tree" / "x");
  std::ofstream(dir_ / "tree" / "x" / "summary.json") << R"({"case": "x", "status": "pass"})";
  try {
    read_report_tree(dir_ / "tree");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x/summary.json: not a bladebench summary"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb
