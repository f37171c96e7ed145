#include "analysis/static_analysis.hpp"

#include <fmt/format.h>

#include <chrono>

#include "analysis/stress_tables.hpp"
#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "linalg/spd_factor.hpp"

namespace bb {
StaticSolution solve_static(const Model& model) {
  const Mesh& mesh = model.mesh;
  auto t0 = std::chrono::steady_clock::now();
  const DofMap dofs = number_dofs(model);
  const GlobalMatrices global = assemble(mesh, model.section, {.stiffness = true, .mass = false});
  const Eigen::VectorXd f = load_vector(model);
  const Partitioned k = partition(global.stiffness, dofs);
  StaticSolution sol;
  sol.assembly_seconds = seconds_since(t0);
  sol.n_free_dofs = dofs.n_free;

  Eigen::VectorXd rhs = free_part(dofs, f);
  if (dofs.prescribed.size() > 0) rhs -= k.fc * dofs.prescribed;

  t0 = std::chrono::steady_clock::now();
  SpdFactorization factor(ordering_for_dimension(mesh.dim));
  const FactorStatus status = factor.factorize(k.ff);
  if (!status.ok) {
    const std::string where = status.weakest_column >= 0
                                  ? fmt::format(" at {}", describe_dof(mesh, dofs.free_dofs[status.weakest_column]))
                                  : std::string();
    throw InputError(fmt::format(
        "the model is singular: {}{}; a rigid-body motion or mechanism is not constrained (check the [[bc]] entries)",
        status.message, where));
  }
  const Eigen::VectorXd u_free = factor.solve(rhs);
  sol.solve_seconds = seconds_since(t0);
  sol.pivot_ratio = status.rcond;
  const double rhs_norm = rhs.norm();
  sol.relative_residual = rhs_norm > 0 ? (k.ff * u_free - rhs).norm() / rhs_norm : (k.ff * u_free).norm();
  if (!u_free.allFinite()) throw SolverError("static solve produced non-finite displacements");

  const Eigen::VectorXd u = to_global(dofs, u_free, true);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.n_global());
  if (!dofs.constrained_dofs.empty()) {
    const Eigen::VectorXd ku = global.stiffness * u;
    for (int g : dofs.constrained_dofs) r[g] = ku[g] - f[g];
  }
  sol.displacements = Eigen::Map<const Eigen::MatrixXd>(u.data(), mesh.dim, mesh.n_nodes()).transpose();
  sol.reactions = Eigen::Map<const Eigen::MatrixXd>(r.data(), mesh.dim, mesh.n_nodes()).transpose();
  sol.loads = f;
  return sol;
}

StaticOutcome run_static(const Model& model, const StaticSpec& spec, ResultTables& tables) {
  StaticOutcome o;
  o.solution = solve_static(model);
  o.stresses = recover_stresses(model.mesh, model.section, o.solution.displacements,
                                {.integration_points = spec.integration_point_stresses});
  tables.emplace("nodal_displacements", nodal_displacement_table(model.mesh, o.solution.displacements));
  tables.emplace("nodal_stresses", nodal_stress_table("nodal_stresses", model.mesh, o.stresses));
  tables.emplace("nodal_strains", nodal_strain_table("nodal_strains", model.mesh, o.stresses, model.section));
  if (o.stresses.points)
    tables.emplace("integration_point_stresses",
                   integration_point_stress_table("integration_point_stresses", o.stresses));
  return o;
}

ResultTable nodal_displacement_table(const Mesh& mesh, const Eigen::MatrixXd& displacements) {
  ResultTable t;
  t.name = "nodal_displacements";
  t.columns = {"node", "ux", "uy"};
  if (mesh.dim == 3) t.columns.push_back("uz");
  t.values.resize(mesh.n_nodes(), 1 + mesh.dim);
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    t.values(n, 0) = static_cast<double>(mesh.node_ids[n]);
    t.values.row(n).tail(mesh.dim) = displacements.row(n);
  }
  return t;
}

}  // namespace bb
