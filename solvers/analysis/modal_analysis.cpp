#include "analysis/modal_analysis.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"

namespace bb {

ModalResult solve_modal(const Model& model, const ModalOptions& options) {
  const Mesh& mesh = model.mesh;
  auto t0 = std::chrono::steady_clock::now();
  const DofMap dofs = number_dofs(model);
  const GlobalMatrices global = assemble(mesh, model.section);
  const Partitioned k = partition(global.stiffness, dofs);
  const Partitioned m = partition(global.mass, dofs);
  if (options.n_modes >= dofs.n_free)
    throw InputError(fmt::format("'analysis.modes': asked for {} modes of a model with only {} free DOFs",
                                 options.n_modes, dofs.n_free));
  ModalResult result;
  result.n_free_dofs = dofs.n_free;
  auto t1 = std::chrono::steady_clock::now();
  result.assembly_seconds = std::chrono::duration<double>(t1 - t0).count();
  const ModalSolution sol = lowest_modes(k.ff, m.ff, options);
  result.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  result.iterations = sol.iterations;
  result.max_residual = sol.max_residual;
  result.frequencies_hz = sol.eigenvalues.array().max(0.0).sqrt() / (2 * std::numbers::pi);
  for (Eigen::Index k_mode = 0; k_mode < sol.shapes.cols(); ++k_mode) {
    Eigen::MatrixXd shape = Eigen::MatrixXd::Zero(mesh.n_nodes(), mesh.dim);
    for (int i = 0; i < dofs.n_free; ++i) shape(dofs.free_dofs[i] / mesh.dim, dofs.free_dofs[i] % mesh.dim) = sol.shapes(i, k_mode);
    result.shapes.push_back(std::move(shape));
  }
  return result;
}

ResultTable frequency_table(const Eigen::VectorXd& frequencies_hz) {
  ResultTable t;
  t.name = "frequencies";
  t.columns = {"mode", "frequency_hz"};
  t.values.resize(frequencies_hz.size(), 2);
  for (Eigen::Index i = 0; i < frequencies_hz.size(); ++i) {
    t.values(i, 0) = static_cast<double>(i + 1);
    t.values(i, 1) = frequencies_hz[i];
  }
  return t;
}

}  // namespace bb
