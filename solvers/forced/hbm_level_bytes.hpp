// A swept force level as bytes, for levels swept on other MPI ranks (forced/hbm_levels.hpp):
// every field, numbers bit for bit, so that the levels a rank receives are those it would have swept.
#pragma once
#include <string>

#include "forced/hbm_level.hpp"

namespace bb {

std::string to_bytes(const HbmLevel& level);
// Throws std::runtime_error when the bytes are cut short or run on.
HbmLevel level_from_bytes(const std::string& bytes);

}  // namespace bb
