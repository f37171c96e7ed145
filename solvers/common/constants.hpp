#pragma once
// Constants that many files use, defined once: a unity build joins translation units, where two
// file-local copies of one name collide.
#include <limits>
#include <numbers>

namespace bb {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;  // degrees = radians * kDegPerRad
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

}  // namespace bb
