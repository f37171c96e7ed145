// Lexical rules of the Abaqus keyword format (Abaqus Analysis User's Guide, "Input syntax rules";
// CalculiX's ccx manual, "Input deck format"): a line starting with "**" is a comment, one starting
// with "*" a keyword with comma-separated parameters, names case-insensitive and blanks in them
// insignificant; other lines are data, fields separated by commas.
#include "mesh/inp_lines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"

namespace fs = std::filesystem;

namespace bb::inp {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// Blanks inside a keyword or parameter name do not count ("*SOLID SECTION" = "*SOLIDSECTION" in
// Abaqus); one space between words keeps the names readable in messages.
std::string keyword_name(std::string_view text) {
  std::string out;
  bool blank = false;
  for (const char c : trim(text)) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      blank = true;
      continue;
    }
    if (blank && !out.empty()) out += ' ';
    blank = false;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

constexpr int kMaxIncludeDepth = 16;

}  // namespace

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

const std::string* Keyword::find(std::string_view key) const {
  for (const auto& [k, v] : parameters)
    if (k == key) return &v;
  return nullptr;
}

InpLines::InpLines(const fs::path& file, const fs::path& folder) {
  std::vector<int> stack;
  load(file, folder, stack, nullptr);
}

std::string InpLines::where(const Line& line) const {
  return fmt::format("{}:{}", files_[static_cast<size_t>(line.file)].string(), line.number);
}

void InpLines::fail(const Line& line, std::string_view message) const {
  throw InputError(fmt::format("{}: {}", where(line), message));
}

void InpLines::load(const fs::path& file, const fs::path& folder, std::vector<int>& stack, const Line* included_at) {
  auto refuse = [&](const std::string& message) {
    if (included_at) fail(*included_at, message);
    throw InputError(fmt::format("{}: {}", file.string(), message));
  };
  if (const std::string problem = file_problem(file); !problem.empty())
    refuse(fmt::format("cannot read the deck {}: {}", file.string(), problem));
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  for (const int open : stack)
    if (fs::weakly_canonical(files_[static_cast<size_t>(open)], ec) == canonical)
      refuse(fmt::format("*INCLUDE of {} includes itself (through the files it includes)", file.string()));
  if (static_cast<int>(stack.size()) >= kMaxIncludeDepth)
    refuse(fmt::format("*INCLUDEs nest deeper than {} files", kMaxIncludeDepth));
  std::ifstream in(file, std::ios::binary);
  if (!in) refuse(fmt::format("cannot open the deck {}", file.string()));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string& text = texts_.emplace_back(buffer.str());
  if (text.find('\0') != std::string::npos) refuse(fmt::format("{} holds a NUL byte: not a text deck", file.string()));
  const int index = static_cast<int>(files_.size());
  files_.push_back(file);
  stack.push_back(index);
  int number = 0;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view row(text.data() + start, end - start);
    start = end + 1;
    ++number;
    if (!row.empty() && row.back() == '\r') row.remove_suffix(1);
    const std::string_view content = trim(row);
    if (content.empty() || content.starts_with("**")) continue;
    const Line line{content, index, number};
    if (line.keyword() && keyword_name(content.substr(1, content.find(',') - 1)) == "INCLUDE") {
      const Keyword k = parse_keyword(*this, line);
      const std::string* input = k.find("INPUT");
      if (!input || input->empty()) fail(line, "*INCLUDE needs INPUT=<file>");
      std::string name = *input;
      if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
      const fs::path target = fs::path(name).is_absolute() ? fs::path(name) : file.parent_path() / name;
      const fs::path inside = fs::weakly_canonical(target, ec).lexically_relative(fs::weakly_canonical(folder, ec));
      if (inside.empty() || *inside.begin() == "..")
        fail(line, fmt::format("*INCLUDE, INPUT={}: the file lies outside the case's folder {}; copy it there",
                               printable(name), folder.string()));
      load(target, folder, stack, &line);
      continue;
    }
    lines_.push_back(line);
  }
  stack.pop_back();
}

Keyword parse_keyword(const InpLines& deck, const Line& line) {
  Keyword k;
  const std::vector<std::string_view> parts = fields(line.text.substr(1));
  k.name = keyword_name(parts.front());
  if (k.name.empty()) deck.fail(line, "a keyword line without a keyword");
  for (size_t i = 1; i < parts.size(); ++i) {
    if (parts[i].empty()) continue;
    const size_t eq = parts[i].find('=');
    std::string key = keyword_name(parts[i].substr(0, eq));
    std::string value = eq == std::string_view::npos ? "" : std::string(trim(parts[i].substr(eq + 1)));
    k.parameters.emplace_back(std::move(key), std::move(value));
  }
  return k;
}

std::vector<std::string_view> fields(std::string_view text) {
  std::vector<std::string_view> out;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    out.push_back(trim(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

long integer_field(const InpLines& deck, const Line& line, std::string_view field, std::string_view what) {
  long value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || ec != std::errc() || end != field.data() + field.size())
    deck.fail(line, fmt::format("expected {} (an integer), found '{}'", what, printable(field)));
  return value;
}

// Fortran-style reals as decks write them: "2.1E+11", "7.8e3", "1.", ".5", "+3".
double number_field(const InpLines& deck, const Line& line, std::string_view field, std::string_view what) {
  std::string_view digits = field;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value))
    deck.fail(line, fmt::format("expected {} (a finite number), found '{}'", what, printable(field)));
  return value;
}

}  // namespace bb::inp
