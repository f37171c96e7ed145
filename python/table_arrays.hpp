// Result tables as NumPy record arrays (bladebench.Table: a numpy.recarray with to_pandas()).
#pragma once
#include <pybind11/pybind11.h>

#include "results/table.hpp"

namespace bb::python {

// Defines bladebench.Table in `m` (once, at import).
void define_table_class(pybind11::module_& m);

// One field per column: the key an int64, the numbers float64, the text columns str.
pybind11::object table_array(const ResultTable& table);
pybind11::dict table_arrays(const ResultTables& tables);

}  // namespace bb::python
