#pragma once
// The abscissae of the 2- and 3-point Gauss-Legendre rules on [-1, 1].
namespace bb::fe {

inline constexpr double kG2 = 0.57735026918962576451;  // 1/sqrt(3)
inline constexpr double kG3 = 0.77459666924148337704;  // sqrt(3/5)

}  // namespace bb::fe
