#include "common/toml_reader.hpp"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.hpp"
#include "common/user_text.hpp"

namespace bb {
namespace {

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date/time";
  }
}

}  // namespace

std::optional<double> toml_number(const toml::node& n) {
  if (const auto* i = n.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = n.as_floating_point()) return f->get();
  return std::nullopt;
}

std::string SourceLocation::where() const {
  return line > 0 ? fmt::format("{}:{}", file.string(), line) : file.string();
}

TomlReader::TomlReader(const toml::table& table, std::string path, std::filesystem::path file)
    : table_(table), path_(std::move(path)), file_(std::move(file)) {}

SourceLocation TomlReader::location(const std::string& key) const {
  const toml::node* n = key.empty() ? nullptr : table_.get(key);
  const auto& src = n ? n->source() : table_.source();
  return {file_, static_cast<int>(src.begin.line)};
}

void TomlReader::fail(const std::string& key, const std::string& message) const {
  const std::string name =
      key.empty() ? fmt::format("[{}]", path_) : (path_.empty() ? key : fmt::format("{}.{}", path_, key));
  // Keys and messages may echo user bytes: printable() keeps them safe for terminals and reports.
  throw InputError(printable(fmt::format("{}: '{}': {}", location(key).where(), name, message)));
}

bool TomlReader::has(const std::string& key) const {
  used_.insert(key);
  return table_.contains(key);
}

bool TomlReader::has_array(const std::string& key) const {
  const toml::node* n = table_.get(key);
  return n && n->is_array();
}

const toml::node& TomlReader::required(const std::string& key) {
  used_.insert(key);
  const toml::node* n = table_.get(key);
  if (!n) fail(key, "missing required key");
  return *n;
}

double TomlReader::number(const std::string& key) {
  const toml::node& n = required(key);
  const std::optional<double> v = toml_number(n);
  if (!v) fail(key, "expected a number, found " + type_name(n));
  if (const std::string problem = number_problem(*v); !problem.empty()) fail(key, problem);
  return *v;
}

std::optional<double> TomlReader::optional_number(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return number(key);
}

double TomlReader::non_negative(const std::string& key, double fallback) {
  if (!has(key)) return fallback;
  const double v = number(key);
  if (v < 0) fail(key, fmt::format("must be >= 0, found {}", v));
  return v;
}

double TomlReader::positive(const std::string& key) {
  const double v = number(key);
  if (!(v > 0)) fail(key, fmt::format("must be > 0, found {}", v));
  return v;
}

long TomlReader::integer(const std::string& key, long lo, long hi) {
  const toml::node& n = required(key);
  if (!n.is_integer()) fail(key, "expected an integer, found " + type_name(n));
  const int64_t v = n.as_integer()->get();
  if (v < lo || v > hi) fail(key, fmt::format("{} is out of range: must lie in {}..{}", v, lo, hi));
  return static_cast<long>(v);
}

std::optional<long> TomlReader::optional_integer(const std::string& key, long lo, long hi) {
  if (!has(key)) return std::nullopt;
  return integer(key, lo, hi);
}

bool TomlReader::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const toml::node& n = required(key);
  if (!n.is_boolean()) fail(key, "expected true or false, found " + type_name(n));
  return n.value<bool>().value();
}

std::string TomlReader::string(const std::string& key) {
  const toml::node& n = required(key);
  if (!n.is_string()) fail(key, "expected a string, found " + type_name(n));
  return n.value<std::string>().value();
}

std::optional<std::string> TomlReader::optional_string(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return string(key);
}

std::string TomlReader::name(const std::string& key) {
  std::string v = string(key);
  if (const std::string problem = name_problem(v); !problem.empty()) fail(key, problem);
  return v;
}

std::string TomlReader::label(const std::string& key) {
  std::string v = string(key);
  if (const std::string problem = label_problem(v); !problem.empty()) fail(key, problem);
  return v;
}

std::optional<std::string> TomlReader::optional_label(const std::string& key, bool multiline) {
  if (!has(key)) return std::nullopt;
  std::string v = string(key);
  if (const std::string problem = label_problem(v, multiline); !problem.empty()) fail(key, problem);
  return v;
}

std::filesystem::path TomlReader::input_file(const std::string& key, const std::filesystem::path& folder) {
  const std::string v = string(key);
  if (v.empty()) fail(key, "an empty file name");
  if (v.find('\0') != std::string::npos) fail(key, "a file name with a NUL byte");
  const std::filesystem::path file = folder / v;
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) fail(key, fmt::format("{} is a folder; name a file", file.string()));
  // A symbolic-link loop (or a folder on the way that cannot be searched): no reader could open it.
  if (ec && ec != std::errc::no_such_file_or_directory)
    fail(key, fmt::format("{}: cannot open ({})", file.string(), ec.message()));
  return file;
}

void TomlReader::labels_as_keys() const {
  for (const auto& [k, v] : table_)
    if (const std::string problem = label_problem(k.str()); !problem.empty()) fail(std::string(k.str()), problem);
}

std::string TomlReader::choice(const std::string& key, const std::vector<std::string>& choices,
                               std::optional<std::string> fallback) {
  if (fallback && !has(key)) return *fallback;
  const std::string v = string(key);
  for (const auto& c : choices)
    if (c == v) return v;
  fail(key, fmt::format("unknown value '{}'; expected one of: {}", v, fmt::join(choices, ", ")));
}

const toml::array& TomlReader::array(const std::string& key) {
  const toml::node& n = required(key);
  if (!n.is_array()) fail(key, "expected an array, found " + type_name(n));
  return *n.as_array();
}

std::vector<double> TomlReader::number_array(const std::string& key) {
  std::vector<double> out;
  for (const toml::node& n : array(key)) {
    const std::optional<double> v = toml_number(n);
    if (!v) fail(key, "expected an array of numbers, found " + type_name(n) + " in it");
    if (!std::isfinite(*v)) fail(key, "array entries must be finite");
    if (const std::string problem = number_problem(*v); !problem.empty()) fail(key, "an entry: " + problem);
    out.push_back(*v);
  }
  return out;
}

std::vector<long> TomlReader::integer_array(const std::string& key, long lo, long hi) {
  std::vector<long> out;
  for (const toml::node& n : array(key)) {
    if (!n.is_integer()) fail(key, "expected an array of integers, found " + type_name(n) + " in it");
    const int64_t v = n.as_integer()->get();
    if (v < lo || v > hi) fail(key, fmt::format("an entry {} is out of range: must lie in {}..{}", v, lo, hi));
    out.push_back(static_cast<long>(v));
  }
  return out;
}

std::vector<std::string> TomlReader::string_array(const std::string& key) {
  std::vector<std::string> out;
  for (const toml::node& n : array(key)) {
    if (!n.is_string()) fail(key, "expected an array of strings, found " + type_name(n) + " in it");
    out.push_back(n.value<std::string>().value());
  }
  return out;
}

const toml::table& TomlReader::table(const std::string& key) {
  const toml::node& n = required(key);
  if (!n.is_table()) fail(key, "expected a table, found " + type_name(n));
  return *n.as_table();
}

const toml::table* TomlReader::optional_table(const std::string& key) {
  if (!has(key)) return nullptr;
  return &table(key);
}

void TomlReader::finish() const {
  for (const auto& [k, v] : table_) {
    const std::string key(k.str());
    if (!used_.count(key)) fail(key, "unknown key (see cases/README.md for the case format)");
  }
}

}  // namespace bb
