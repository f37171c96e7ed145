// Checks: computed result vs reference value vs tolerance, one entry per compared number.
#pragma once
#include <string>
#include <vector>

#include <filesystem>

#include "checks/check_spec.hpp"
#include "results/table.hpp"

namespace bb {

struct CheckEntry {
  std::string name;        // "<check name>: <column> <key> <id>"
  std::string group;       // the check's name
  std::string column;      // the compared result column
  long key = 0;            // the row's key (node id, mode number)
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

// Throws InputError when the reference names a row the results do not have. A reference_result is
// looked up in `reference_results` when given (the run of check.reference_case), else in `results`.
std::vector<CheckEntry> evaluate_check(const CheckSpec& check, const ResultTables& results,
                                       const ResultTables* reference_results = nullptr);

// "=", "<=" or ">=": how an entry's computed value must relate to its reference.
const char* relation_symbol(CheckSpec::Relation relation);

}  // namespace bb
