#include "assembly/assemble.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "assembly/element_traits.hpp"
#include "assembly/sparsity.hpp"
#include "common/errors.hpp"
#include "mesh/element_coords.hpp"
#include "mesh/element_topology.hpp"

namespace bb {
namespace {

template <class E>
void assemble_block(const Mesh& mesh, const ElementBlock& block, const ElementMaterials& materials,
                    const NodalPattern& pattern, GlobalMatrices& g, const AssemblyOptions& options) {
  for (Eigen::Index e = 0; e < block.conn.rows(); ++e) {
    const int* nodes = block.conn.row(e).data();
    const auto xyz = element_coords<E::nodes, E::dim>(mesh, nodes);
    try {
      if (options.stiffness) pattern.add(g.stiffness, nodes, E::nodes, E::stiffness(xyz, materials));
      if (options.mass) pattern.add(g.mass, nodes, E::nodes, E::mass(xyz, materials));
    } catch (const std::domain_error& err) {
      throw InputError(fmt::format("element {} ({}): {}", block.ids[e], element_name(block.type), err.what()));
    }
  }
}

}  // namespace

GlobalMatrices assemble(const Mesh& mesh, const fe::PlaneSection& section, const AssemblyOptions& options) {
  for (const auto& b : mesh.blocks)
    if (element_dimension(b.type) != mesh.dim)
      throw InputError(fmt::format("{} elements in a {}D mesh", element_name(b.type), mesh.dim));
  const NodalPattern pattern(mesh);
  GlobalMatrices g;
  if (options.stiffness) g.stiffness = pattern.zero_matrix();
  if (options.mass) g.mass = pattern.zero_matrix();
  const fe::SolidMaterial solid{section.youngs_modulus, section.poisson_ratio, section.density};
  const ElementMaterials materials{section, solid};
  for (const auto& b : mesh.blocks)
    with_element(b.type, [&]<class E>(E) { assemble_block<E>(mesh, b, materials, pattern, g, options); });
  // The mass pattern carries the stiffness's direction coupling, which mass never has.
  if (options.mass) g.mass.prune(0.0);
  return g;
}

Partitioned partition(const SparseMatrix& a, const DofMap& dofs) {
  // Equation numbers grow with the global DOF, so slicing columns keeps rows sorted.
  const int n_con = static_cast<int>(dofs.constrained_dofs.size());
  auto slice = [&](const std::vector<int>& columns, int n_cols) {
    SparseMatrix out(dofs.n_free, n_cols);
    long nnz = 0;
    for (int col : columns)
      for (SparseMatrix::InnerIterator it(a, col); it; ++it) nnz += dofs.equation[it.row()] >= 0 ? 1 : 0;
    out.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    long pos = 0;
    int j = 0;
    for (int col : columns) {
      out.outerIndexPtr()[j++] = static_cast<int>(pos);
      for (SparseMatrix::InnerIterator it(a, col); it; ++it) {
        const int row = dofs.equation[it.row()];
        if (row < 0) continue;
        out.innerIndexPtr()[pos] = row;
        out.valuePtr()[pos++] = it.value();
      }
    }
    out.outerIndexPtr()[j] = static_cast<int>(pos);
    return out;
  };
  Partitioned p;
  p.ff = slice(dofs.free_dofs, dofs.n_free);
  p.fc = slice(dofs.constrained_dofs, n_con);
  return p;
}

}  // namespace bb
