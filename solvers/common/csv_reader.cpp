#include "common/csv_reader.hpp"

#include <fmt/format.h>

#include "common/errors.hpp"

namespace bb {

LineSource::LineSource(std::filesystem::path file) : file_(std::move(file)) {
  std::error_code ec;
  if (std::filesystem::is_directory(file_, ec)) throw InputError(file_.string() + ": cannot open (it is a directory)");
  try {
    in_ = std::make_unique<io::LineReader>(file_.string());
  } catch (const io::error::can_not_open_file&) {
    throw InputError(file_.string() + ": cannot open");
  }
}

LineSource::~LineSource() = default;

bool LineSource::next(std::string_view& line) {
  const char* raw = in_->next_line();
  if (!raw) return false;
  line_ = in_->get_file_line();
  line = raw;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // files written on Windows
  return true;
}

std::optional<std::string_view> LineSource::next_content(char comment) {
  std::string_view line;
  while (next(line)) {
    if (line_ == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);  // UTF-8 BOM
    line = trim(line);
    if (!line.empty() && line[0] != comment) return line;
  }
  return std::nullopt;
}

void LineSource::fail(const std::string& message) const {
  throw InputError(fmt::format("{}:{}: {}", file_.string(), line_, message));
}

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> split_csv(std::string_view line) {
  std::vector<std::string_view> cells;
  for (size_t start = 0;;) {
    const size_t comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

std::vector<std::string> read_csv_header(const std::filesystem::path& file) {
  LineSource in(file);
  std::vector<std::string> cells;
  if (const auto header = in.next_content())
    for (std::string_view c : split_csv(*header)) cells.emplace_back(c);
  return cells;
}

}  // namespace bb
