#include "shooting_binding.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "friction/coulomb_law.hpp"
#include "friction_arrays.hpp"
#include "timeint/shooting.hpp"

namespace py = pybind11;

namespace bb::python {
namespace {

constexpr const char* kShootingDoc =
    R"(The exact periodic response of a reduced model of yours with friction contacts, by shooting:
Newton's method on the period map of the piecewise-linear flow (every stick, slip and lift-off
transition located), with the monodromy matrix as its Jacobian; no harmonic truncation, no time
step. Each frequency starts from the one before.

  mass, stiffness, damping, force, frequencies_hz, contacts   as hbm_sweep. Laws: "jenkins"
                 (default), "coulomb" (the stick rigid, as Den Hartog's oscillator: kt unused; the
                 contacts' tangential rows independent), "iwan" (its parallel sliders). A law
                 without a piecewise-linear form ("coupled_slip") is refused: use hbm_sweep.
  harmonics      H >= 1: harmonics 0..H of the exact motion (Fourier integrals, not a DFT)
  steps_per_period  sub-intervals that bracket the transitions (>= 2 (H + 1))
  tolerance      Newton's, relative to the largest displacement and rate at the start
  floquet        also the Floquet multipliers and the stability verdict

Returns {"frequency_hz", "amplitude" (frequencies x n), "coefficients" (frequencies x n x 2H+1: c0,
a1, b1, ...), "largest" (max |q| over the period), "transitions", "largest_multiplier" and "stable"
(NaN / False without floquet), "converged", "failures"}. A frequency that does not converge is NaN
and named in failures with its residual. Raises InputError as hbm_sweep does.)";

py::dict shooting_sweep(const py::handle& mass, const py::handle& stiffness, const py::handle& damping,
                        const py::handle& force, const py::handle& frequencies_hz, const py::list& contacts,
                        int harmonics, int steps_per_period, double tolerance, bool floquet) {
  if (harmonics < 1 || harmonics > 100) throw InputError("harmonics: must lie in [1, 100]");
  if (!(tolerance > 0.0 && tolerance < 1e-2)) throw InputError("tolerance: must lie in (0, 1e-2)");
  if (steps_per_period < 2 * (harmonics + 1) || steps_per_period > 100000)
    throw InputError("steps_per_period: must lie in [2 (harmonics + 1), 100000]");
  friction::FrictionModel model = friction_model_of(mass, stiffness, damping, force, contacts, "shooting_sweep");
  const std::vector<double> hz = frequencies_of(frequencies_hz);
  const auto n = static_cast<py::ssize_t>(model.mass.rows());
  timeint::ShootingOptions options;
  for (py::ssize_t d = 0; d < n; ++d) options.dofs.push_back(d);
  options.harmonics = harmonics;
  options.steps_per_period = steps_per_period;
  options.tolerance = tolerance;
  options.floquet = floquet;
  size_t rigid = 0;
  for (const friction::ContactElement& e : model.contacts) {
    if (e.law == friction::coulomb_law()) ++rigid;
    if (!e.law->piecewise_linear())
      throw InputError("contacts: law '" + e.law->name() +
                       "' has no piecewise-linear form for the exact flow; use hbm_sweep for it");
  }
  if (rigid > 0 && rigid != model.contacts.size())
    throw InputError("contacts: Coulomb's rigid stick holds for every contact of a run or for none");
  options.rigid_stick = rigid > 0;
  try {
    if (options.rigid_stick) timeint::validate_rigid_stick(model);
    timeint::validate_shooting(model, 2.0 * std::numbers::pi * hz.front(), options);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  const auto count = static_cast<py::ssize_t>(hz.size()), coefficients = static_cast<py::ssize_t>(2 * harmonics + 1);
  py::array_t<double> amplitude({count, n}), coefficients_out({count, n, coefficients}), largest({count, n}),
      multiplier(count);
  py::array_t<bool> converged(count), stable(count);
  py::array_t<int> transitions(count);
  auto a = amplitude.mutable_unchecked<2>();
  auto q = coefficients_out.mutable_unchecked<3>();
  auto big = largest.mutable_unchecked<2>();
  auto mult = multiplier.mutable_unchecked<1>();
  auto ok = converged.mutable_unchecked<1>();
  auto steady = stable.mutable_unchecked<1>();
  auto events = transitions.mutable_unchecked<1>();
  std::vector<std::string> failures;
  std::optional<timeint::FlowState> start;
  for (py::ssize_t i = 0; i < count; ++i) {
    const double omega = 2.0 * std::numbers::pi * hz[static_cast<size_t>(i)];
    const timeint::ShootingResult r = timeint::shooting(model, omega, options, start);
    ok(i) = r.steady.converged;
    steady(i) = r.stable;
    mult(i) = floquet ? r.largest_multiplier : NAN;
    events(i) = r.transitions;
    if (!r.steady.converged) {
      failures.push_back(r.steady.failure);
      for (py::ssize_t d = 0; d < n; ++d) {
        a(i, d) = big(i, d) = NAN;
        for (py::ssize_t c = 0; c < coefficients; ++c) q(i, d, c) = NAN;
      }
      continue;
    }
    start = r.start;
    for (py::ssize_t d = 0; d < n; ++d) {
      a(i, d) = r.steady.amplitude(d, 1);
      big(i, d) = r.largest[d];
      for (py::ssize_t c = 0; c < coefficients; ++c) q(i, d, c) = r.steady.coefficients(d, c);
    }
  }
  py::dict out;
  out["frequency_hz"] = py::array_t<double>(count, hz.data());
  out["amplitude"] = amplitude;
  out["coefficients"] = coefficients_out;
  out["largest"] = largest;
  out["transitions"] = transitions;
  out["largest_multiplier"] = multiplier;
  out["stable"] = stable;
  out["converged"] = converged;
  out["failures"] = failures;
  return out;
}

}  // namespace

void define_shooting(py::module_& m) {
  m.def("shooting_sweep", &shooting_sweep, py::arg("mass"), py::arg("stiffness"), py::arg("damping"), py::arg("force"),
        py::arg("frequencies_hz"), py::arg("contacts"), py::arg("harmonics") = 1, py::arg("steps_per_period") = 128,
        py::arg("tolerance") = 1e-9, py::arg("floquet") = false, kShootingDoc);
}

}  // namespace bb::python
