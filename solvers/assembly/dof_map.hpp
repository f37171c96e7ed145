// Numbering of nodal DOFs into free equations and constrained values.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "model/model.hpp"

namespace bb {

struct DofMap {
  int dim = 2;
  int n_free = 0;
  std::vector<int> equation;          // per global DOF (node * dim + dir): free index, or -1
  std::vector<int> free_dofs;         // global DOF of each free equation
  std::vector<int> constrained_dofs;  // global DOFs with a prescribed value
  Eigen::VectorXd prescribed;         // value of each constrained DOF, in constrained_dofs order

  int n_global() const { return static_cast<int>(equation.size()); }
};

// The free equations' entries of a vector over every nodal DOF.
Eigen::VectorXd free_part(const DofMap& dofs, const Eigen::VectorXd& global);
// A vector over every nodal DOF from the free equations' values: the constrained ones take their
// prescribed values, or zero (an increment, a shape) when `with_prescribed` is false.
Eigen::VectorXd to_global(const DofMap& dofs, const Eigen::VectorXd& free, bool with_prescribed);
// The free equations' values laid out over the mesh, one row per node (n_nodes x dim), constrained
// DOFs zero: a mode shape, an increment, a harmonic of a response.
Eigen::MatrixXd nodal_rows(const DofMap& dofs, const Eigen::VectorXd& free);

// Throws InputError when a constraint names an unknown set.
DofMap number_dofs(const Model& model);

// "node 17 uy" for messages.
std::string describe_dof(const Mesh& mesh, int global_dof);

}  // namespace bb
