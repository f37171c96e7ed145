// NumPy arrays and dicts into a friction model (bladebench.hbm_sweep, shooting_sweep): dtypes and
// shapes checked with the shape expected named, every law of the case files, the case reader's rules.
#pragma once
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "friction/friction_system.hpp"

namespace bb::python {

// M, K, C (n x n float64), the force's first harmonic (n complex128) and the contacts (dicts, see
// hbm_sweep's documentation). Throws InputError with `caller`'s name where the case reader would.
friction::FrictionModel friction_model_of(const pybind11::handle& mass, const pybind11::handle& stiffness,
                                          const pybind11::handle& damping, const pybind11::handle& force,
                                          const pybind11::list& contacts, const std::string& caller);
// A float64 array of frequencies, each > 0 and finite [Hz].
std::vector<double> frequencies_of(const pybind11::handle& frequencies_hz);

}  // namespace bb::python
