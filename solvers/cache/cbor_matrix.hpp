// Dense matrices in a cache entry's CBOR payload: shape and raw doubles (a CBOR byte string), so a
// stored model comes back bit for bit.
#pragma once
#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace bb {

nlohmann::json matrix_to_json(const Eigen::MatrixXd& m);
// Throws std::runtime_error (or a json exception) when the shape and the data disagree.
Eigen::MatrixXd matrix_from_json(const nlohmann::json& j);

}  // namespace bb
