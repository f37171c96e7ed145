#include "common/csv_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "common/errors.hpp"

namespace bb {

LineSource::LineSource(std::filesystem::path file) : file_(std::move(file)) {
  require_readable_file(file_);
  try {
    in_ = std::make_unique<io::LineReader>(file_.string());
  } catch (const io::error::can_not_open_file&) {
    throw InputError(file_.string() + ": cannot open");
  }
}

std::string file_problem(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(file, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) return ec.message();  // a symlink loop, say
  if (!std::filesystem::exists(st)) return "no such file";
  if (std::filesystem::is_directory(st)) return "it is a directory";
  // A device (/dev/zero), a FIFO or a socket never ends or never is data.
  if (!std::filesystem::is_regular_file(st)) return "not a regular file: a device, a FIFO or a socket";
  return {};
}

void require_readable_file(const std::filesystem::path& file, bool text) {
  if (const std::string why = file_problem(file); !why.empty())
    throw InputError(fmt::format("{}: cannot open ({})", file.string(), why));
  if (!text) return;
  // The line readers end a line at a NUL byte: one inside a cell would silently cut its value.
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open");
  std::vector<char> block(1 << 16);
  unsigned line = 1;
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto n = static_cast<size_t>(in.gcount());
    if (const void* nul = std::memchr(block.data(), '\0', n)) {
      line += static_cast<unsigned>(
          std::count(static_cast<const char*>(block.data()), static_cast<const char*>(nul), '\n'));
      throw InputError(
          fmt::format("{}:{}: a NUL byte in the file (binary data, or a corrupted text file)", file.string(), line));
    }
    line += static_cast<unsigned>(std::count(block.data(), block.data() + n, '\n'));
  }
}

LineSource::~LineSource() = default;

bool LineSource::next(std::string_view& line) {
  const char* raw = nullptr;
  try {
    raw = in_->next_line();
  } catch (const io::error::base& e) {  // a line longer than the reader's block, say
    fail(e.what());
  }
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
