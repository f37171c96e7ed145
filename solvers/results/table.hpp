// A result table: named columns of numbers, the first column an integer key (node id, mode),
// optionally followed by text columns (labels such as a mode's type). Checks compare numeric
// columns only; the CSV writer puts the text columns after the numeric ones.
#pragma once
#include <Eigen/Dense>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace bb {

struct ResultTable {
  std::string name;                            // e.g. "nodal_displacements"; the CSV is <name>.csv
  std::vector<std::string> columns;            // columns[0] is the key
  Eigen::MatrixXd values;                      // one row per entry
  std::vector<std::string> text_columns;       // names of the text columns, or empty
  std::vector<std::vector<std::string>> text;  // per text column, one string per row

  // Appends a text column; throws std::invalid_argument unless it has one value per row.
  void add_text_column(const std::string& column, std::vector<std::string> values);
  std::optional<int> column_index(const std::string& column) const;
  // Row whose key equals `key`, or -1.
  int row_of_key(long key) const;
};

using ResultTables = std::map<std::string, ResultTable>;

// A table from rows of numbers, each as long as `columns` (the first is the key).
ResultTable table_from_rows(const std::string& name, std::vector<std::string> columns,
                            const std::vector<std::vector<double>>& rows);

}  // namespace bb
