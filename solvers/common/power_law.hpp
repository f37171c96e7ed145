// The error left in a converging sequence of results (harmonics, samples, refinement), estimated
// from the differences between its successive levels.
#pragma once
#include <array>

namespace bb {

// The error of level x1 when the error falls as a power law e = C x^-p of the level (harmonics,
// samples, refinement; 1 / tolerance), fitted through the differences d_before = e(x0) - e(x1) and
// d = e(x1) - e(x2) of three successive levels x0 < x1 < x2: C x1^-p. Infinite when the
// differences do not decrease as any such law allows (no convergence seen), d itself when the
// convergence is faster than x^-30.
double power_law_error(const std::array<double, 3>& x, double d_before, double d);

}  // namespace bb
