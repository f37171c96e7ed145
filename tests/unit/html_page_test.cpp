// The HTML pages of the reports: tables rendered, plots carried inside, links to the HTML twins,
// user markup never passed through.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "report/html_page.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

using test::TempFolderTest;

TEST(Base64, MatchesTheTestVectorsOfRfc4648) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(MarkdownToHtml, RendersPipeTablesAsHtmlTables) {
  const std::string html = markdown_to_html("| a | b |\n|---|---|\n| 1 | 2 |\n");
  EXPECT_NE(html.find("<table>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>2</td>"), std::string::npos) << html;
}

TEST(MarkdownToHtml, DoesNotPassRawMarkupThrough) {
  const std::string html = markdown_to_html("A label <script>alert(1)</script> and <b>bold</b>\n");
  EXPECT_EQ(html.find("<script>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<b>"), std::string::npos) << html;
}

class HtmlPage : public TempFolderTest {};

TEST_F(HtmlPage, InlinesLocalPlotsAndKeepsMissingOnesVisible) {
  std::filesystem::create_directories(dir_ / "plots");
  const std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"/>";
  write(svg, "plots/frf.svg");
  const std::string page = html_page("# Case\n\n![FRF](plots/frf.svg)\n\n![gone](plots/gone.svg)\n", dir_);
  EXPECT_NE(page.find("<title>Case</title>"), std::string::npos);
  EXPECT_NE(page.find("src=\"data:image/svg+xml;base64," + base64(svg) + "\""), std::string::npos) << page;
  EXPECT_NE(page.find("src=\"plots/gone.svg\""), std::string::npos) << page;
}

// A huge plot was inlined whole (issue 70: std::bad_alloc, exit 3): above the stated size it stays a
// link, and the note names it.
TEST_F(HtmlPage, LinksAnSvgAboveTheInlineSizeAndNamesIt) {
  std::filesystem::create_directories(dir_ / "plots");
  const std::string small = "<svg xmlns=\"http://www.w3.org/2000/svg\"/>";
  write(small, "plots/small.svg");
  write("<svg xmlns=\"http://www.w3.org/2000/svg\">" + std::string(kMaxInlineSvgBytes, ' ') + "</svg>",
        "plots/huge.svg");
  std::vector<std::string> notes;
  const std::string page = html_page("![huge](plots/huge.svg)\n\n![small](plots/small.svg)\n", dir_, true, &notes);
  EXPECT_NE(page.find("src=\"plots/huge.svg\""), std::string::npos);
  EXPECT_NE(page.find("src=\"data:image/svg+xml;base64," + base64(small) + "\""), std::string::npos);
  EXPECT_LT(page.size(), 100000u);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("huge.svg"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("linked, not inlined"), std::string::npos) << notes[0];
}

TEST_F(HtmlPage, LinksToReportsPointAtTheirHtmlPages) {
  const std::string page =
      html_page("[a](table02/report.md) [csv](frf_5.csv) [web](https://example.org/report.md)\n", dir_);
  EXPECT_NE(page.find("href=\"table02/report.html\""), std::string::npos) << page;
  EXPECT_NE(page.find("href=\"frf_5.csv\""), std::string::npos) << page;
  EXPECT_NE(page.find("href=\"https://example.org/report.md\""), std::string::npos) << page;
}

TEST_F(HtmlPage, TwinIsWrittenBesideTheMarkdown) {
  const auto md = write("# Index\n\n| case | status |\n|---|---|\n| x | pass |\n", "index.md");
  write_html_twin(md);
  std::ifstream in(dir_ / "index.html");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(text.starts_with("<!DOCTYPE html>"));
  EXPECT_NE(text.find("<td>pass</td>"), std::string::npos);
}

TEST_F(HtmlPage, EveryReportUnderAFolderGetsItsPage) {
  write("# Index\n\n[a](a/report.md)\n", "index.md");
  std::filesystem::create_directories(dir_ / "a");
  write("# A\n", "a/report.md");
  write("# notes, not a report\n", "a/notes.md");
  const auto pages = write_html_twins(dir_);
  ASSERT_EQ(pages.size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "index.html"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "a" / "report.html"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "a" / "notes.html"));
}

}  // namespace
}  // namespace bb
