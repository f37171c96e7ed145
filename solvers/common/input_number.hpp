// The one rule for every number read from user input (case files, measured data, meshes): finite,
// and of a magnitude some quantity in SI units can have.
#pragma once
#include <string>

namespace bb {

// Why `v` cannot be an input ("" when it can): not finite, or a magnitude above 1e100, or below
// 1e-100 but not zero (subnormals included: their reciprocals and squares overflow).
std::string number_problem(double v);

}  // namespace bb
