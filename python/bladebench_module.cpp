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
#include "hbm/harmonic_balance.hpp"
#include "linalg/modal_solver.hpp"
#include "model/build_model.hpp"
#include "reduction/reduced_model.hpp"
#include "reduction/reduced_model_io.hpp"
#include "table_arrays.hpp"

namespace py = pybind11;

namespace {

// "(3, 3)", "(n,)" for an expected shape (-1: any extent).
std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string out = "(";
  for (size_t i = 0; i < shape.size(); ++i)
    out += (i ? ", " : "") + (shape[i] < 0 ? std::string("any") : std::to_string(shape[i]));
  return out + (shape.size() == 1 ? ",)" : ")");
}

// The array `value` if it has the dtype T and the shape `expected`; else InputError naming the
// argument, the expected dtype and shape and what came. No silent conversion: a float32 or an
// integer array is refused, so that no precision or unit is lost on the way in.
template <class T>
py::array_t<T> checked_array(const py::handle& value, const std::string& name, const std::vector<py::ssize_t>& expected,
                             const std::string& dtype) {
  if (!py::isinstance<py::array>(value))
    throw bb::InputError(name + ": expected a NumPy array of dtype " + dtype + " and shape " + shape_text(expected) +
                         ", got " + std::string(py::str(py::type::of(value).attr("__name__"))));
  const auto a = py::reinterpret_borrow<py::array>(value);
  std::vector<py::ssize_t> got(a.shape(), a.shape() + a.ndim());
  bool fits = got.size() == expected.size();
  for (size_t i = 0; fits && i < got.size(); ++i) fits = expected[i] < 0 || got[i] == expected[i];
  if (!a.dtype().is(py::dtype::of<T>()) || !fits)
    throw bb::InputError(name + ": expected dtype " + dtype + " and shape " + shape_text(expected) + ", got dtype " +
                         std::string(py::str(a.dtype())) + " and shape " + shape_text(got));
  return py::reinterpret_borrow<py::array_t<T>>(a);
}

Eigen::MatrixXd square_matrix(const py::handle& value, const std::string& name, py::ssize_t n) {
  const auto a = checked_array<double>(value, name, {n, n}, "float64").template unchecked<2>();
  Eigen::MatrixXd m(n, n);
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t j = 0; j < n; ++j) m(i, j) = a(i, j);
  if (!m.allFinite()) throw bb::InputError(name + ": every entry must be finite");
  return m;
}

Eigen::RowVectorXd dof_row(const py::handle& value, const std::string& name, py::ssize_t n) {
  const auto a = checked_array<double>(value, name, {n}, "float64").template unchecked<1>();
  Eigen::RowVectorXd r(n);
  for (py::ssize_t i = 0; i < n; ++i) r[i] = a(i);
  if (!r.allFinite()) throw bb::InputError(name + ": every entry must be finite");
  return r;
}

