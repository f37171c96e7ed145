#include "results/table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bb {

std::optional<int> ResultTable::column_index(const std::string& column) const {
  auto it = std::find(columns.begin(), columns.end(), column);
  if (it == columns.end()) return std::nullopt;
  return static_cast<int>(it - columns.begin());
}

void ResultTable::add_text_column(const std::string& column, std::vector<std::string> column_values) {
  if (static_cast<Eigen::Index>(column_values.size()) != values.rows())
    throw std::invalid_argument("text column '" + column + "' has " + std::to_string(column_values.size()) +
                                " values for " + std::to_string(values.rows()) + " rows");
  text_columns.push_back(column);
  text.push_back(std::move(column_values));
}

int ResultTable::row_of_key(long key) const {
  for (Eigen::Index r = 0; r < values.rows(); ++r)
    if (std::lround(values(r, 0)) == key) return static_cast<int>(r);
  return -1;
}

ResultTable table_from_rows(const std::string& name, std::vector<std::string> columns,
                            const std::vector<std::vector<double>>& rows) {
  ResultTable t;
  t.name = name;
  t.columns = std::move(columns);
  t.values.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(t.columns.size()));
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].size() != t.columns.size())
      throw std::invalid_argument(name + ": a row has " + std::to_string(rows[i].size()) + " values for " +
                                  std::to_string(t.columns.size()) + " columns");
    for (size_t j = 0; j < rows[i].size(); ++j)
      t.values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = rows[i][j];
  }
  return t;
}

}  // namespace bb
