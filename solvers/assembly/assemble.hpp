// Global sparse stiffness and consistent mass from element formulas (fe/).
#pragma once
#include <Eigen/Sparse>

#include "assembly/dof_map.hpp"
#include "assembly/load_vector.hpp"
#include "model/model.hpp"

namespace bb {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct GlobalMatrices {
  SparseMatrix stiffness;  // all nodal DOFs, global order node * dim + dir
  SparseMatrix mass;
};

struct AssemblyOptions {
  bool stiffness = true;
  bool mass = true;
};

// Throws InputError naming the element when its geometry is invalid (inverted, degenerate).
GlobalMatrices assemble(const Mesh& mesh, const fe::PlaneSection& section, const AssemblyOptions& options = {});

// Rows and columns of `a` restricted to the free DOFs (ff) and free x constrained (fc).
struct Partitioned {
  SparseMatrix ff;
  SparseMatrix fc;
};
Partitioned partition(const SparseMatrix& a, const DofMap& dofs);

}  // namespace bb
