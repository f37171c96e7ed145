// The lines of an Abaqus / CalculiX deck as its keywords and data lines, *INCLUDEs expanded in place,
// comments and blank lines dropped, each line knowing its file and number for messages.
#pragma once
#include <deque>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace bb::inp {

struct Line {
  std::string_view text;  // without the line end
  int file = 0;           // index into InpLines::files
  int number = 0;         // 1-based
  bool keyword() const { return !text.empty() && text.front() == '*'; }
};

// A keyword line: name upper-cased with single spaces ("SOLID SECTION"), parameters by upper-case key
// with their values as written ("" for a flag such as GENERATE).
struct Keyword {
  std::string name;
  std::vector<std::pair<std::string, std::string>> parameters;
  const std::string* find(std::string_view key) const;
};

class InpLines {
 public:
  // `folder`: an *INCLUDE must name a file inside it.
  InpLines(const std::filesystem::path& file, const std::filesystem::path& folder);

  const std::vector<Line>& lines() const { return lines_; }
  std::string where(const Line& line) const;  // "file:line"
  [[noreturn]] void fail(const Line& line, std::string_view message) const;

 private:
  void load(const std::filesystem::path& file, const std::filesystem::path& folder, std::vector<int>& stack,
            const Line* included_at);

  std::deque<std::string> texts_;
  std::vector<std::filesystem::path> files_;
  std::vector<Line> lines_;
};

Keyword parse_keyword(const InpLines& deck, const Line& line);
// The comma-separated fields of a data line, trimmed; a line ending in a comma gives a last empty field.
std::vector<std::string_view> fields(std::string_view text);
long integer_field(const InpLines& deck, const Line& line, std::string_view field, std::string_view what);
double number_field(const InpLines& deck, const Line& line, std::string_view field, std::string_view what);
std::string upper(std::string_view text);

}  // namespace bb::inp
