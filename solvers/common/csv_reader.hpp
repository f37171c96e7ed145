// Reading the project's text inputs, all through fast-cpp-csv-parser (libfccp): CsvReader for
// tables read by column name (comma separated, '#' comment lines, blanks trimmed, a header row),
// LineSource for files read line by line (measured data with units in the header, Matrix Market,
// dense matrices), and one way to split and trim a CSV line.
#pragma once
#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__)            // a GCC-only warning (clang has no such group)
#pragma GCC diagnostic ignored "-Wstringop-truncation"  // inside libfccp's error-message copy
#endif
#include <libfccp/csv.h>
#pragma GCC diagnostic pop

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bb {

template <unsigned N>
using CsvReader = io::CSVReader<N, io::trim_chars<' ', '\t'>, io::no_quote_escape<','>, io::throw_on_overflow,
                                io::single_line_comment<'#'>>;

// The numbered lines of a text file (any length, \n or \r\n endings). Every error it raises is an
// InputError that starts with "file:line:".
class LineSource {
 public:
  // InputError when the file cannot be opened or is a directory.
  explicit LineSource(std::filesystem::path file);
  ~LineSource();
  LineSource(const LineSource&) = delete;
  LineSource& operator=(const LineSource&) = delete;

  // The next line as it is; false at the end of the file.
  bool next(std::string_view& line);
  // The next line that is neither blank nor starts with `comment`, trimmed (and without a UTF-8
  // byte-order mark on the first line); nullopt at the end of the file.
  std::optional<std::string_view> next_content(char comment = '#');
  unsigned line_number() const { return line_; }
  const std::filesystem::path& file() const { return file_; }
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::filesystem::path file_;
  std::unique_ptr<io::LineReader> in_;
  unsigned line_ = 0;
};

// InputError naming the file unless it is a regular file that exists (not a folder, a device such as
// /dev/zero, a FIFO, a dangling link or a link loop) and, when `text`, holds no NUL byte (the line
// readers would end a cell there silently).
void require_readable_file(const std::filesystem::path& file, bool text = true);
// Why `file` is not a regular file that exists ("no such file", "it is a directory", a link loop's
// "Too many levels of symbolic links", ...); "" when it is one. Never throws.
std::string file_problem(const std::filesystem::path& file);

// Without leading and trailing blanks (spaces, tabs, \r).
std::string_view trim(std::string_view text);

// The comma-separated cells of one line, each trimmed.
std::vector<std::string_view> split_csv(std::string_view line);

// The header cells of a CSV file: its first line that is neither blank nor a '#' comment.
std::vector<std::string> read_csv_header(const std::filesystem::path& file);

}  // namespace bb
