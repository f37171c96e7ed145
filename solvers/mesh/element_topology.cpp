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

constexpr ElementTopology kQ4{"q4", 2, 4, 4, kQuadEdges, {}};
constexpr ElementTopology kCst{"cst", 2, 3, 3, kTriangleEdges, {}};
constexpr ElementTopology kHex8{"hex8", 3, 8, 8, kHexEdges, kHexFaces};
constexpr ElementTopology kHex8i{"hex8i", 3, 8, 8, kHexEdges, kHexFaces};
constexpr ElementTopology kHex20{"hex20", 3, 20, 8, kHexEdges, kHexFaces};

}  // namespace

const ElementTopology& topology(ElementType type) {
  switch (type) {
    case ElementType::q4: return kQ4;
    case ElementType::cst: return kCst;
    case ElementType::hex8: return kHex8;
    case ElementType::hex8i: return kHex8i;
    case ElementType::hex20: return kHex20;
  }
  return kQ4;  // unreachable: every enumerator is handled above (-Wswitch)
}

}  // namespace bb
