// Checks: computed result vs reference value vs tolerance, one entry per compared number.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "checks/check_spec.hpp"
#include "results/table.hpp"

namespace bb {

struct CheckEntry {
  std::string name;       // "<check name>: <column> <key> <id>" (and the matched row, when matched)
  std::string group;      // the check's name
  std::string column;     // the compared result column
  long key = 0;           // the reference row's key (node id, mode number)
  long computed_key = 0;  // the computed row's key: `key`, or the row a match pairs it with
  double computed = 0.0;
  double reference = 0.0;
  double abs_error = 0.0;
  double rel_error = 0.0;  // abs_error / |reference|, infinity for a zero reference with a nonzero error
  double tolerance = 0.0;  // abs_tol + rel_tol * |reference|
  CheckSpec::Relation relation = CheckSpec::Relation::equal;
  bool pass = false;
};

struct ReferenceColumn {
  std::vector<long> keys;
  std::vector<double> values;
};

// Reads one key column and one value column by header name; '#' lines are comments.
// Throws InputError naming the file and line of a missing column, a bad or non-finite number.
ReferenceColumn read_reference_column(const std::filesystem::path& file, const std::string& key_column,
                                      const std::string& value_column);

// Reads the text labels of `label_column` by `key_column` ('#' lines are comments); an empty cell is
// the label "". Throws InputError naming the file and line.
std::vector<std::pair<long, std::string>> read_reference_labels(const std::filesystem::path& file,
                                                                const std::string& key_column,
                                                                const std::string& label_column);

// Opens every reference the checks name (each compared column and label column of a reference
// file, the file of a reference case), so that a missing file, column or number stops the run
// before any solve instead of after it. InputError naming the check's line and name.
void require_check_references(const std::vector<CheckSpec>& checks);

// The computed row of each reference row when a check does not pair them by key (match = mac: from
// checks/mode_matching; a reference key absent from `computed_key` has no partner and fails).
struct RowMatch {
  std::map<long, long> computed_key;
  std::map<long, std::string> note;  // shown in the entry's name, e.g. "MAC 0.998"
};

// Throws InputError when the reference names a row the results do not have. A reference_result is
// looked up in `reference_results` when given (the run of check.reference_case), else in `results`.
// `match` pairs the rows of a check with match = mac; match = label is resolved here from the text
// columns of the two tables (or of the reference file).
std::vector<CheckEntry> evaluate_check(const CheckSpec& check, const ResultTables& results,
                                       const ResultTables* reference_results = nullptr,
                                       const RowMatch* match = nullptr);

// How much of its tolerance an entry uses: |computed - reference| / tolerance for `=`, the excess
// over the bound for `<=` / `>=` (negative: inside the bound by that much); infinity for a failed
// entry whose numbers do not say why (a non-finite value, a row without a partner). At most 1 for
// a passing entry, above 1 for a failing one.
double tolerance_used(const CheckEntry& e);

// "=", "<=" or ">=": how an entry's computed value must relate to its reference.
const char* relation_symbol(CheckSpec::Relation relation);

}  // namespace bb
