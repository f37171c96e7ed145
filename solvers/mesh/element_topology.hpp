// The data of each element type in one table (its formulas are its row in assembly/element_traits.hpp):
// name, dimension, node count, its edges and (solids) its faces in local node numbers, node order as
// in mesh/mesh.hpp (Ansys/CalculiX); its Gmsh type and node order, its CalculiX name, the work its
// rows cost. Plots, loads on edges and faces, mesh readers and writers, the case parser and the work
// estimate read it here instead of listing the types themselves.
#pragma once
#include <array>
#include <optional>
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
  int gmsh_type = 0;                // elm-type of the MSH format (hex8 and hex8i share 5: a case says which)
  std::span<const int> gmsh_order;  // our node a is Gmsh's gmsh_order[a]; empty = the same order
  std::string_view calculix;        // the deck name (ccx, Abaqus): read by mesh/abaqus_inp, solids exported
  double row_nonzeros = 0.0;        // nonzeros of a stiffness row: the DOFs of the nodes an element shares with one
  int vtk_type = 0;                 // VTK's cell type; our node order is VTK's (hex20: VTK_QUADRATIC_HEXAHEDRON)

  bool quadratic() const { return nodes > corners; }
};

const ElementTopology& topology(ElementType type);

// Every element type, in enumerator order.
std::span<const ElementType> element_types();
// The type of that name ("q4", "hex20", ...), or nullopt.
std::optional<ElementType> element_type_named(std::string_view name);

// The facets of an element (2D: its edges, 3D: its faces) and their local nodes: the corners in the
// order of `edges` / `faces` (a face counterclockwise seen from outside), then for a quadratic element
// the mid-edge nodes of the facet's edges in the same order (a-b, b-c, c-d, d-a): hex20 faces are
// 8-node serendipity quadrilaterals.
int facet_count(ElementType type);
std::vector<int> facet_nodes(ElementType type, int facet);

}  // namespace bb
