// The bladebench Python module: a case's result tables as NumPy record arrays, its calibration, a
// harmonic-balance sweep of a user's reduced model with every friction law (matrices in, curves out),
// reduced models read from exports, and the lowest modes of a case's mesh with their completeness
// count. Errors are Python exceptions of the command line's
// classes: InputError (exit class 2: bad input, with file:line:key, or an array of the wrong shape
// or dtype, with the shape expected) and SolverError (exit class 3: a solver that did not converge).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/run_analysis.hpp"
#include "assembly/free_system.hpp"
#include "calibrate_binding.hpp"
#include "cases/case_settings.hpp"
#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "common/input_number.hpp"
#include "friction/coulomb_law.hpp"
#include "friction/coupled_slip.hpp"
#include "friction/iwan_law.hpp"
#include "friction_arrays.hpp"
#include "hbm/harmonic_balance.hpp"
#include "linalg/modal_solver.hpp"
#include "model/build_model.hpp"
#include "modes_binding.hpp"
#include "reduction/reduced_model.hpp"
#include "reduction/reduced_model_io.hpp"
#include "shooting_binding.hpp"
#include "table_arrays.hpp"

namespace py = pybind11;

namespace {

// {table name: bladebench.Table}, the tables the command line writes as CSV.
py::dict run_case(const std::string& case_file, const std::vector<std::string>& settings) {
  toml::table root = bb::read_case_table(case_file);
  bb::apply_settings(root, settings);
  const bb::CaseSpec spec = bb::parse_case_table(root, case_file);
  return bb::python::table_arrays(bb::run_analysis(spec.analysis, bb::build_model(spec.model)).tables);
}

// The first-harmonic amplitude of every DOF over the frequencies, each frequency solved from the
// one before (natural continuation; a frequency that does not converge is marked and skipped).
py::dict hbm_sweep(const py::handle& mass, const py::handle& stiffness, const py::handle& damping,
                   const py::handle& force, const py::handle& frequencies_hz, const py::list& contacts, int harmonics,
                   double tolerance) {
  if (harmonics < 1 || harmonics > 100) throw bb::InputError("harmonics: must lie in [1, 100]");
  if (!(tolerance > 0.0 && tolerance < 1e-2)) throw bb::InputError("tolerance: must lie in (0, 1e-2)");
  const bb::friction::FrictionModel model =
      bb::python::friction_model_of(mass, stiffness, damping, force, contacts, "hbm_sweep");
  const auto n = static_cast<py::ssize_t>(model.mass.rows());
  const std::vector<double> hz = bb::python::frequencies_of(frequencies_hz);
  std::optional<bb::hbm::HarmonicBalance> system;
  try {
    system.emplace(model, bb::hbm::HbmOptions{.harmonics = harmonics, .tolerance = tolerance});
  } catch (const std::invalid_argument& e) {
    throw bb::InputError(e.what());
  }
  const auto count = static_cast<py::ssize_t>(hz.size()), coefficients = static_cast<py::ssize_t>(2 * harmonics + 1);
  py::array_t<double> amplitude({count, n}), coefficients_out({count, n, coefficients});
  py::array_t<bool> converged(count);
  auto a = amplitude.mutable_unchecked<2>();
  auto q = coefficients_out.mutable_unchecked<3>();
  auto ok = converged.mutable_unchecked<1>();
  std::vector<std::string> failures;
  std::optional<Eigen::VectorXd> previous;
  for (py::ssize_t i = 0; i < count; ++i) {
    const double omega = 2.0 * std::numbers::pi * hz[static_cast<size_t>(i)];
    const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(*system, omega, previous);
    ok(i) = s.converged;
    if (!s.converged) {
      failures.push_back(s.failure);
      for (py::ssize_t d = 0; d < n; ++d) {
        a(i, d) = NAN;
        for (py::ssize_t c = 0; c < coefficients; ++c) q(i, d, c) = NAN;
      }
      continue;
    }
    previous = s.x;
    const Eigen::MatrixXd all = system->recover(s.x, omega);  // rows: DOFs; columns: c0, a1, b1, ...
    for (py::ssize_t d = 0; d < n; ++d) {
      a(i, d) = std::hypot(all(d, 1), all(d, 2));
      for (py::ssize_t c = 0; c < coefficients; ++c) q(i, d, c) = all(d, c);
    }
  }
  py::dict out;
  out["frequency_hz"] = py::array_t<double>(count, hz.data());
  out["amplitude"] = amplitude;
  out["coefficients"] = coefficients_out;
  out["converged"] = converged;
  out["failures"] = failures;
  return out;
}

// The lowest modes of the case's mesh (its [material], [mesh], boundary conditions), with the
// completeness count: the eigenvalues below the last one counted by the inertia of K - sigma M.
py::dict mesh_modes(const std::string& case_file, int count) {
  if (count < 1 || count > 10000) throw bb::InputError("count: must lie in [1, 10000]");
  const bb::CaseSpec spec = bb::parse_case_file(case_file);
  if (spec.model.mesh.kind == bb::MeshSpec::Kind::none)
    throw bb::InputError(case_file + ": the case has no mesh (a [mesh] section)");
  const bb::FreeSystem system = bb::assemble_free_system(bb::build_model(spec.model));
  bb::ModalOptions options;
  options.n_modes = count;
  const bb::ModalSolution modes = bb::lowest_modes(system.stiffness, system.mass, options);
  const Eigen::VectorXd hz = modes.eigenvalues.cwiseMax(0.0).cwiseSqrt() / (2.0 * std::numbers::pi);
  py::dict out;
  out["frequency_hz"] = hz;
  out["shapes"] = modes.shapes;
  out["sturm_count"] = modes.sturm_count;
  out["complete"] = modes.sturm_count == static_cast<int>(modes.eigenvalues.size());
  return out;
}

// A reduced model on disk (a sidecar naming Matrix Market, CSV or Harwell-Boeing files and the DOFs).
py::dict read_reduced_model(const std::string& sidecar) {
  const bb::ReducedModel model = bb::read_reduced_model(sidecar);
  std::vector<std::string> dofs;
  for (const bb::ReducedDof& d : model.dofs) dofs.push_back(d.name());
  py::dict out;
  out["stiffness"] = model.stiffness;
  out["mass"] = model.mass;
  out["dofs"] = dofs;
  return out;
}

}  // namespace

