#include "mesh/element_topology.hpp"

namespace bb {
namespace {

constexpr std::array<std::array<int, 2>, 3> kTriangleEdges = {{{0, 1}, {1, 2}, {2, 0}}};
constexpr std::array<std::array<int, 2>, 4> kQuadEdges = {{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
// hex20's mid-edge nodes 9-20 lie on these edges in this order (mesh/mesh.hpp).
constexpr std::array<std::array<int, 2>, 12> kHexEdges = {
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
constexpr std::array<std::array<int, 4>, 6> kHexFaces = {
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

// Gmsh numbers hex20's mid-edge nodes by its own edge order ((0-1, 0-3, 0-4, 1-2, 1-5, 2-3, 2-6,
// 3-7, 4-5, 4-7, 5-6, 6-7), reference manual, "Node ordering"); ours goes round the bottom face, the
// top face, then up the vertical edges (mesh/mesh.hpp).
constexpr std::array<int, 20> kGmshHex20 = {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15};

// name, dimension, nodes, corners, edges, faces, Gmsh type and order, CalculiX name, row nonzeros, VTK type.
constexpr ElementTopology kQ4{"q4", 2, 4, 4, kQuadEdges, {}, 3, {}, "CPS4", 18.0, 9};
constexpr ElementTopology kCst{"cst", 2, 3, 3, kTriangleEdges, {}, 2, {}, "CPS3", 14.0, 5};
constexpr ElementTopology kHex8{"hex8", 3, 8, 8, kHexEdges, kHexFaces, 5, {}, "C3D8", 81.0, 12};
constexpr ElementTopology kHex8i{"hex8i", 3, 8, 8, kHexEdges, kHexFaces, 5, {}, "C3D8I", 81.0, 12};  // ccx's own bubbles
constexpr ElementTopology kHex20{"hex20",   3,  20,         8,       kHexEdges,
                                 kHexFaces, 17, kGmshHex20, "C3D20", 180.0, 25};  // 3x3x3 Gauss

constexpr std::array<ElementType, 5> kTypes = {ElementType::q4, ElementType::cst, ElementType::hex8, ElementType::hex8i,
                                               ElementType::hex20};

}  // namespace

const ElementTopology& topology(ElementType type) {
  switch (type) {
    case ElementType::q4:
      return kQ4;
    case ElementType::cst:
      return kCst;
    case ElementType::hex8:
      return kHex8;
    case ElementType::hex8i:
      return kHex8i;
    case ElementType::hex20:
      return kHex20;
  }
  return kQ4;  // unreachable: every enumerator is handled above (-Wswitch)
}

std::span<const ElementType> element_types() { return kTypes; }

std::optional<ElementType> element_type_named(std::string_view name) {
  for (ElementType t : kTypes)
    if (topology(t).name == name) return t;
  return std::nullopt;
}

int facet_count(ElementType type) {
  const ElementTopology& t = topology(type);
  return static_cast<int>(t.dimension == 2 ? t.edges.size() : t.faces.size());
}

std::vector<int> facet_nodes(ElementType type, int facet) {
  const ElementTopology& t = topology(type);
  const auto f = static_cast<size_t>(facet);
  if (t.dimension == 2) return {t.edges[f][0], t.edges[f][1]};  // the plane elements are linear
  const auto& c = t.faces[f];
  std::vector<int> nodes(c.begin(), c.end());
  if (t.nodes > t.corners)
    for (size_t i = 0; i < 4; ++i) {
      const int a = c[i], b = c[(i + 1) % 4];
      for (size_t k = 0; k < t.edges.size(); ++k)
        if ((t.edges[k][0] == a && t.edges[k][1] == b) || (t.edges[k][0] == b && t.edges[k][1] == a))
          nodes.push_back(t.corners + static_cast<int>(k));
    }
  return nodes;
}

}  // namespace bb
