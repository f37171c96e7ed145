#include "checks/checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"

namespace bb {

ReferenceColumn read_reference_column(const std::filesystem::path& file, const std::string& key_column,
                                      const std::string& value_column) {
  if (!std::filesystem::is_regular_file(file)) throw InputError(fmt::format("reference file not found: {}", file.string()));
  ReferenceColumn out;
  try {
    CsvReader<2> in(file.string());
    in.read_header(io::ignore_extra_column, key_column, value_column);
    std::string key_text, value_text;
    while (in.read_row(key_text, value_text)) {
      const auto line = in.get_file_line();
      long key = 0;
      auto [kp, kec] = std::from_chars(key_text.data(), key_text.data() + key_text.size(), key);
      if (kec != std::errc() || kp != key_text.data() + key_text.size())
        throw InputError(fmt::format("{}:{}: column '{}': '{}' is not an integer key", file.string(), line, key_column, key_text));
      double value = 0.0;
      auto [vp, vec] = std::from_chars(value_text.data(), value_text.data() + value_text.size(), value);
      if (vec != std::errc() || vp != value_text.data() + value_text.size())
        throw InputError(fmt::format("{}:{}: column '{}': '{}' is not a number", file.string(), line, value_column, value_text));
      if (!std::isfinite(value))
        throw InputError(fmt::format("{}:{}: column '{}': non-finite reference value '{}'", file.string(), line, value_column, value_text));
      out.keys.push_back(key);
      out.values.push_back(value);
    }
  } catch (const io::error::base& e) {
    throw InputError(fmt::format("{}: {}", file.string(), e.what()));
  }
  if (out.keys.empty()) throw InputError(fmt::format("{}: no data rows", file.string()));
  return out;
}

namespace {

// A column of another result table of the same run as the reference (e.g. the full model's
// peaks for a reduced model's).
ReferenceColumn result_reference_column(const ResultTables& results, const std::string& table_name,
                                        const std::string& key_column, const std::string& value_column) {
  const auto it = results.find(table_name);
  if (it == results.end()) throw InputError(fmt::format("reference result '{}' is not produced by this analysis", table_name));
  const ResultTable& t = it->second;
  if (t.columns.empty() || t.columns[0] != key_column)
    throw InputError(fmt::format("reference result '{}' is keyed by '{}', not '{}'", table_name,
                                 t.columns.empty() ? "" : t.columns[0], key_column));
  const auto col = t.column_index(value_column);
  if (!col || *col == 0)
    throw InputError(fmt::format("reference result '{}' has no column '{}' (columns: {})", table_name, value_column,
                                 fmt::join(t.columns, ", ")));
  ReferenceColumn ref;
  for (Eigen::Index i = 0; i < t.values.rows(); ++i) {
    ref.keys.push_back(std::lround(t.values(i, 0)));
    ref.values.push_back(t.values(i, *col));
  }
  return ref;
}

std::string reference_name(const CheckSpec& check) {
  if (!check.reference_case.empty()) return fmt::format("result {} of {}", check.reference_result, check.reference_case.filename().string());
  return check.reference_result.empty() ? check.reference.string() : "result " + check.reference_result;
}

}  // namespace

const char* relation_symbol(CheckSpec::Relation relation) {
  switch (relation) {
    case CheckSpec::Relation::equal: return "=";
    case CheckSpec::Relation::at_most: return "<=";
    case CheckSpec::Relation::at_least: return ">=";
  }
  return "?";
}

std::vector<CheckEntry> evaluate_check(const CheckSpec& check, const ResultTables& results, const ResultTables* reference_results) {
  auto table_it = results.find(check.result);
  if (table_it == results.end()) {
    std::vector<std::string> produced;
    for (const auto& [name, table] : results) produced.push_back(name);
    throw InputError(fmt::format("{}: check '{}' asks for result '{}', which this analysis does not produce (it produces: {})",
                                 check.at.where(), check.name, check.result, fmt::join(produced, ", ")));
  }
  const ResultTable& table = table_it->second;
  std::vector<CheckEntry> entries;
  for (const auto& [result_column, reference_column] : check.compare) {
    const auto col = table.column_index(result_column);
    const bool text_column = std::find(table.text_columns.begin(), table.text_columns.end(), result_column) != table.text_columns.end();
    if (text_column)
      throw InputError(fmt::format("{}: check '{}': column '{}' of result '{}' holds text labels; checks compare numbers",
                                   check.at.where(), check.name, result_column, check.result));
    if (!col || *col == 0)
      throw InputError(fmt::format("{}: check '{}': result '{}' has no column '{}' (columns: {})", check.at.where(),
                                   check.name, check.result, result_column, fmt::join(table.columns, ", ")));
    ReferenceColumn ref;
    try {
      ref = check.reference_result.empty() ? read_reference_column(check.reference, check.key, reference_column)
                                           : result_reference_column(reference_results ? *reference_results : results,
                                                                     check.reference_result, check.key, reference_column);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: check '{}': {}", check.at.where(), check.name, e.what()));
    }
    for (long key : check.keys)
      if (std::find(ref.keys.begin(), ref.keys.end(), key) == ref.keys.end())
        throw InputError(fmt::format("{}: check '{}': key {} = {} is not a row of {}", check.at.where(), check.name,
                                     check.key, key, reference_name(check)));
    for (size_t i = 0; i < ref.keys.size(); ++i) {
      if (!check.keys.empty() && std::find(check.keys.begin(), check.keys.end(), ref.keys[i]) == check.keys.end()) continue;
      const int row = table.row_of_key(ref.keys[i]);
      if (row < 0)
        throw InputError(fmt::format("{}: reference row {} = {} has no match in result '{}'", reference_name(check),
                                     check.key, ref.keys[i], check.result));
      CheckEntry e;
      e.group = check.name;
      e.column = result_column;
      e.key = ref.keys[i];
      e.name = fmt::format("{}: {} {} {}", check.name, result_column, table.columns[0], ref.keys[i]);
      e.computed = table.values(row, *col);
      e.reference = ref.values[i];
      e.abs_error = std::abs(e.computed - e.reference);
      e.rel_error = e.reference != 0.0 ? e.abs_error / std::abs(e.reference)
                                       : (e.abs_error == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
      e.tolerance = check.abs_tol + check.rel_tol * std::abs(e.reference);
      e.relation = check.relation;
      switch (check.relation) {
        case CheckSpec::Relation::equal: e.pass = e.abs_error <= e.tolerance; break;
        case CheckSpec::Relation::at_most: e.pass = e.computed <= e.reference + e.tolerance; break;
        case CheckSpec::Relation::at_least: e.pass = e.computed >= e.reference - e.tolerance; break;
      }
      e.pass = e.pass && std::isfinite(e.computed);
      entries.push_back(e);
    }
  }
  return entries;
}

}  // namespace bb
