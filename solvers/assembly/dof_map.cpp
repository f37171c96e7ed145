#include "assembly/dof_map.hpp"

#include <fmt/format.h>

#include <map>

#include "common/errors.hpp"

namespace bb {

Eigen::VectorXd free_part(const DofMap& dofs, const Eigen::VectorXd& global) {
  Eigen::VectorXd out(dofs.n_free);
  for (int i = 0; i < dofs.n_free; ++i) out[i] = global[dofs.free_dofs[static_cast<size_t>(i)]];
  return out;
}

Eigen::VectorXd to_global(const DofMap& dofs, const Eigen::VectorXd& free, bool with_prescribed) {
  Eigen::VectorXd all = Eigen::VectorXd::Zero(dofs.n_global());
  for (int i = 0; i < dofs.n_free; ++i) all[dofs.free_dofs[static_cast<size_t>(i)]] = free[i];
  if (with_prescribed)
    for (size_t c = 0; c < dofs.constrained_dofs.size(); ++c)
      all[dofs.constrained_dofs[c]] = dofs.prescribed[static_cast<Eigen::Index>(c)];
  return all;
}

Eigen::MatrixXd nodal_rows(const DofMap& dofs, const Eigen::VectorXd& free) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(dofs.n_global() / dofs.dim, dofs.dim);
  for (int i = 0; i < dofs.n_free; ++i) {
    const int global = dofs.free_dofs[static_cast<size_t>(i)];
    out(global / dofs.dim, global % dofs.dim) = free[i];
  }
  return out;
}

DofMap number_dofs(const Model& model) {
  DofMap map;
  map.dim = model.mesh.dim;
  const int n = model.mesh.n_nodes() * map.dim;
  std::vector<char> fixed(n, 0);
  std::map<int, double> values;
  for (const Constraint& c : model.constraints) {
    auto set = model.node_sets.find(c.set);
    if (set == model.node_sets.end()) throw InputError(fmt::format("constraint on unknown node set '{}'", c.set));
    for (int node : set->second) {
      for (Direction d : c.directions) {
        const int g = node * map.dim + d;
        fixed[g] = 1;
        values[g] = c.value;  // a later constraint on the same DOF wins
      }
    }
  }
  map.equation.assign(n, -1);
  for (int g = 0; g < n; ++g) {
    if (fixed[g]) {
      map.constrained_dofs.push_back(g);
    } else {
      map.equation[g] = map.n_free++;
      map.free_dofs.push_back(g);
    }
  }
  map.prescribed.resize(static_cast<Eigen::Index>(map.constrained_dofs.size()));
  for (size_t i = 0; i < map.constrained_dofs.size(); ++i)
    map.prescribed[static_cast<Eigen::Index>(i)] = values[map.constrained_dofs[i]];
  return map;
}

std::string describe_dof(const Mesh& mesh, int global_dof) {
  static constexpr const char* names[] = {"ux", "uy", "uz"};
  const int node = global_dof / mesh.dim;
  return fmt::format("node {} {}", mesh.node_ids[node], names[global_dof % mesh.dim]);
}

}  // namespace bb
