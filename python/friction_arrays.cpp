#include "friction_arrays.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/input_number.hpp"
#include "friction/coulomb_law.hpp"
#include "friction/coupled_slip.hpp"
#include "friction/iwan_law.hpp"
#include "reduction/reduced_model.hpp"

namespace py = pybind11;

namespace bb::python {
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

}  // namespace

friction::FrictionModel friction_model_of(const py::handle& mass, const py::handle& stiffness,
                                          const py::handle& damping, const py::handle& force, const py::list& contacts,
                                          const std::string& caller) {
  const py::ssize_t n = checked_array<double>(mass, "mass", {-1, -1}, "float64").shape(0);  // the model's DOFs
  if (n < 1) throw bb::InputError("mass: the model needs at least one DOF");
  friction::FrictionModel model;
  model.mass = square_matrix(mass, "mass", n);
  model.stiffness = square_matrix(stiffness, "stiffness", n);
  model.damping = square_matrix(damping, "damping", n);
  // What the case reader requires of a model written in a case (cases/parse_hbm.cpp), in its words.
  ReducedModel rom;
  rom.mass = model.mass;
  rom.stiffness = model.stiffness;
  for (int i = 1; i <= n; ++i) rom.dofs.push_back({.label = "", .direction = -1, .mode = i});
  validate_reduced_model(rom, caller);
  if (const std::string problem = damping_matrix_problem(model.damping); !problem.empty())
    throw InputError("damping: " + problem);
  const auto f = checked_array<std::complex<double>>(force, "force", {n}, "complex128").unchecked<1>();
  model.harmonic_load.resize(n);
  for (py::ssize_t i = 0; i < n; ++i) model.harmonic_load[i] = f(i);
  if (contacts.empty()) throw InputError("contacts: needs at least one contact");
  for (size_t k = 0; k < contacts.size(); ++k)
    for (friction::ContactElement& e : contacts_of(contacts[k], k, n)) model.contacts.push_back(std::move(e));
  return model;
}

std::vector<double> frequencies_of(const py::handle& frequencies_hz) {
  const auto hz = checked_array<double>(frequencies_hz, "frequencies_hz", {-1}, "float64").unchecked<1>();
  std::vector<double> out;
  for (py::ssize_t i = 0; i < hz.shape(0); ++i) {
    if (!(hz(i) > 0.0) || !std::isfinite(hz(i))) throw InputError("frequencies_hz: every frequency must be > 0");
    out.push_back(hz(i));
  }
  return out;
}

}  // namespace bb::python