PYBIND11_MODULE(bladebench, m) {
  m.doc() =
      "bladebench: harmonic balance with friction contacts, modes and validation cases (README.md, section Python)";
  auto input_error = py::register_exception<bb::InputError>(m, "InputError", PyExc_ValueError);
  auto solver_error = py::register_exception<bb::SolverError>(m, "SolverError", PyExc_RuntimeError);
  input_error.attr("exit_code") = 2;  // the command line's exit code for the same failure
  solver_error.attr("exit_code") = 3;
  bb::python::define_table_class(m);
  m.def("run_case", &run_case, py::arg("case_file"), py::arg("settings") = std::vector<std::string>{},
        R"(Runs a case file's analysis (its model and analysis; no checks, no report) and returns its result
tables, the ones `bladebench run` writes as CSV, as {name: bladebench.Table}: NumPy record arrays,
one field per column (the key int64, numbers float64 in SI units, labels str), with to_pandas().

  settings  'dotted.key=VALUE' strings replacing the case file's values, as `bladebench run --set`.

Raises InputError (exit class 2: a malformed case, with file:line:key) and SolverError (exit class
3: a solver that did not converge).)");
  bb::python::define_calibrate(m);
  bb::python::define_shooting(m);
  bb::python::define_modes(m);
  m.def("read_reduced_model", &read_reduced_model, py::arg("sidecar"),
        R"(Reads a reduced model as the cases do (cases/README.md, "Reduced models on disk"): a TOML sidecar
naming the stiffness and mass files (Matrix Market, CSV, or Harwell-Boeing as Ansys HBMAT writes
them) and the DOFs (a list, or a DOF map: Ansys's .mapping or a CSV node,direction). Returns
{"stiffness", "mass": n x n float64 [N/m, kg], "dofs": ["101.x", ...]}: matrices for hbm_sweep.
Raises InputError naming the file and line of anything malformed (a header that disagrees with its
data, a matrix that is not symmetric, a DOF map of the wrong length).)");
  m.def("hbm_sweep", &hbm_sweep, py::arg("mass"), py::arg("stiffness"), py::arg("damping"), py::arg("force"),
        py::arg("frequencies_hz"), py::arg("contacts"), py::arg("harmonics") = 1, py::arg("tolerance") = 1e-9,
        R"(Harmonic-balance frequency sweep of a reduced model of yours with friction contacts, each frequency
solved from the one before (natural continuation). Every law of the case files: "jenkins" (default:
a spring kt in series with a Coulomb slider), "coulomb" (regularised by kt in the frequency domain,
as in the cases), "iwan" (Segalman's four-parameter joint as "sliders" parallel Jenkins sliders,
exponent "chi" in (-1, 0], macro-slip weight "beta"), "coupled_slip" (the 2D contact: one slider in
the plane of "tangential" and "tangential_2", a circular limit |T| <= mu N); the normal load is
n0 + kn a_n.q, with lift-off when it reaches 0.

  mass, stiffness, damping  n x n float64 [kg, N/m, N s/m]: symmetric, M positive definite (the case
                            reader's rules: read_reduced_model gives them from an export)
  force                     n complex128: the first harmonic of the force [N], F e^{i w t}
  frequencies_hz            float64 [Hz], each > 0
  contacts                  a list of dicts: "tangential" (n float64: the relative tangential
                            displacement a_t.q), "kt" [N/m], "mu", "n0" [N], and optionally "normal"
                            (n float64), "kn" [N/m], "law" and its keys ("chi", "beta", "sliders";
                            "tangential_2")
  harmonics                 H in [1, 100]: harmonics 0..H of the response
  tolerance                 the Newton loop's relative residual, in (0, 1e-2)

Returns {"frequency_hz", "amplitude" (frequencies x n: |harmonic 1|), "coefficients" (frequencies x
n x 2H+1: c0, a1, b1, ...), "converged" (bool per frequency), "failures" (why each that did not)}.
A frequency that does not converge is NaN and named in failures, never silently wrong. Raises
InputError for an array of the wrong dtype or shape (the shape expected named), a number out of
range, a matrix that is not symmetric.)");
  m.def("mesh_modes", &mesh_modes, py::arg("case_file"), py::arg("count") = 6,
        R"(The lowest `count` modes (1..10000) of a case's mesh with its material and boundary conditions
(the case's [analysis] is not run), by Lanczos with the Sturm (inertia) count of K - sigma M.
Returns {"frequency_hz" (count), "shapes" (free DOFs x count, mass-normalized), "sturm_count" (the
eigenvalues below the last one's shift), "complete" (no mode missed)}. Raises InputError for a case
without a mesh or a malformed one.)");
}
