#include "cache/cbor_matrix.hpp"

#include <cstring>
#include <stdexcept>

namespace bb {

nlohmann::json matrix_to_json(const Eigen::MatrixXd& m) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(m.data());
  return {{"rows", m.rows()},
          {"cols", m.cols()},
          {"data", nlohmann::json::binary(std::vector<std::uint8_t>(bytes, bytes + m.size() * sizeof(double)))}};
}

Eigen::MatrixXd matrix_from_json(const nlohmann::json& j) {
  const auto rows = j.at("rows").get<Eigen::Index>(), cols = j.at("cols").get<Eigen::Index>();
  const auto& data = j.at("data").get_binary();
  if (rows < 0 || cols < 0 || data.size() != static_cast<size_t>(rows * cols) * sizeof(double))
    throw std::runtime_error("a matrix's size does not match its data");
  Eigen::MatrixXd m(rows, cols);
  if (!data.empty()) std::memcpy(m.data(), data.data(), data.size());
  return m;
}

}  // namespace bb
