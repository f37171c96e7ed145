// The boundary of a mesh: the facets (2D element edges, 3D element faces) that belong to one element
// only. Distributed loads act on them and plots draw them (the skin of a solid).
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "mesh/mesh.hpp"

namespace bb {

struct Facet {
  int block = 0;             // index into mesh.blocks
  Eigen::Index element = 0;  // row of the block's connectivity
  int local = 0;             // facet number in the element (mesh/element_topology.hpp)
  std::vector<int> nodes;    // internal node indices, in the order of facet_nodes()
};

// Facets are matched by their corner nodes, so two elements glued at coincident nodes share theirs
// (an interior facet); the outward normal of a boundary facet is that of its one element.
std::vector<Facet> boundary_facets(const Mesh& mesh);

// The boundary facets whose nodes (mid-edge nodes included) all lie in `nodes` (internal indices).
std::vector<Facet> boundary_facets_within(const Mesh& mesh, const std::vector<int>& nodes);

}  // namespace bb
