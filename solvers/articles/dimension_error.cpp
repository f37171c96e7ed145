#include "articles/dimension_error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace bb {

void require_positive_size(const char* name, double value) {
  if (!(value > 0) || !std::isfinite(value))
    throw DimensionError(name, fmt::format("{} must be a positive finite size, found {}", name, value));
}

}  // namespace bb