double law_number(const py::dict& contact, const char* key, const std::string& where, double fallback, bool required) {
  if (!contact.contains(key)) {
    if (required) throw bb::InputError(where + ": needs '" + key + "'");
    return fallback;
  }
  // The case reader's rule and words for a number (common/input_number.hpp), not pybind11's cast error.
  const py::handle value = contact[key];
  double v = 0.0;
  try {
    v = py::cast<double>(value);
  } catch (const py::cast_error&) {
    throw bb::InputError(where + ": '" + key + "': expected a number, found " +
                         std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  if (const std::string problem = bb::number_problem(v); !problem.empty())
    throw bb::InputError(where + ": '" + key + "': " + problem);
  return v;
}

// One contact point from {"tangential": a_t, "normal": a_n (optional), "kn", "kt", "mu", "n0",
// "law": "jenkins" | "coulomb" | "iwan" (with "chi", "beta", "sliders") | "coupled_slip" (with
// "tangential_2")}: the contacts it is in the friction model (an Iwan joint is its parallel sliders).
std::vector<bb::friction::ContactElement> contacts_of(const py::handle& item, size_t index, py::ssize_t n) {
  const std::string where = "contacts[" + std::to_string(index) + "]";
  if (!py::isinstance<py::dict>(item))
    throw bb::InputError(
        where + ": expected a dict with 'tangential', 'kt', 'mu', 'n0' (and optionally 'normal', 'kn', 'law')");
  const auto c = py::reinterpret_borrow<py::dict>(item);
  static const std::vector<std::string> keys = {"tangential", "normal", "tangential_2", "kn",   "kt",     "mu",
                                                "n0",         "law",    "chi",          "beta", "sliders"};
  for (const auto& [key, _] : c) {
    const std::string k = py::str(key);
    if (std::find(keys.begin(), keys.end(), k) == keys.end())
      throw bb::InputError(where + ": unknown key '" + k +
                           "' (tangential, normal, tangential_2, kn, kt, mu, n0, law, chi, beta, sliders)");
  }
  if (!c.contains("tangential")) throw bb::InputError(where + ": needs 'tangential', one weight per DOF");
  const std::string law = c.contains("law") ? std::string(py::str(c["law"])) : "jenkins";
  if (law != "jenkins" && law != "coulomb" && law != "iwan" && law != "coupled_slip")
    throw bb::InputError(where + ": 'law': '" + law + "' is not one of jenkins, coulomb, iwan, coupled_slip");
  if (c.contains("tangential_2") != (law == "coupled_slip"))
    throw bb::InputError(where +
                         ": 'tangential_2' (the second tangential direction) goes with law 'coupled_slip', "
                         "and that law needs it");
  for (const char* key : {"chi", "beta", "sliders"})
    if (c.contains(key) && law != "iwan") throw bb::InputError(where + ": '" + key + "' belongs to law 'iwan'");
  bb::friction::ContactElement e;
  e.tangential = dof_row(c["tangential"], where + ".tangential", n);
  e.normal = c.contains("normal") ? dof_row(c["normal"], where + ".normal", n) : Eigen::RowVectorXd::Zero(n);
  e.point = {.kn = law_number(c, "kn", where, 0.0, false),
             .kt = law_number(c, "kt", where, 0.0, true),
             .mu = law_number(c, "mu", where, 0.0, true),
             .n0 = law_number(c, "n0", where, 0.0, true)};
  if (law == "coulomb") e.law = bb::friction::coulomb_law();
  if (law == "coupled_slip") {
    e.tangential_2 = dof_row(c["tangential_2"], where + ".tangential_2", n);
    e.law = bb::friction::coupled_slip_law();
  }
  if (law != "iwan") return {e};
  bb::friction::IwanParameters p;
  p.chi = law_number(c, "chi", where, p.chi, false);
  p.beta = law_number(c, "beta", where, p.beta, false);
  const double slider_count = law_number(c, "sliders", where, p.sliders, false);
  if (slider_count != std::floor(slider_count) || slider_count < 1 || slider_count > 10000)
    throw bb::InputError(where + ": 'sliders': an integer in [1, 10000]");
  p.sliders = static_cast<int>(slider_count);
  std::vector<bb::friction::ContactElement> sliders;
  try {
    const bb::friction::IwanDistribution distribution(p);
    if (!(e.point.mu * e.point.n0 > 0.0))
      throw std::invalid_argument("an Iwan element needs a positive slip force mu n0");
    for (const bb::friction::PointParameters& slider : bb::friction::parallel_sliders(e.point, &distribution)) {
      sliders.push_back(e);
      sliders.back().point = slider;
    }
  } catch (const std::invalid_argument& error) {
    throw bb::InputError(where + ": " + error.what());
  }
  return sliders;
}

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
  const py::ssize_t n = checked_array<double>(mass, "mass", {-1, -1}, "float64").shape(0);  // the model's DOFs
  if (n < 1) throw bb::InputError("mass: the model needs at least one DOF");
  if (harmonics < 1 || harmonics > 100) throw bb::InputError("harmonics: must lie in [1, 100]");
  if (!(tolerance > 0.0 && tolerance < 1e-2)) throw bb::InputError("tolerance: must lie in (0, 1e-2)");
  bb::friction::FrictionModel model;
  model.mass = square_matrix(mass, "mass", n);
  model.stiffness = square_matrix(stiffness, "stiffness", n);
  model.damping = square_matrix(damping, "damping", n);
  // What the case reader requires of a model written in a case (cases/parse_hbm.cpp), in its words.
  {
    bb::ReducedModel rom;
    rom.mass = model.mass;
    rom.stiffness = model.stiffness;
    for (int i = 1; i <= n; ++i) rom.dofs.push_back({.label = "", .direction = -1, .mode = i});
    bb::validate_reduced_model(rom, "hbm_sweep");
    if (const std::string problem = bb::damping_matrix_problem(model.damping); !problem.empty())
      throw bb::InputError("damping: " + problem);
  }
  {
    const auto f = checked_array<std::complex<double>>(force, "force", {n}, "complex128").unchecked<1>();
    model.harmonic_load.resize(n);
    for (py::ssize_t i = 0; i < n; ++i) model.harmonic_load[i] = f(i);
  }
  if (contacts.empty()) throw bb::InputError("contacts: needs at least one contact");
  for (size_t k = 0; k < contacts.size(); ++k)
    for (bb::friction::ContactElement& e : contacts_of(contacts[k], k, n)) model.contacts.push_back(std::move(e));
  const auto hz = checked_array<double>(frequencies_hz, "frequencies_hz", {-1}, "float64").unchecked<1>();
  for (py::ssize_t i = 0; i < hz.shape(0); ++i)
    if (!(hz(i) > 0.0) || !std::isfinite(hz(i))) throw bb::InputError("frequencies_hz: every frequency must be > 0");
  std::optional<bb::hbm::HarmonicBalance> system;
  try {
    system.emplace(model, bb::hbm::HbmOptions{.harmonics = harmonics, .tolerance = tolerance});
  } catch (const std::invalid_argument& e) {
    throw bb::InputError(e.what());
  }
  const py::ssize_t count = hz.shape(0), coefficients = 2 * harmonics + 1;
  py::array_t<double> amplitude({count, n}), coefficients_out({count, n, coefficients});
  py::array_t<bool> converged(count);
  auto a = amplitude.mutable_unchecked<2>();
  auto q = coefficients_out.mutable_unchecked<3>();
  auto ok = converged.mutable_unchecked<1>();
  std::vector<std::string> failures;
  std::optional<Eigen::VectorXd> previous;
  for (py::ssize_t i = 0; i < count; ++i) {
    const double omega = 2.0 * std::numbers::pi * hz(i);
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
  out["frequency_hz"] = py::array_t<double>(count, &hz(0));
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
