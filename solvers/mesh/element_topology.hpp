// The topology of each element type in one table: dimension, node count, its edges and (solids) its
// faces in local node numbers, node order as in mesh/mesh.hpp (Ansys/CalculiX). Plots, loads on
// edges and faces, and mesh checks read it here instead of walking the connectivity themselves.
#pragma once
#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"

namespace bb {

struct ElementTopology {
  std::string_view name;
  int dimension = 2;
  int nodes = 0;
  int corners = 0;  // the vertex nodes (the first `corners` in the numbering)
  // Edges by their two corner nodes; a quadratic element's mid-edge node of edge k is node corners + k.
  std::span<const std::array<int, 2>> edges;
  // Solids: faces by their four corner nodes, counterclockwise seen from outside (outward normal).
  std::span<const std::array<int, 4>> faces;
};

const ElementTopology& topology(ElementType type);

// The facets of an element (2D: its edges, 3D: its faces) and their local nodes: the corners in the
// order of `edges` / `faces` (a face counterclockwise seen from outside), then for a quadratic element
// the mid-edge nodes of the facet's edges in the same order (a-b, b-c, c-d, d-a): hex20 faces are
// 8-node serendipity quadrilaterals.
int facet_count(ElementType type);
std::vector<int> facet_nodes(ElementType type, int facet);

}  // namespace bb
