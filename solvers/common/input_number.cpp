#include "common/input_number.hpp"

#include <fmt/format.h>

#include <cmath>

namespace bb {

std::string number_problem(double v) {
  if (!std::isfinite(v)) return "must be finite";
  const double a = std::abs(v);
  if (a > 1e100) return fmt::format("{:g} is out of range: no input in SI units exceeds 1e100 in magnitude", v);
  if (a != 0.0 && a < 1e-100)
    return fmt::format("{:g} is out of range: a non-zero magnitude below 1e-100 (write 0, or a value in SI units)", v);
  return {};
}

}  // namespace bb
