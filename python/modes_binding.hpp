// bladebench.nonlinear_modes (a user's reduced model with friction contacts, by the extended periodic
// motion concept) and bladebench.cyclic_modes (a case's bladed disk, per nodal diameter).
#pragma once
#include <pybind11/pybind11.h>

namespace bb::python {

void define_modes(pybind11::module_& m);

}  // namespace bb::python
