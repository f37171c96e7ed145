#include "calibrate_binding.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "pipeline/calibrate_case.hpp"
#include "table_arrays.hpp"

namespace py = pybind11;

namespace bb::python {
namespace {

constexpr const char* kCalibrateDoc =
    R"(Identifies the case's [calibration] parameters by weighted nonlinear least squares (Ceres), as
`bladebench calibrate CASE` does, and returns what its report shows, as Python objects.

Arguments:
  case_file     a case file with a [calibration] section (cases/README.md, "Calibration").
  settings      'dotted.key=VALUE' strings replacing the case file's values before the fit (the
                start), as `bladebench calibrate --set`.
  restart_from  the calibrated.toml or restart.toml of an earlier fit: its values are the start.
  max_work      the bound on every model evaluation's estimated operations (default 1e12, as
                --max-work); a case above it is refused before it runs.

Returns a dict:
  parameters          the dotted paths fitted, in order
  values, std_devs    identified values and their 1-sigma (float64, the parameters' units; std_devs
                      scaled by the reduced chi-square when it exceeds 1; NaN when unavailable)
  covariance          std_devs x correlation x std_devs (parameters x parameters; NaN if unavailable)
  correlation         the correlation matrix (empty when the covariance could not be computed)
  reduced_chi_square  2 cost / (residuals - parameters) at the optimum
  converged, termination, warnings
  starts              one dict per start: start, values, initial_cost, final_cost, iterations,
                      converged, evaluated
  initial_cost, final_cost, evaluations
  points              a Table of the fitted points: set, label, quantity, x, measured,
                      computed_before, computed_after, sigma, held_out (1: predicted, not fitted)
  curves, curves_before  the result tables the measured curves are fitted to, at the identified and
                      the start values (dict of Table: the predicted curves)
  cross_check         the cross-check case's tables at the identified values (with band columns
                      when [calibration] asks for them), {} without a cross-check
  calibrated_case     the case file's text with the identified values

Raises InputError (a malformed case, [calibration] or data file: the command line's message, with
file:line:key) and SolverError (a model that cannot be solved at the start).)";

py::array_t<double> vector_of(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

py::object points_table(const CalibrationOutcome& o) {
  ResultTable t;
  t.name = "points";
  t.columns = {"point", "x", "measured", "computed_before", "computed_after", "sigma", "held_out"};
  const auto n = static_cast<Eigen::Index>(o.after.size());
  t.values.resize(n, static_cast<Eigen::Index>(t.columns.size()));
  std::vector<std::string> set, label, quantity;
  for (Eigen::Index i = 0; i < n; ++i) {
    const FitPoint& a = o.after[static_cast<size_t>(i)];
    const double before = static_cast<size_t>(i) < o.before.size() ? o.before[static_cast<size_t>(i)].computed : NAN;
    t.values.row(i) << static_cast<double>(i + 1), a.x, a.measured, before, a.computed, a.sigma, a.held_out ? 1.0 : 0.0;
    set.push_back(a.set);
    label.push_back(a.label);
    quantity.push_back(a.quantity);
  }
  t.add_text_column("set", set);
  t.add_text_column("label", label);
  t.add_text_column("quantity", quantity);
  return table_array(t);
}

py::dict calibrate(const std::string& case_file, const std::vector<std::string>& settings,
                   const std::optional<std::string>& restart_from, const std::optional<double>& max_work) {
  WorkLimits limits;
  if (max_work) {
    if (!(*max_work > 0) || !std::isfinite(*max_work)) throw InputError("max_work: must be a positive finite number");
    limits.operations = *max_work;
  }
  CalibrationStartEdits edits;
  edits.settings = settings;
  if (restart_from) edits.restart_from = *restart_from;
  const CalibrationOutcome o = calibrate_case(case_file, {}, limits, nullptr, edits);
  py::dict out;
  std::vector<std::string> paths;
  for (const CalibrationParameter& p : o.spec.parameters) paths.push_back(p.path);
  const auto n = static_cast<Eigen::Index>(paths.size());
  out["parameters"] = paths;
  out["values"] = vector_of(o.values);
  out["std_devs"] = vector_of(o.std_devs);
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Constant(n, n, NAN);
  if (o.correlation.rows() == n && static_cast<Eigen::Index>(o.std_devs.size()) == n)
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        covariance(i, j) =
            o.std_devs[static_cast<size_t>(i)] * o.correlation(i, j) * o.std_devs[static_cast<size_t>(j)];
  out["covariance"] = covariance;
  out["correlation"] = o.correlation;
  out["reduced_chi_square"] = o.reduced_chi_square;
  out["converged"] = o.converged;
  out["termination"] = o.termination;
  out["warnings"] = o.warnings;
  py::list starts;
  for (const CalibrationStart& s : o.starts) {
    py::dict d;
    d["start"] = vector_of(s.start);
    d["values"] = vector_of(s.values);
    d["initial_cost"] = s.initial_cost;
    d["final_cost"] = s.final_cost;
    d["iterations"] = s.iterations;
    d["converged"] = s.converged;
    d["evaluated"] = s.evaluated;
    starts.append(d);
  }
  out["starts"] = starts;
  out["initial_cost"] = o.initial_cost;
  out["final_cost"] = o.final_cost;
  out["evaluations"] = o.residual_evaluations;
  out["points"] = points_table(o);
  out["curves"] = table_arrays(o.curves_after);
  out["curves_before"] = table_arrays(o.curves_before);
  out["cross_check"] = table_arrays(o.cross_check_tables);
  std::ostringstream text;
  text << o.calibrated << '\n';
  out["calibrated_case"] = text.str();
  return out;
}

}  // namespace

void define_calibrate(py::module_& m) {
  m.def("calibrate", &calibrate, py::arg("case_file"), py::arg("settings") = std::vector<std::string>{},
        py::arg("restart_from") = std::nullopt, py::arg("max_work") = std::nullopt, kCalibrateDoc);
}

}  // namespace bb::python
