#include "checks/checks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"

namespace bb {

ReferenceColumn read_reference_column(const std::filesystem::path& file, const std::string& key_column,
                                      const std::string& value_column) {
  if (file_problem(file) == "no such file")
    throw InputError(fmt::format("reference file not found: {}", file.string()));
  require_readable_file(file);
  ReferenceColumn out;
  std::map<long, unsigned> line_of_key;  // a key twice would make two entries of one computed row
  try {
    CsvReader<2> in(file.string());
    in.read_header(io::ignore_extra_column, key_column, value_column);
    std::string key_text, value_text;
    while (in.read_row(key_text, value_text)) {
      const auto line = in.get_file_line();
      long key = 0;
      auto [kp, kec] = std::from_chars(key_text.data(), key_text.data() + key_text.size(), key);
      if (kec != std::errc() || kp != key_text.data() + key_text.size())
        throw InputError(
            fmt::format("{}:{}: column '{}': '{}' is not an integer key", file.string(), line, key_column, key_text));
      if (const auto [it, fresh] = line_of_key.emplace(key, line); !fresh)
        throw InputError(fmt::format("{}:{}: column '{}': key {} is also the key of line {}; each row needs its own",
                                     file.string(), line, key_column, key, it->second));
      double value = 0.0;
      auto [vp, vec] = std::from_chars(value_text.data(), value_text.data() + value_text.size(), value);
      if (vec != std::errc() || vp != value_text.data() + value_text.size())
        throw InputError(
            fmt::format("{}:{}: column '{}': '{}' is not a number", file.string(), line, value_column, value_text));
      if (!std::isfinite(value))
        throw InputError(fmt::format("{}:{}: column '{}': non-finite reference value '{}'", file.string(), line,
                                     value_column, value_text));
      out.keys.push_back(key);
      out.values.push_back(value);
    }
  } catch (const io::error::base& e) {
    throw InputError(fmt::format("{}: {}", file.string(), e.what()));
  }
  if (out.keys.empty()) throw InputError(fmt::format("{}: no data rows", file.string()));
  return out;
}

std::vector<std::pair<long, std::string>> read_reference_labels(const std::filesystem::path& file,
                                                                const std::string& key_column,
                                                                const std::string& label_column) {
  if (file_problem(file) == "no such file")
    throw InputError(fmt::format("reference file not found: {}", file.string()));
  require_readable_file(file);
  std::vector<std::pair<long, std::string>> out;
  try {
    CsvReader<2> in(file.string());
    in.read_header(io::ignore_extra_column, key_column, label_column);
    std::string key_text, label;
    while (in.read_row(key_text, label)) {
      long key = 0;
      auto [kp, kec] = std::from_chars(key_text.data(), key_text.data() + key_text.size(), key);
      if (kec != std::errc() || kp != key_text.data() + key_text.size())
        throw InputError(fmt::format("{}:{}: column '{}': '{}' is not an integer key", file.string(),
                                     in.get_file_line(), key_column, key_text));
      out.emplace_back(key, label);
    }
  } catch (const io::error::base& e) {
    throw InputError(fmt::format("{}: {}", file.string(), e.what()));
  }
  return out;
}

void require_check_references(const std::vector<CheckSpec>& checks) {
  for (const CheckSpec& c : checks) {
    try {
      if (!c.reference_case.empty() && !file_problem(c.reference_case).empty())
        throw InputError(
            fmt::format("reference case {}: {}", c.reference_case.string(), file_problem(c.reference_case)));
      if (c.reference.empty()) continue;
      for (const auto& [result_column, reference_column] : c.compare)
        read_reference_column(c.reference, c.key, reference_column);
      for (const std::string& label : c.labels) read_reference_labels(c.reference, c.key, label);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: check '{}': {}", c.at.where(), c.name, e.what()));
    }
  }
}

namespace {

// The labels of every row of a result table by its key, the chosen text columns joined.
std::map<long, std::string> table_labels(const ResultTable& t, const std::vector<std::string>& columns,
                                         const std::string& where) {
  std::map<long, std::string> out;
  for (Eigen::Index r = 0; r < t.values.rows(); ++r) out[std::lround(t.values(r, 0))] = "";
  for (const std::string& c : columns) {
    const auto it = std::find(t.text_columns.begin(), t.text_columns.end(), c);
    if (it == t.text_columns.end())
      throw InputError(fmt::format(
          "{}: result '{}' has no text column '{}' to match rows by (text columns: {})", where, t.name, c,
          t.text_columns.empty() ? std::string("none") : fmt::format("{}", fmt::join(t.text_columns, ", "))));
    const auto& text = t.text[static_cast<size_t>(it - t.text_columns.begin())];
    for (Eigen::Index r = 0; r < t.values.rows(); ++r)
      out[std::lround(t.values(r, 0))] +=
          (out[std::lround(t.values(r, 0))].empty() ? "" : " ") + text[static_cast<size_t>(r)];
  }
  return out;
}

// match = label: the k-th reference row (in key order) of a label pairs with the k-th computed row of
// the same label.
RowMatch match_by_labels(const CheckSpec& check, const ResultTable& computed, const ResultTables& reference_tables) {
  const std::string where = fmt::format("{}: check '{}'", check.at.where(), check.name);
  std::map<long, std::string> reference;
  if (!check.reference_result.empty()) {
    const auto it = reference_tables.find(check.reference_result);
    if (it == reference_tables.end())
      throw InputError(fmt::format("{}: reference result '{}' is not produced", where, check.reference_result));
    reference = table_labels(it->second, check.labels, where);
  } else {
    for (const std::string& c : check.labels)
      for (const auto& [key, label] : read_reference_labels(check.reference, check.key, c))
        reference[key] += (reference[key].empty() ? "" : " ") + label;
  }
  std::map<std::string, std::vector<long>> computed_by_label;
  for (const auto& [key, label] : table_labels(computed, check.labels, where)) computed_by_label[label].push_back(key);
  RowMatch m;
  std::map<std::string, size_t> seen;
  for (const auto& [key, label] : reference) {
    const size_t k = seen[label]++;
    const auto& candidates = computed_by_label[label];
    if (k < candidates.size()) {
      m.computed_key[key] = candidates[k];
      m.note[key] = fmt::format("'{}' #{}", label, k + 1);
    } else {
      m.note[key] = fmt::format("no computed row '{}' #{}", label, k + 1);
    }
  }
  return m;
}

// A column of another result table of the same run as the reference (e.g. the full model's
// peaks for a reduced model's).
ReferenceColumn result_reference_column(const ResultTables& results, const std::string& table_name,
                                        const std::string& key_column, const std::string& value_column) {
  const auto it = results.find(table_name);
  if (it == results.end())
    throw InputError(fmt::format("reference result '{}' is not produced by this analysis", table_name));
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
  if (!check.reference_case.empty())
    return fmt::format("result {} of {}", check.reference_result, check.reference_case.filename().string());
  return check.reference_result.empty() ? check.reference.string() : "result " + check.reference_result;
}

}  // namespace

double tolerance_used(const CheckEntry& e) {
  double excess = e.abs_error;
  switch (e.relation) {
    case CheckSpec::Relation::equal:
      break;
    case CheckSpec::Relation::at_most:
      excess = e.computed - e.reference;
      break;
    case CheckSpec::Relation::at_least:
      excess = e.reference - e.computed;
      break;
  }
  double used = e.tolerance > 0.0 ? excess / e.tolerance : excess > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  if (std::isnan(used)) used = std::numeric_limits<double>::infinity();
  if (!e.pass && used <= 1.0) used = std::numeric_limits<double>::infinity();
  return used;
}

const char* relation_symbol(CheckSpec::Relation relation) {
  switch (relation) {
    case CheckSpec::Relation::equal:
      return "=";
    case CheckSpec::Relation::at_most:
      return "<=";
    case CheckSpec::Relation::at_least:
      return ">=";
  }
  return "?";
}

std::vector<CheckEntry> evaluate_check(const CheckSpec& check, const ResultTables& results,
                                       const ResultTables* reference_results, const RowMatch* match) {
  auto table_it = results.find(check.result);
  if (table_it == results.end()) {
    std::vector<std::string> produced;
    for (const auto& [name, table] : results) produced.push_back(name);
    throw InputError(
        fmt::format("{}: check '{}' asks for result '{}', which this analysis does not produce (it produces: {})",
                    check.at.where(), check.name, check.result, fmt::join(produced, ", ")));
  }
  const ResultTable& table = table_it->second;
  std::optional<RowMatch> by_label;
  if (check.match == CheckSpec::Match::label)
    by_label = match_by_labels(check, table, reference_results ? *reference_results : results);
  const RowMatch* pairing = by_label ? &*by_label : match;
  if (check.match == CheckSpec::Match::mac && !match)
    throw InputError(fmt::format(
        "{}: check '{}': match = \"mac\" pairs the modes of two modal runs; this run has no mode shapes to pair",
        check.at.where(), check.name));
  std::vector<CheckEntry> entries;
  for (const auto& [result_column, reference_column] : check.compare) {
    const auto col = table.column_index(result_column);
    const bool text_column =
        std::find(table.text_columns.begin(), table.text_columns.end(), result_column) != table.text_columns.end();
    if (text_column)
      throw InputError(
          fmt::format("{}: check '{}': column '{}' of result '{}' holds text labels; checks compare numbers",
                      check.at.where(), check.name, result_column, check.result));
    if (!col || *col == 0)
      throw InputError(fmt::format("{}: check '{}': result '{}' has no column '{}' (columns: {})", check.at.where(),
                                   check.name, check.result, result_column, fmt::join(table.columns, ", ")));
    ReferenceColumn ref;
    try {
      ref = check.reference_result.empty()
                ? read_reference_column(check.reference, check.key, reference_column)
                : result_reference_column(reference_results ? *reference_results : results, check.reference_result,
                                          check.key, reference_column);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: check '{}': {}", check.at.where(), check.name, e.what()));
    }
    for (long key : check.keys)
      if (std::find(ref.keys.begin(), ref.keys.end(), key) == ref.keys.end())
        throw InputError(fmt::format("{}: check '{}': key {} = {} is not a row of {}", check.at.where(), check.name,
                                     check.key, key, reference_name(check)));
    for (size_t i = 0; i < ref.keys.size(); ++i) {
      if (!check.keys.empty() && std::find(check.keys.begin(), check.keys.end(), ref.keys[i]) == check.keys.end())
        continue;
      CheckEntry e;
      e.group = check.name;
      e.column = result_column;
      e.key = ref.keys[i];
      e.computed_key = ref.keys[i];
      e.name = fmt::format("{}: {} {} {}", check.name, result_column, table.columns[0], ref.keys[i]);
      int row = -1;
      if (pairing) {
        const auto it = pairing->computed_key.find(ref.keys[i]);
        const auto note = pairing->note.find(ref.keys[i]);
        const std::string why = note == pairing->note.end() ? std::string("no match") : note->second;
        if (it == pairing->computed_key.end()) {
          // No partner: the entry fails with its reason, it does not stop the run.
          e.name += fmt::format(" (unmatched: {})", why);
          e.computed = std::numeric_limits<double>::quiet_NaN();
          e.reference = ref.values[i];
          e.abs_error = e.rel_error = std::numeric_limits<double>::infinity();
          e.tolerance = check.abs_tol + check.rel_tol * std::abs(e.reference);
          e.relation = check.relation;
          e.pass = false;
          entries.push_back(e);
          continue;
        }
        e.computed_key = it->second;
        e.name += fmt::format(" (computed {} {}, {})", table.columns[0], it->second, why);
      }
      row = table.row_of_key(e.computed_key);
      if (row < 0)
        throw InputError(fmt::format("{}: reference row {} = {} has no match in result '{}'", reference_name(check),
                                     check.key, e.computed_key, check.result));
      e.computed = table.values(row, *col);
      e.reference = ref.values[i];
      e.abs_error = std::abs(e.computed - e.reference);
      e.rel_error = e.reference != 0.0 ? e.abs_error / std::abs(e.reference)
                                       : (e.abs_error == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
      e.tolerance = check.abs_tol + check.rel_tol * std::abs(e.reference);
      e.relation = check.relation;
      switch (check.relation) {
        case CheckSpec::Relation::equal:
          e.pass = e.abs_error <= e.tolerance;
          break;
        case CheckSpec::Relation::at_most:
          e.pass = e.computed <= e.reference + e.tolerance;
          break;
        case CheckSpec::Relation::at_least:
          e.pass = e.computed >= e.reference - e.tolerance;
          break;
      }
      // A NaN or inf on either side (a value that does not apply, e.g. a reference_result row
      // without a peak) fails the entry, whatever the relation: a run cannot pass on it.
      e.pass = e.pass && std::isfinite(e.computed) && std::isfinite(e.reference);
      entries.push_back(e);
    }
  }
  return entries;
}

}  // namespace bb
