#include "cases/case_settings.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <memory>
#include <sstream>
#include <type_traits>
#include <utility>

#include "common/errors.hpp"
#include "common/user_text.hpp"

namespace bb {

namespace {

// A copy of the node without its source region (a parsed node would name line 1 of the case file).
std::unique_ptr<toml::node> without_source(const toml::node& n) {
  if (const toml::array* a = n.as_array()) {
    auto out = std::make_unique<toml::array>();
    for (const toml::node& e : *a) out->push_back(std::move(*without_source(e)));
    return out;
  }
  if (const toml::table* t = n.as_table()) {
    auto out = std::make_unique<toml::table>();
    for (const auto& [k, v] : *t) out->insert(k, std::move(*without_source(v)));
    return out;
  }
  return n.visit([](const auto& v) -> std::unique_ptr<toml::node> {
    using V = std::decay_t<decltype(v)>;
    if constexpr (toml::is_value<V>)
      return std::make_unique<V>(v.get());
    else
      return nullptr;
  });
}

[[noreturn]] void fail(const std::string& option, const std::string& setting, const std::string& why) {
  throw InputError(printable(fmt::format("{} '{}': {}", option, setting, why)));
}

// The table that holds the last part of `key`, and that part.
std::pair<toml::table*, std::string> holder(toml::table& root, const std::string& key, const std::string& option,
                                            const std::string& setting) {
  std::vector<std::string> parts;
  std::stringstream in(key);
  for (std::string part; std::getline(in, part, '.');) {
    if (part.empty()) fail(option, setting, "empty key part");
    parts.push_back(part);
  }
  if (parts.empty()) fail(option, setting, "no key");
  toml::table* table = &root;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = table->get(parts[i]);
    // An array of tables ([[analysis.contact]]) is entered by index: analysis.contact.0.mu.
    if (toml::array* array = next ? next->as_array() : nullptr; array && array->is_array_of_tables()) {
      const std::string name = fmt::format("{}", fmt::join(parts.begin(), parts.begin() + i + 1, "."));
      if (i + 2 >= parts.size())
        fail(option, setting,
             fmt::format("[[{}]] is an array of tables: name an element's key, {}.0.<key>", name, name));
      const std::string& index = parts[++i];
      if (index.find_first_not_of("0123456789") != std::string::npos || index.size() > 6 ||
          std::stoul(index) >= array->size())
        fail(option, setting, fmt::format("'{}' is not an index of [[{}]] (0 to {})", index, name, array->size() - 1));
      next = array->get(std::stoul(index));
    }  // (an empty array is no array of tables)
    if (!next || !next->is_table())
      fail(option, setting,
           fmt::format("the case has no table [{}]", fmt::join(parts.begin(), parts.begin() + i + 1, ".")));
    table = next->as_table();
  }
  return {table, parts.back()};
}

// An element of an array of values (analysis.model.frequency_hz.0 = 75.3): false when `key` does
// not end in an index of one.
bool set_array_element(toml::table& root, const std::string& key, const toml::node& value, const std::string& setting) {
  const size_t dot = key.rfind('.');
  if (dot == std::string::npos) return false;
  const std::string index = key.substr(dot + 1);
  if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos) return false;
  const auto [table, last] = holder(root, key.substr(0, dot), "--set", setting);
  toml::array* array = table->get(last) ? table->get(last)->as_array() : nullptr;
  if (!array || array->is_array_of_tables()) return false;
  if (index.size() > 6 || std::stoul(index) >= array->size())
    fail("--set", setting,
         fmt::format("'{}' is not an index of {} ({} element(s))", index, key.substr(0, dot), array->size()));
  array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(std::stoul(index)), std::move(*without_source(value)));
  return true;
}

}  // namespace

void apply_settings(toml::table& root, const std::vector<std::string>& settings,
                    const std::vector<std::string>& removals) {
  for (const std::string& setting : settings) {
    const size_t eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) fail("--set", setting, "expected dotted.key=VALUE");
    toml::table parsed;
    try {
      parsed = toml::parse("value = " + setting.substr(eq + 1));
    } catch (const toml::parse_error& e) {
      fail("--set", setting, fmt::format("the value is not TOML ({}); strings need quotes", e.description()));
    }
    const std::string key = setting.substr(0, eq);
    const toml::node* value = parsed.get("value");
    if (!value) fail("--set", setting, "no value");
    // More keys or tables after a newline would be dropped silently: one value or nothing.
    if (parsed.size() != 1)
      fail("--set", setting, "the value is more than one TOML value (keys or tables after it); give exactly one");
    if (set_array_element(root, key, *value, setting)) continue;
    const auto [table, last] = holder(root, key, "--set", setting);
    table->insert_or_assign(last, std::move(*without_source(*value)));
  }
  for (const std::string& key : removals) {
    const auto [table, last] = holder(root, key, "--unset", key);
    if (!table->contains(last)) fail("--unset", key, "the case has no such key");
    table->erase(last);
  }
}

}  // namespace bb
