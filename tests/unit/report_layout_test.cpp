// What a reader meets in a report: numbers as engineers write them, the verdict and key plots before
// the checks, long tables folded, misses named with their size, and the index sorted worst first.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "checks/checks.hpp"
#include "report/html_page.hpp"
#include "report/number_format.hpp"
#include "report/writers.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
const std::string kNbsp = "\u00a0";

using test::read_text;

TEST(NumberFormat, ColumnSuffixesGiveTheirSiUnits) {
  EXPECT_EQ(unit_of_column("frequency_hz"), "Hz");
  EXPECT_EQ(unit_of_column("ip_hz"), "Hz");
  EXPECT_EQ(unit_of_column("oop_amp_per_n"), "m/N");
  EXPECT_EQ(unit_of_column("stick_slope_n_per_m"), "N/m");
  EXPECT_EQ(unit_of_column("max_tangential_force_n"), "N");
  EXPECT_EQ(unit_of_column("A.x_max_m"), "m");
  EXPECT_EQ(unit_of_column("dissipated_energy_j"), "J");
  EXPECT_EQ(unit_of_column("divergence_speed_rad_s"), "rad/s");
  EXPECT_EQ(unit_of_column("ux"), "m");
  EXPECT_EQ(unit_of_column("syy"), "Pa");
  EXPECT_EQ(unit_of_column("relative_error"), "");
  EXPECT_EQ(unit_of_column("damping_ratio"), "");
  EXPECT_EQ(unit_of_column("stick"), "");
}

