// bladebench.shooting_sweep: the exact periodic response of a user's reduced model with friction
// contacts, by shooting on the piecewise-linear flow (timeint/shooting.hpp), from Python.
#pragma once
#include <pybind11/pybind11.h>

namespace bb::python {

void define_shooting(pybind11::module_& m);

}  // namespace bb::python
