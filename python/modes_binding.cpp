#include "modes_binding.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/cyclic_modal_analysis.hpp"
#include "analysis/run_analysis.hpp"
#include "assembly/dof_map.hpp"
#include "cases/case_settings.hpp"
#include "cases/case_spec.hpp"
#include "common/errors.hpp"
#include "friction_arrays.hpp"
#include "hbm/nonlinear_modes.hpp"
#include "model/build_model.hpp"

namespace py = pybind11;

namespace bb::python {
namespace {

constexpr const char* kNonlinearModesDoc =
    R"(The nonlinear mode of a reduced model of yours with friction contacts, by the extended periodic
motion concept (Krack 2015): along the modal amplitude a, the free motion made periodic by a
negative mass-proportional damping gives the frequency, the modal damping ratio and the shape. The
branch starts from stuck linear mode `mode` (1-based, K with every contact stuck, M).

  mass, stiffness, damping, contacts   as hbm_sweep (no force: the motion is free)
  amplitudes     modal amplitudes a [m kg^1/2], positive and increasing (e.g. np.geomspace)
  mode, harmonics, tolerance           the linear mode, H, Newton's scaled tolerance

Returns {"modal_amplitude", "frequency_hz", "damping_ratio" (per converged point), "coefficients"
(points x n x 2H+1), "converged" (every amplitude reached), "failure", "skipped" (amplitudes the
branch went past without a solution)}. Raises InputError as hbm_sweep does.)";

constexpr const char* kCyclicModesDoc =
    R"(The modes of a case's bladed disk by cyclic symmetry (its [analysis] type = "cyclic_modal"), per
nodal diameter, with each family's sector shape as standing waves.

  case_file, settings  as run_case

Returns {"sectors", "node_ids" (the sector's), "diameters": [{"nodal_diameter", "frequency_hz",
"cosine", "sine" (families x nodes x dim: the standing waves over the sector's nodes; sector j of the
disk moves as R^j (c cos(k j 2 pi / N) - s sin(k j 2 pi / N)), the sine zero for k = 0 and N/2)}]}.
Raises InputError for a case that is not a cyclic modal analysis.)";

py::dict nonlinear_modes(const py::handle& mass, const py::handle& stiffness, const py::handle& damping,
                         const py::list& contacts, const py::handle& amplitudes, int mode, int harmonics,
                         double tolerance) {
  if (harmonics < 1 || harmonics > 100) throw InputError("harmonics: must lie in [1, 100]");
  if (!(tolerance > 0.0 && tolerance < 1e-2)) throw InputError("tolerance: must lie in (0, 1e-2)");
  const py::ssize_t n =
      py::reinterpret_borrow<py::array>(mass).ndim() == 2 ? py::reinterpret_borrow<py::array>(mass).shape(0) : 0;
  py::array_t<std::complex<double>> no_force(n);
  std::fill(no_force.mutable_data(), no_force.mutable_data() + n, std::complex<double>(0.0, 0.0));
  const friction::FrictionModel model =
      friction_model_of(mass, stiffness, damping, no_force, contacts, "nonlinear_modes");
  const std::vector<double> a = frequencies_of(amplitudes);  // positive and finite, as frequencies are
  hbm::NonlinearModeOptions options;
  options.harmonics = harmonics;
  options.tolerance = tolerance;
  hbm::NonlinearModeBranch branch;
  try {
    branch = hbm::trace_nonlinear_mode(model, mode, a, Eigen::VectorXd(), options);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  const auto points = static_cast<py::ssize_t>(branch.points.size());
  py::array_t<double> amplitude(points), hz(points), zeta(points),
      coefficients({points, static_cast<py::ssize_t>(model.mass.rows()), static_cast<py::ssize_t>(2 * harmonics + 1)});
  auto q = coefficients.mutable_unchecked<3>();
  for (py::ssize_t i = 0; i < points; ++i) {
    const hbm::NonlinearModePoint& p = branch.points[static_cast<size_t>(i)];
    amplitude.mutable_at(i) = p.modal_amplitude;
    hz.mutable_at(i) = p.omega / (2.0 * std::numbers::pi);
    zeta.mutable_at(i) = p.damping_ratio();
    for (Eigen::Index d = 0; d < p.coefficients.rows(); ++d)
      for (Eigen::Index c = 0; c < p.coefficients.cols(); ++c) q(i, d, c) = p.coefficients(d, c);
  }
  py::dict out;
  out["modal_amplitude"] = amplitude;
  out["frequency_hz"] = hz;
  out["damping_ratio"] = zeta;
  out["coefficients"] = coefficients;
  out["converged"] = branch.converged;
  out["failure"] = branch.failure;
  out["skipped"] = branch.skipped;
  return out;
}

py::dict cyclic_modes(const std::string& case_file, const std::vector<std::string>& settings) {
  toml::table root = read_case_table(case_file);
  apply_settings(root, settings);
  const CaseSpec spec = parse_case_table(root, case_file);
  if (!std::holds_alternative<CyclicModalSpec>(spec.analysis))
    throw InputError(case_file + ": 'analysis.type': cyclic_modes needs a cyclic_modal analysis");
  const Model model = build_model(spec.model);
  const AnalysisResults results = run_analysis(spec.analysis, model);
  const auto& o = std::get<CyclicModalOutcome>(results.outcome);
  const int dim = model.mesh.dim;
  const auto nodes = static_cast<py::ssize_t>(model.mesh.n_nodes());
  py::list diameters;
  for (const NodalDiameterModes& nd : o.diameters) {
    const auto families = static_cast<py::ssize_t>(nd.frequencies_hz.size());
    py::array_t<double> cosine({families, nodes, static_cast<py::ssize_t>(dim)}),
        sine({families, nodes, static_cast<py::ssize_t>(dim)});
    auto c = cosine.mutable_unchecked<3>();
    auto s = sine.mutable_unchecked<3>();
    for (py::ssize_t f = 0; f < families; ++f) {
      const Eigen::MatrixXd cos_rows = nodal_rows(o.dofs, nd.cosine.col(f));
      const Eigen::MatrixXd sin_rows =
          nd.pairs ? nodal_rows(o.dofs, nd.sine.col(f)) : Eigen::MatrixXd::Zero(nodes, dim);
      for (py::ssize_t node = 0; node < nodes; ++node)
        for (int d = 0; d < dim; ++d) {
          c(f, node, d) = cos_rows(node, d);
          s(f, node, d) = sin_rows(node, d);
        }
    }
    py::dict entry;
    entry["nodal_diameter"] = nd.nodal_diameter;
    entry["frequency_hz"] = nd.frequencies_hz;
    entry["cosine"] = cosine;
    entry["sine"] = sine;
    diameters.append(entry);
  }
  py::dict out;
  out["sectors"] = o.sectors;
  out["node_ids"] = model.mesh.node_ids;
  out["diameters"] = diameters;
  return out;
}

}  // namespace

void define_modes(py::module_& m) {
  m.def("nonlinear_modes", &nonlinear_modes, py::arg("mass"), py::arg("stiffness"), py::arg("damping"),
        py::arg("contacts"), py::arg("amplitudes"), py::arg("mode") = 1, py::arg("harmonics") = 1,
        py::arg("tolerance") = 1e-9, kNonlinearModesDoc);
  m.def("cyclic_modes", &cyclic_modes, py::arg("case_file"), py::arg("settings") = std::vector<std::string>{},
        kCyclicModesDoc);
}

}  // namespace bb::python
