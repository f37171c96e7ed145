// Typed access to one TOML table with errors that name file, line and key, and a final
// check that rejects keys the case format does not know (typos must not pass silently). Every
// number and integer of a case passes through here: its range, overflow and finiteness are
// checked once, for every key.
#pragma once
#include <toml++/toml.h>

#include <climits>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/input_number.hpp"
#include "common/source_location.hpp"

namespace bb {

// The value of a number node (an integer converted exactly where it can be), else nullopt.
std::optional<double> toml_number(const toml::node& n);

class TomlReader {
 public:
  TomlReader(const toml::table& table, std::string path, std::filesystem::path file);

  bool has(const std::string& key) const;
  bool has_array(const std::string& key) const;  // the key is there and holds an array
  double number(const std::string& key);
  std::optional<double> optional_number(const std::string& key);
  double non_negative(const std::string& key, double fallback);
  double positive(const std::string& key);
  // An integer within [lo, hi]; by default the range of an int, so that no count or index wraps.
  long integer(const std::string& key, long lo = INT_MIN, long hi = INT_MAX);
  std::optional<long> optional_integer(const std::string& key, long lo = INT_MIN, long hi = INT_MAX);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::optional<std::string> optional_string(const std::string& key);
  // A string that is a name or a label (common/user_text.hpp), else an error naming file, line, key.
  std::string name(const std::string& key);
  std::string label(const std::string& key);
  std::optional<std::string> optional_label(const std::string& key, bool multiline = false);
  // A file named relative to `folder`; it may be missing (its reader says so), but a folder or a
  // path that cannot be resolved (a symbolic-link loop) is an error naming the key.
  std::filesystem::path input_file(const std::string& key, const std::filesystem::path& folder);
  // One of `choices`; the error lists them.
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     std::optional<std::string> fallback = std::nullopt);
  const toml::array& array(const std::string& key);
  std::vector<double> number_array(const std::string& key);
  std::vector<long> integer_array(const std::string& key, long lo = INT_MIN, long hi = INT_MAX);
  std::vector<std::string> string_array(const std::string& key);
  const toml::table& table(const std::string& key);
  const toml::table* optional_table(const std::string& key);

  // Throws unless every key of the table is a label (e.g. the column names of a check's compare).
  void labels_as_keys() const;
  // Throws for any key that was never read.
  void finish() const;
  SourceLocation location(const std::string& key = {}) const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  const std::string& path() const { return path_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  const toml::node& required(const std::string& key);
  const toml::table& table_;
  std::string path_;
  std::filesystem::path file_;
  mutable std::set<std::string> used_;
};

}  // namespace bb