TEST(NumberFormat, FiveSignificantDigitsWithAShortExponent) {
  EXPECT_EQ(format_number(174.7329344), "174.73");
  EXPECT_EQ(format_number(0.01802137), "0.018021");
  EXPECT_EQ(format_number(5.63e-5), "5.63e-5");
  EXPECT_EQ(format_number(1e6), "1e6");
  EXPECT_EQ(format_number(-2.5e-12), "-2.5e-12");
  EXPECT_EQ(format_number(0.0), "0");
  EXPECT_EQ(format_number(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_number(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(format_quantity(174.7329344, "Hz"), "174.73" + kNbsp + "Hz");
  EXPECT_EQ(format_quantity(0.5, ""), "0.5");
}

TEST(NumberFormat, PercentagesCarryTheirSign) {
  EXPECT_EQ(format_percent(-0.0055), "-0.55" + kNbsp + "%");
  EXPECT_EQ(format_percent(0.123), "+12.30" + kNbsp + "%");
  EXPECT_EQ(format_percent(2e-8), "+2.0e-6" + kNbsp + "%");
  EXPECT_EQ(format_percent(0.0), "0" + kNbsp + "%");
}

TEST(NumberFormat, DurationsInSecondsThenHours) {
  EXPECT_EQ(format_seconds(0.0134), "0.013" + kNbsp + "s");
  EXPECT_EQ(format_seconds(1.23), "1.2" + kNbsp + "s");
  EXPECT_EQ(format_seconds(372.553), "372.6" + kNbsp + "s");
  EXPECT_EQ(format_seconds(3720.0), "1" + kNbsp + "h 02" + kNbsp + "min");
}

TEST(ToleranceBar, FillsInProportionAndSaturatesBeyondTheTolerance) {
  EXPECT_EQ(tolerance_bar(0.0, 4), "░░░░");
  EXPECT_EQ(tolerance_bar(0.5, 4), "██░░");
  EXPECT_EQ(tolerance_bar(0.5625, 4), "██▎░");  // 2.25 cells: a quarter cell is two eighths
  EXPECT_EQ(tolerance_bar(1.0, 4), "████");
  EXPECT_EQ(tolerance_bar(7.0, 4), "████");
  EXPECT_EQ(tolerance_bar(std::numeric_limits<double>::infinity(), 4), "████");
}

CheckEntry entry(const std::string& group, double computed, double reference, double tolerance,
                 CheckSpec::Relation relation = CheckSpec::Relation::equal) {
  CheckEntry e;
  e.group = group;
  e.name = group + ": frequency_hz mode 1";
  e.column = "frequency_hz";
  e.computed = computed;
  e.reference = reference;
  e.abs_error = std::abs(computed - reference);
  e.rel_error = e.abs_error / std::abs(reference);
  e.tolerance = tolerance;
  e.relation = relation;
  e.pass = relation == CheckSpec::Relation::equal     ? e.abs_error <= tolerance
           : relation == CheckSpec::Relation::at_most ? computed <= reference + tolerance
                                                      : computed >= reference - tolerance;
  return e;
}

TEST(ToleranceUsed, IsTheErrorOverTheToleranceAndAboveOneExactlyForAMiss) {
  EXPECT_DOUBLE_EQ(tolerance_used(entry("c", 101.0, 100.0, 2.0)), 0.5);
  EXPECT_DOUBLE_EQ(tolerance_used(entry("c", 97.0, 100.0, 2.0)), 1.5);
  EXPECT_DOUBLE_EQ(tolerance_used(entry("c", 90.0, 100.0, 2.0, CheckSpec::Relation::at_most)), -5.0);
  EXPECT_DOUBLE_EQ(tolerance_used(entry("c", 103.0, 100.0, 2.0, CheckSpec::Relation::at_most)), 1.5);
  EXPECT_DOUBLE_EQ(tolerance_used(entry("c", 99.0, 100.0, 2.0, CheckSpec::Relation::at_least)), 0.5);
  CheckEntry no_value = entry("c", 100.0, 100.0, 2.0);
  no_value.computed = std::numeric_limits<double>::quiet_NaN();
  no_value.abs_error = no_value.computed;
  no_value.pass = false;
  EXPECT_TRUE(std::isinf(tolerance_used(no_value)));
}

class ReportLayout : public test::TempFolderTest {};

RunRecord failing_run() {
  RunRecord run;
  run.title = "A frequency check";
  run.case_name = "c";
  run.status = RunStatus::fail;
  run.wall_seconds = 1.23;
  run.description = "**Model.** A description long enough to push things down.";
  run.facts = {{"mesh", "8 x 2 Q4"}};
  CheckSpec spec;
  spec.name = "Modes vs Euler-Bernoulli";
  spec.result = "frequencies";
  spec.rel_tol = 0.001;
  run.check_specs.push_back(spec);
  run.checks.push_back(entry(spec.name, 100.05, 100.0, 0.1));
  run.checks.push_back(entry(spec.name, 99.0, 100.0, 0.1));  // -1 %: a miss, 10x the tolerance
  run.plots = {{"Mode 1", "plots/mode1.svg", "", "mode1"}, {"Check", "plots/check1.svg", "", "check1"}};
  run.key_plots = {"check1"};
  return run;
}

TEST_F(ReportLayout, VerdictAndKeyPlotComeBeforeTheChecksAndTheChecksBeforeTheDescription) {
  write_report_md(failing_run(), dir_ / "report.md");
  const std::string md = read_text(dir_ / "report.md");
  const size_t verdict = md.find("**FAIL**: 1 of 2 check entries miss their tolerance");
  const size_t miss = md.find("error -1.00" + kNbsp + "% where 0.10" + kNbsp + "% is allowed: 10.00 x the tolerance");
  const size_t key_plot = md.find("![Check](plots/check1.svg)");
  const size_t checks = md.find("## Checks");
  const size_t description = md.find("## Description and assumptions");
  const size_t inputs = md.find("## Inputs and solver");
  const size_t other_plot = md.find("![Mode 1](plots/mode1.svg)");
  ASSERT_NE(verdict, std::string::npos) << md;
  ASSERT_NE(miss, std::string::npos) << md;
  ASSERT_NE(other_plot, std::string::npos) << md;
  EXPECT_LT(verdict, miss);
  EXPECT_LT(miss, key_plot);
  EXPECT_LT(key_plot, checks);
  EXPECT_LT(checks, description);
  EXPECT_LT(description, inputs);
  EXPECT_LT(inputs, other_plot);
  EXPECT_EQ(md.find("![Check](plots/check1.svg)", key_plot + 1), std::string::npos) << "each plot once";
  // The checks table: one row for the check, its worst entry with unit and share of the tolerance.
  EXPECT_NE(md.find("| 99" + kNbsp + "Hz | 100" + kNbsp + "Hz | -1.00" + kNbsp + "% | 0.10" + kNbsp + "% | `"),
            std::string::npos)
      << md;
}

TEST_F(ReportLayout, LongTablesAreFoldedAndTheHtmlPageKeepsTheFold) {
  RunRecord run = failing_run();
  std::vector<std::vector<double>> rows;
  for (int i = 1; i <= 40; ++i) rows.push_back({double(i), 100.0 + i});
  ResultTable states = table_from_rows("contact_states", {"key", "frequency_hz"}, rows);
  states.add_text_column("contact", std::vector<std::string>(40, "L1"));
  run.listed_tables.push_back(states);
  write_report_md(run, dir_ / "report.md");
  const std::string md = read_text(dir_ / "report.md");
  EXPECT_NE(md.find("40 rows; full precision in [`contact_states.csv`](contact_states.csv)."), std::string::npos);
  EXPECT_NE(md.find("<details><summary>contact_states: 40 rows</summary>"), std::string::npos) << md;
  EXPECT_NE(md.find("| key | frequency_hz [Hz] | contact |"), std::string::npos) << md;
  const std::string html = markdown_to_html(md);
  EXPECT_NE(html.find("<details><summary>contact_states: 40 rows</summary>"), std::string::npos);
  EXPECT_NE(html.find("<td>140</td>"), std::string::npos) << "the folded table is rendered";
}

TEST(MarkdownToHtml, PassesFoldsThroughWithTheirSummaryEscapedAndNothingElse) {
  const std::string html = markdown_to_html(
      "<details><summary>a <b>bold</b> claim</summary>\n\n| x |\n|---|\n| 1 |\n\n</details>\n"
      "<details><script>alert(1)</script>\n</details>\n");
  EXPECT_NE(html.find("<details><summary>a &lt;b&gt;bold&lt;/b&gt; claim</summary>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>1</td>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<script>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<b>"), std::string::npos) << html;
  // The unmatched second </details> is not markup: folds stay balanced.
  size_t opened = 0, closed = 0;
  for (size_t at = 0; (at = html.find("<details>", at)) != std::string::npos; ++at) ++opened;
  for (size_t at = 0; (at = html.find("</details>", at)) != std::string::npos; ++at) ++closed;
  EXPECT_EQ(opened, 1u);
  EXPECT_EQ(closed, 1u);
}

TEST_F(ReportLayout, TheIndexListsFailuresFirstThenNearMisses) {
  auto row = [](const std::string& name, RunStatus status, int failed, double used) {
    IndexEntry e;
    e.case_name = name;
    e.report = name + "/report.md";
    e.status = status;
    e.checks = status == RunStatus::no_checks ? 0 : 3;
    e.failed = failed;
    e.worst_used = used;
    return e;
  };
  std::vector<IndexEntry> entries = {row("relaxed", RunStatus::pass, 0, 0.1), row("broken", RunStatus::fail, 1, 2.0),
                                     row("close", RunStatus::pass, 0, 0.95),
                                     row("unchecked", RunStatus::no_checks, 0, NAN)};
  entries[2].key_plot = "close/plots/frf.svg";
  write_index_md(entries, dir_ / "index.md");
  const std::string md = read_text(dir_ / "index.md");
  const size_t broken = md.find("| [broken]"), close = md.find("| [close]"), relaxed = md.find("| [relaxed]"),
               unchecked = md.find("| [unchecked]");
  ASSERT_NE(unchecked, std::string::npos) << md;
  EXPECT_LT(broken, close);
  EXPECT_LT(close, relaxed);
  EXPECT_LT(relaxed, unchecked);
  EXPECT_NE(md.find("3 of 4 cases passed; 1 near miss"), std::string::npos) << md;
  EXPECT_NE(md.find("[![close](close/plots/frf.svg)](close/report.md)"), std::string::npos) << md;
  EXPECT_NE(md.find("`█████████▌`" + kNbsp + "0.95"), std::string::npos) << md;
}

}  // namespace
}  // namespace bb
