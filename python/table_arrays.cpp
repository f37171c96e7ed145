#include "table_arrays.hpp"

#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;

namespace bb::python {
namespace {

constexpr const char* kTableClass = R"(
import numpy as _numpy

class Table(_numpy.recarray):
    """A bladebench result table: a NumPy record array, one field per CSV column (the key column an
    int64, the numbers float64 in SI units, the label columns str), rows in the CSV's order.
    table["frequency_hz"] is a column, table[0] a row, table.dtype.names the columns."""

    def to_pandas(self):
        """The table as a pandas.DataFrame (needs pandas: Debian's python3-pandas)."""
        import pandas
        return pandas.DataFrame.from_records(_numpy.asarray(self).view(_numpy.ndarray))
)";

}  // namespace

void define_table_class(py::module_& m) {
  py::dict scope;
  py::exec(kTableClass, scope);
  m.attr("Table") = scope["Table"];
  m.attr("Table").attr("__module__") = "bladebench";
}

py::object table_array(const ResultTable& t) {
  const py::module_ np = py::module_::import("numpy");
  const auto rows = static_cast<py::ssize_t>(t.values.rows());
  py::list arrays, names;
  for (Eigen::Index c = 0; c < t.values.cols(); ++c) {
    names.append(t.columns[static_cast<size_t>(c)]);
    if (c == 0) {
      py::array_t<long long> key(rows);
      auto k = key.mutable_unchecked<1>();
      for (py::ssize_t r = 0; r < rows; ++r) k(r) = std::llround(t.values(r, 0));
      arrays.append(key);
    } else {
      py::array_t<double> column(rows);
      auto v = column.mutable_unchecked<1>();
      for (py::ssize_t r = 0; r < rows; ++r) v(r) = t.values(r, c);
      arrays.append(column);
    }
  }
  for (size_t c = 0; c < t.text_columns.size(); ++c) {
    names.append(t.text_columns[c]);
    arrays.append(np.attr("array")(py::cast(t.text[c]), py::arg("dtype") = "U"));
  }
  const py::object records = np.attr("rec").attr("fromarrays")(arrays, py::arg("names") = names);
  return records.attr("view")(py::module_::import("bladebench").attr("Table"));
}

py::dict table_arrays(const ResultTables& tables) {
  py::dict out;
  for (const auto& [name, t] : tables) out[py::str(name)] = table_array(t);
  return out;
}

}  // namespace bb::python
