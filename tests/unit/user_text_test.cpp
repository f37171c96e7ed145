// User text (common/user_text): which names and labels a case may use, and how user bytes are
// echoed in messages and reports.
#include "common/user_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace bb {
namespace {

using namespace std::string_literals;

TEST(Names, LettersDigitsUnderscoreAndDashAreNames) {
  for (const char* name : {"tip", "T2", "clamp_left", "rom-corner", "_private", "0"})
    EXPECT_EQ(name_problem(name), "") << name;
}

TEST(Names, PathsNulBytesControlCharactersBracesAndEmptyAreNotNames) {
  EXPECT_NE(name_problem("../tip").find("a dot"), std::string::npos);
  EXPECT_NE(name_problem("a/b").find("a path separator"), std::string::npos);
  EXPECT_NE(name_problem("/etc").find("a path separator"), std::string::npos);
  EXPECT_NE(name_problem("a\\b").find("a path separator"), std::string::npos);
  EXPECT_NE(name_problem("ti\0p"s).find("a NUL byte"), std::string::npos);
  EXPECT_NE(name_problem("ti\0p"s).find("ti\\x00p"), std::string::npos) << "the NUL is shown, not echoed";
  EXPECT_NE(name_problem("tip\n").find("\\x0A"), std::string::npos);
  EXPECT_NE(name_problem("{}").find("the character '{'"), std::string::npos);
  EXPECT_NE(name_problem("a b").find("a space"), std::string::npos);
  EXPECT_NE(name_problem("x'; rm -rf ~").find("the character '''"), std::string::npos);
  EXPECT_NE(name_problem("-x").find("starts with '-'"), std::string::npos);
  EXPECT_NE(name_problem("").find("an empty name"), std::string::npos);
  EXPECT_NE(name_problem(std::string(65, 'a')).find("longer than 64"), std::string::npos);
  EXPECT_EQ(name_problem(std::string(64, 'a')), "");
}

TEST(Names, CaseNamesMayHoldInnerDotsButNoPath) {
  EXPECT_EQ(dotted_name_problem("table02_q4_cantilever"), "");
  EXPECT_EQ(dotted_name_problem("run.v2"), "");
  for (const char* bad : {".", "..", ".hidden", "../escape", "/tmp/x", "a/b", ""})
    EXPECT_NE(dotted_name_problem(bad), "") << bad;
  EXPECT_NE(dotted_name_problem("a\0b"s), "");
}

TEST(Labels, AnyUtf8TextWithoutControlCharactersIsALabel) {
  EXPECT_EQ(label_problem("Table VI, modes 3-10 (x-flexure 2-4): 5 % target {braces too}"), "");
  EXPECT_EQ(label_problem("\xC2\xB5m and \xE2\x80\x94 dashes"), "");  // µm, em dash
  EXPECT_NE(label_problem("ok\x1b[31m").find("U+001B"), std::string::npos);
  EXPECT_NE(label_problem("a\0b"s).find("U+0000"), std::string::npos);
  EXPECT_NE(label_problem("line\nbreak").find("U+000A"), std::string::npos);
  EXPECT_EQ(label_problem("line\nbreak\tand tab", true), "") << "a description may span lines";
  EXPECT_NE(label_problem("latin-1 \xB5m").find("not valid UTF-8 (byte 9)"), std::string::npos);
}

TEST(Printable, ValidUtf8AndTabsAreKeptAndLineBreaksInAWholeReport) {
  const std::string text = "\xC2\xB5m, line\n\ttab";
  EXPECT_EQ(printable(text, true), text);
  EXPECT_EQ(printable(text), "\xC2\xB5m, line\\x0A\ttab") << "a message stays on its line";
}

TEST(Printable, InvalidBytesAndControlCharactersAreWrittenAsHex) {
  EXPECT_EQ(printable("a\xFF"
                      "b"),
            "a\\xFFb");
  EXPECT_EQ(printable("\xB5m"), "\\xB5m");                  // Latin-1 micro sign
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");           // overlong '/'
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a UTF-16 surrogate
  EXPECT_EQ(printable("\xE2\x82"), "\\xE2\\x82");           // truncated sequence
  EXPECT_EQ(printable("nul\0here"s), "nul\\x00here");
  EXPECT_EQ(printable("\x1b[2J\r"), "\\x1B[2J\\x0D");
  EXPECT_TRUE(is_valid_utf8(printable("\xFF\xFE\x80 mixed \xC3\xA9")));
}

}  // namespace
}  // namespace bb
