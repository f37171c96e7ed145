// Geometric check of 20-node hexahedra shared by the mesh-generator and Gmsh-import tests.
#pragma once
#include <gtest/gtest.h>

#include <array>

#include "mesh/mesh.hpp"

namespace bb::test {

// Every hex20 mid-edge node (9-20, Ansys/CalculiX order of mesh/mesh.hpp) lies at the midpoint of
// its two corners, as it must for straight edges.
inline ::testing::AssertionResult hex20_mid_edge_nodes_at_midpoints(const Mesh& mesh) {
  static constexpr std::array<std::array<int, 2>, 12> kEdges = {{
      {0, 1},
      {1, 2},
      {2, 3},
      {3, 0},
      {4, 5},
      {5, 6},
      {6, 7},
      {7, 4},
      {0, 4},
      {1, 5},
      {2, 6},
      {3, 7},
  }};
  for (const ElementBlock& b : mesh.blocks) {
    if (b.type != ElementType::hex20) continue;
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (size_t k = 0; k < kEdges.size(); ++k) {
        const Eigen::Vector3d mid =
            0.5 * (mesh.coords.row(b.conn(e, kEdges[k][0])) + mesh.coords.row(b.conn(e, kEdges[k][1]))).transpose();
        const Eigen::Vector3d at = mesh.coords.row(b.conn(e, 8 + static_cast<Eigen::Index>(k))).transpose();
        if ((at - mid).norm() > 1e-12)
          return ::testing::AssertionFailure() << "element " << b.ids[static_cast<size_t>(e)] << " node " << 9 + k
                                               << " lies " << (at - mid).norm() << " m off the midpoint of its edge";
      }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace bb::test
