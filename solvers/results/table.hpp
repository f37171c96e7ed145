// A result table: named columns of numbers, the first column an integer key (node id, mode).
#pragma once
#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace bb {

struct ResultTable {
  std::string name;                  // e.g. "nodal_displacements"; the CSV is <name>.csv
  std::vector<std::string> columns;  // columns[0] is the key
  Eigen::MatrixXd values;            // one row per entry

  std::optional<int> column_index(const std::string& column) const;
  // Row whose key equals `key`, or -1.
  int row_of_key(long key) const;
};

using ResultTables = std::map<std::string, ResultTable>;

}  // namespace bb
