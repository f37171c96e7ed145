#include "results/table.hpp"

#include <algorithm>
#include <cmath>

namespace bb {

std::optional<int> ResultTable::column_index(const std::string& column) const {
  auto it = std::find(columns.begin(), columns.end(), column);
  if (it == columns.end()) return std::nullopt;
  return static_cast<int>(it - columns.begin());
}

int ResultTable::row_of_key(long key) const {
  for (Eigen::Index r = 0; r < values.rows(); ++r)
    if (std::lround(values(r, 0)) == key) return static_cast<int>(r);
  return -1;
}

}  // namespace bb
