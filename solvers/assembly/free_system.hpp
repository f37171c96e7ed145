// The free system of a model: K and M assembled and restricted to the free DOFs (constraints
// removed), for analyses that need them several times (modes, reductions, responses).
#pragma once
#include <Eigen/Sparse>

#include "assembly/dof_map.hpp"
#include "model/model.hpp"

namespace bb {

struct FreeSystem {
  DofMap dofs;
  Eigen::SparseMatrix<double> stiffness;
  Eigen::SparseMatrix<double> mass;
  double assembly_seconds = 0.0;
};

FreeSystem assemble_free_system(const Model& model);

}  // namespace bb
