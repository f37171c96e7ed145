// bladebench.calibrate: a case's [calibration] from Python, the fit's every output as NumPy arrays.
#pragma once
#include <pybind11/pybind11.h>

namespace bb::python {

void define_calibrate(pybind11::module_& m);

}  // namespace bb::python
