// Structured hexahedral blocks and their merging (mesh/hex_block): counts, exact coverage of the
// block volume, positive orientation, hex20 mid-edge nodes, conformity, and merging at coincident
// nodes within a tolerance. Units: m.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "hex20_checks.hpp"
#include "mesh/hex_block.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

using Vec3 = Eigen::Vector3d;

// Faces of a hex by corners; for hex20 also the mid-edge nodes on each face's edges.
constexpr std::array<std::array<int, 4>, 6> kFaceCorners = {{
    {0, 1, 2, 3},
    {4, 5, 6, 7},
    {0, 1, 5, 4},
    {1, 2, 6, 5},
    {2, 3, 7, 6},
    {3, 0, 4, 7},
}};
constexpr std::array<std::array<int, 4>, 6> kFaceMidEdges = {{
    {8, 9, 10, 11},
    {12, 13, 14, 15},
    {8, 17, 12, 16},
    {9, 18, 13, 17},
    {10, 19, 14, 18},
    {11, 16, 15, 19},
}};

HexBlockSpec box(Vec3 origin, Vec3 size, int nx, int ny, int nz, ElementType type = ElementType::hex8) {
  HexBlockSpec spec;
  const double x0 = origin.x(), y0 = origin.y(), z0 = origin.z();
  const double x1 = x0 + size.x(), y1 = y0 + size.y(), z1 = z0 + size.z();
  spec.corners = {Vec3(x0, y0, z0), Vec3(x1, y0, z0), Vec3(x1, y1, z0), Vec3(x0, y1, z0),
                  Vec3(x0, y0, z1), Vec3(x1, y0, z1), Vec3(x1, y1, z1), Vec3(x0, y1, z1)};
  spec.nx = nx;
  spec.ny = ny;
  spec.nz = nz;
  spec.element = type;
  return spec;
}

// A parallelepiped spanned by three oblique edge vectors: the trilinear map is affine, so
// straight-faced elements fill it exactly.
HexBlockSpec parallelepiped(int nx, int ny, int nz, ElementType type, Vec3* a = nullptr, Vec3* b = nullptr,
                            Vec3* c = nullptr) {
  const Vec3 o(0.3, -0.2, 0.1), ea(2.0, 0.3, -0.1), eb(0.4, 1.1, 0.2), ec(-0.3, 0.2, 0.7);
  HexBlockSpec spec = box(Vec3::Zero(), Vec3::Ones(), nx, ny, nz, type);
  spec.corners = {o, o + ea, o + ea + eb, o + eb, o + ec, o + ea + ec, o + ea + eb + ec, o + eb + ec};
  if (a) *a = ea;
  if (b) *b = eb;
  if (c) *c = ec;
  return spec;
}

// A convex block with no parallel faces: a general trilinear map.
HexBlockSpec distorted(int nx, int ny, int nz, ElementType type) {
  HexBlockSpec spec = box(Vec3::Zero(), Vec3::Ones(), nx, ny, nz, type);
  spec.corners = {Vec3(0, 0, 0),       Vec3(3.0, -0.2, 0.1), Vec3(3.4, 1.3, -0.1), Vec3(-0.2, 1.0, 0.2),
                  Vec3(0.1, 0.2, 1.4), Vec3(2.6, 0.1, 1.1),  Vec3(3.1, 1.5, 1.6),  Vec3(0.2, 1.2, 1.2)};
  return spec;
}

Vec3 node(const Mesh& mesh, int n) { return mesh.coords.row(n).transpose(); }

double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

// The six tetrahedra around the corner 1 -> 7 diagonal of a hex in our corner order; for a
// straight-edged, planar-faced hex they tile it, and all have positive volume when it is
// right-handed.
std::array<double, 6> split_volumes(const Mesh& mesh, const ElementBlock& b, Eigen::Index e) {
  std::array<Vec3, 8> x;
  for (int a = 0; a < 8; ++a) x[static_cast<size_t>(a)] = node(mesh, b.conn(e, a));
  constexpr std::array<std::array<int, 2>, 6> ring = {{{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}}};
  std::array<double, 6> v{};
  for (size_t t = 0; t < 6; ++t)
    v[t] = tet_volume(x[0], x[static_cast<size_t>(ring[t][0])], x[static_cast<size_t>(ring[t][1])], x[6]);
  return v;
}

double total_volume(const Mesh& mesh) {
  double total = 0.0;
  for (const ElementBlock& b : mesh.blocks)
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (double v : split_volumes(mesh, b, e)) total += v;
  return total;
}

// Element faces (sorted node sets: 4 corners, plus the 4 mid-edge nodes for hex20) -> uses.
std::map<std::vector<int>, int> face_uses(const Mesh& mesh) {
  std::map<std::vector<int>, int> uses;
  for (const ElementBlock& b : mesh.blocks)
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (size_t f = 0; f < 6; ++f) {
        std::vector<int> face;
        for (int a : kFaceCorners[f]) face.push_back(b.conn(e, a));
        if (b.type == ElementType::hex20)
          for (int a : kFaceMidEdges[f]) face.push_back(b.conn(e, a));
        std::sort(face.begin(), face.end());
        ++uses[face];
      }
  return uses;
}

// Checks every face is used once (boundary) or twice (interior) and returns the boundary count.
int boundary_faces(const Mesh& mesh) {
  int boundary = 0;
  for (const auto& [face, count] : face_uses(mesh)) {
    EXPECT_LE(count, 2) << "a face shared by " << count << " elements";
    if (count == 1) ++boundary;
  }
  return boundary;
}

int hex20_node_count(int nx, int ny, int nz) {
  return (nx + 1) * (ny + 1) * (nz + 1) + nx * (ny + 1) * (nz + 1) + (nx + 1) * ny * (nz + 1) +
         (nx + 1) * (ny + 1) * nz;
}

TEST(HexBlockMesh, NodeAndElementCountsMatchTheDivisions) {
  for (const auto& [nx, ny, nz] : {std::array{1, 1, 1}, std::array{3, 2, 1}, std::array{2, 5, 4}}) {
    for (ElementType type : {ElementType::hex8, ElementType::hex8i}) {
      const Mesh m = generate_hex_block(box(Vec3::Zero(), Vec3(3, 2, 1), nx, ny, nz, type));
      EXPECT_EQ(m.dim, 3);
      EXPECT_EQ(m.n_nodes(), (nx + 1) * (ny + 1) * (nz + 1));
      EXPECT_EQ(m.n_elements(), nx * ny * nz);
      ASSERT_EQ(m.blocks.size(), 1u);
      EXPECT_EQ(m.blocks[0].type, type);
      EXPECT_EQ(m.blocks[0].conn.cols(), 8);
    }
    const Mesh q = generate_hex_block(box(Vec3::Zero(), Vec3(3, 2, 1), nx, ny, nz, ElementType::hex20));
    EXPECT_EQ(q.n_nodes(), hex20_node_count(nx, ny, nz));
    EXPECT_EQ(q.n_elements(), nx * ny * nz);
    ASSERT_EQ(q.blocks.size(), 1u);
    EXPECT_EQ(q.blocks[0].conn.cols(), 20);
  }
}

TEST(HexBlockMesh, IdsAreSequentialFromTheFirstIds) {
  HexBlockSpec spec = box(Vec3::Zero(), Vec3(1, 1, 1), 2, 3, 2, ElementType::hex20);
  spec.first_node_id = 1001;
  spec.first_element_id = 51;
  const Mesh m = generate_hex_block(spec);
  for (int n = 0; n < m.n_nodes(); ++n) EXPECT_EQ(m.node_ids[static_cast<size_t>(n)], 1001 + n);
  EXPECT_EQ(m.index_of(1001), 0);
  EXPECT_EQ(m.index_of(1000), -1);
  const std::vector<long>& ids = m.blocks[0].ids;
  for (size_t e = 0; e < ids.size(); ++e) EXPECT_EQ(ids[e], 51 + static_cast<long>(e));
  // Node 1 sits at corner 1 of the block, the last node at corner 7.
  EXPECT_LE((node(m, 0) - spec.corners[0]).norm(), 1e-14);
  EXPECT_LE((node(m, m.n_nodes() - 1) - spec.corners[6]).norm(), 1e-14);
}

class HexBlockTypes : public ::testing::TestWithParam<ElementType> {};

TEST_P(HexBlockTypes, SplitVolumesSumToTheParallelepipedVolume) {
  Vec3 a, b, c;
  const Mesh m = generate_hex_block(parallelepiped(4, 3, 2, GetParam(), &a, &b, &c));
  const double expected = a.dot(b.cross(c));
  ASSERT_GT(expected, 0.0);
  EXPECT_NEAR(total_volume(m), expected, 1e-12 * expected);
}

TEST_P(HexBlockTypes, EveryHexIsRightHandedEvenInADistortedBlock) {
  for (const HexBlockSpec& spec : {parallelepiped(3, 2, 2, GetParam()), distorted(4, 3, 3, GetParam())}) {
    const Mesh m = generate_hex_block(spec);
    const ElementBlock& b = m.blocks[0];
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (double v : split_volumes(m, b, e)) EXPECT_GT(v, 0.0) << "element " << b.ids[static_cast<size_t>(e)];
  }
}

TEST_P(HexBlockTypes, MeshIsConformingWithEveryInteriorFaceSharedByExactlyTwoElements) {
  const int nx = 4, ny = 3, nz = 2;
  const Mesh m = generate_hex_block(distorted(nx, ny, nz, GetParam()));
  EXPECT_EQ(boundary_faces(m), 2 * (nx * ny + ny * nz + nx * nz));
  // Interior faces: every face used twice accounts for the rest.
  const auto uses = face_uses(m);
  int interior = 0;
  for (const auto& [face, count] : uses) interior += count == 2;
  EXPECT_EQ(interior, (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1));
  // Every node belongs to some element, and no element repeats a node.
  const ElementBlock& b = m.blocks[0];
  std::set<int> used(b.conn.data(), b.conn.data() + b.conn.size());
  EXPECT_EQ(static_cast<int>(used.size()), m.n_nodes());
  for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
    std::set<int> own;
    for (Eigen::Index a = 0; a < b.conn.cols(); ++a) own.insert(b.conn(e, a));
    EXPECT_EQ(static_cast<Eigen::Index>(own.size()), b.conn.cols());
  }
}

INSTANTIATE_TEST_SUITE_P(HexBlock, HexBlockTypes,
                         ::testing::Values(ElementType::hex8, ElementType::hex8i, ElementType::hex20),
                         [](const ::testing::TestParamInfo<ElementType>& param_info) {
                           return std::string(element_name(param_info.param));
                         });

TEST(HexBlockMesh, Hex20MidEdgeNodesSitAtTheMidpointsOfTheirEdges) {
  // The trilinear map is linear along each parameter line, so this holds in a distorted block too.
  for (const HexBlockSpec& spec :
       {parallelepiped(3, 2, 2, ElementType::hex20), distorted(3, 3, 2, ElementType::hex20)}) {
    const Mesh m = generate_hex_block(spec);
    ASSERT_EQ(m.blocks[0].type, ElementType::hex20);
    EXPECT_TRUE(test::hex20_mid_edge_nodes_at_midpoints(m));
  }
}

TEST(HexBlockMesh, NodesLieOnTheTrilinearMapOfTheCorners) {
  const HexBlockSpec spec = distorted(4, 2, 3, ElementType::hex8);
  const Mesh m = generate_hex_block(spec);
  // Node order: x fastest, then y, then z, so the block corners are these nodes.
  const std::array<int, 8> corner_nodes = {0, 4, 14, 10, 45, 49, 59, 55};
  for (size_t a = 0; a < 8; ++a)
    EXPECT_LE((node(m, corner_nodes[a]) - spec.corners[a]).norm(), 1e-14) << "corner " << a + 1;
  // Evenly spaced along the straight block edge 1 -> 2.
  for (int i = 0; i <= 4; ++i)
    EXPECT_LE((node(m, i) - (spec.corners[0] + (spec.corners[1] - spec.corners[0]) * (i / 4.0))).norm(), 1e-14);
}

TEST(HexBlockMesh, InvalidSpecsThrowInvalidArgument) {
  EXPECT_THROW(generate_hex_block(box(Vec3::Zero(), Vec3::Ones(), 0, 1, 1)), std::invalid_argument);
  EXPECT_THROW(generate_hex_block(box(Vec3::Zero(), Vec3::Ones(), 1, 1, -2)), std::invalid_argument);
  EXPECT_THROW(generate_hex_block(box(Vec3::Zero(), Vec3::Ones(), 1, 1, 1, ElementType::q4)), std::invalid_argument);
  // Corners 5-8 below 1-4: every element would be inside-out.
  EXPECT_THROW(generate_hex_block(box(Vec3::Zero(), Vec3(1, 1, -1), 2, 2, 2)), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// merge_meshes

TEST(MergeMeshes, TwoBlocksSharingAFaceBecomeOneConformingMesh) {
  for (ElementType type : {ElementType::hex8, ElementType::hex20}) {
    const Mesh a = generate_hex_block(box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2, type));
    const Mesh b = generate_hex_block(box(Vec3(1, 0, 0), Vec3(1, 1, 1), 2, 2, 2, type));
    const Mesh m = merge_meshes({a, b}, 1e-9);
    // The shared face x = 1 holds 3 x 3 nodes for hex8, 3 x 3 + 2 x 3 + 3 x 2 for hex20.
    const int shared = type == ElementType::hex8 ? 9 : 21;
    EXPECT_EQ(m.n_nodes(), a.n_nodes() + b.n_nodes() - shared) << element_name(type);
    EXPECT_EQ(m.n_elements(), 16);
    ASSERT_EQ(m.blocks.size(), 1u);
    EXPECT_EQ(m.blocks[0].type, type);
    // One 2 x 1 x 1 box of 4 x 2 x 2 elements: the shared face became interior.
    EXPECT_EQ(boundary_faces(m), 2 * (4 * 2 + 2 * 2 + 4 * 2));
    EXPECT_NEAR(total_volume(m), 2.0, 1e-12);
  }
}

TEST(MergeMeshes, NodesFartherApartThanTheToleranceStaySeparate) {
  const Mesh a = generate_hex_block(box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2));
  const double tol = 1e-3;
  // A gap of twice the tolerance: nothing merges.
  const Mesh apart = merge_meshes({a, generate_hex_block(box(Vec3(1 + 2 * tol, 0, 0), Vec3(1, 1, 1), 2, 2, 2))}, tol);
  EXPECT_EQ(apart.n_nodes(), 54);
  EXPECT_EQ(boundary_faces(apart), 2 * 24);
  // A gap of half the tolerance: the faces merge, onto the first block's nodes.
  std::vector<std::vector<int>> origin;
  const Mesh b = generate_hex_block(box(Vec3(1 + 0.5 * tol, 0, 0), Vec3(1, 1, 1), 2, 2, 2));
  const Mesh close = merge_meshes({a, b}, tol, &origin);
  EXPECT_EQ(close.n_nodes(), 45);
  for (int n = 0; n < b.n_nodes(); ++n) {
    if (b.coords(n, 0) > 1.5) continue;
    EXPECT_EQ(close.coords(origin[1][static_cast<size_t>(n)], 0), 1.0);
  }
  // Just outside the tolerance along a diagonal (each coordinate within it, the distance not).
  const Mesh c = generate_hex_block(box(Vec3(1, 0, 0) + Vec3::Constant(0.7 * tol), Vec3(1, 1, 1), 2, 2, 2));
  EXPECT_EQ(merge_meshes({a, c}, tol).n_nodes(), 54);
  // Just inside it, and across hashing-cell boundaries in every direction.
  const Mesh d = generate_hex_block(box(Vec3(1, 0, 0) + Vec3(-0.4, 0.4, -0.4) * tol, Vec3(1, 1, 1), 2, 2, 2));
  EXPECT_EQ(merge_meshes({a, d}, tol).n_nodes(), 45);
}

TEST(MergeMeshes, NodesMatchAcrossHashingCellBoundariesInEveryDirection) {
  // A unit cube against a copy shifted along each axis, both ways, in both merge orders. With a
  // 0.3 m tolerance the coordinates 0 and 1 sit in cells 0 and 3 of a 0.3 m hash; a 0.25 m shift
  // moves them into cells -1, 0, 2 or 4, so a match is found only by searching the neighbours.
  const double tol = 0.3;
  const Mesh a = generate_hex_block(box(Vec3::Zero(), Vec3::Ones(), 1, 1, 1));
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      const Mesh near = generate_hex_block(box(0.25 * sign * Vec3::Unit(axis), Vec3::Ones(), 1, 1, 1));
      const Mesh far = generate_hex_block(box(0.35 * sign * Vec3::Unit(axis), Vec3::Ones(), 1, 1, 1));
      EXPECT_EQ(merge_meshes({a, near}, tol).n_nodes(), 8) << "axis " << axis << " sign " << sign;
      EXPECT_EQ(merge_meshes({near, a}, tol).n_nodes(), 8) << "axis " << axis << " sign " << sign;
      EXPECT_EQ(merge_meshes({a, far}, tol).n_nodes(), 16) << "axis " << axis << " sign " << sign;
    }
}

TEST(MergeMeshes, NodeOriginMapsEveryInputNodeToItsMergedNode) {
  const Mesh a = generate_hex_block(box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 3, 2, ElementType::hex20));
  const Mesh b = generate_hex_block(box(Vec3(0, 0, 1), Vec3(1, 1, 0.5), 2, 3, 1, ElementType::hex20));
  std::vector<std::vector<int>> origin;
  const Mesh m = merge_meshes({a, b}, 1e-9, &origin);
  ASSERT_EQ(origin.size(), 2u);
  const std::array<const Mesh*, 2> parts = {&a, &b};
  for (size_t p = 0; p < 2; ++p) {
    ASSERT_EQ(static_cast<int>(origin[p].size()), parts[p]->n_nodes());
    for (int n = 0; n < parts[p]->n_nodes(); ++n) {
      const int merged = origin[p][static_cast<size_t>(n)];
      ASSERT_GE(merged, 0);
      ASSERT_LT(merged, m.n_nodes());
      EXPECT_LE((node(m, merged) - node(*parts[p], n)).norm(), 1e-12);
    }
  }
  // The first mesh's nodes come first, in order; ids are 1..n.
  for (int n = 0; n < a.n_nodes(); ++n) EXPECT_EQ(origin[0][static_cast<size_t>(n)], n);
  for (int n = 0; n < m.n_nodes(); ++n) EXPECT_EQ(m.node_ids[static_cast<size_t>(n)], n + 1);
  EXPECT_EQ(m.index_of(m.n_nodes()), m.n_nodes() - 1);
  // Every element's nodes map through node_origin.
  const ElementBlock& mb = m.blocks[0];
  const ElementBlock& bb = b.blocks[0];
  for (Eigen::Index e = 0; e < bb.conn.rows(); ++e)
    for (Eigen::Index k = 0; k < 20; ++k)
      EXPECT_EQ(mb.conn(a.blocks[0].conn.rows() + e, k), origin[1][static_cast<size_t>(bb.conn(e, k))]);
}

TEST(MergeMeshes, ThreeBlockLShapeHasTheExpectedNodesFacesAndVolume) {
  const Mesh a = generate_hex_block(box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2));
  const Mesh b = generate_hex_block(box(Vec3(1, 0, 0), Vec3(1, 1, 1), 2, 2, 2));
  const Mesh c = generate_hex_block(box(Vec3(0, 1, 0), Vec3(1, 1, 1), 2, 2, 2));
  const Mesh m = merge_meshes({a, b, c}, 1e-9);
  // b and c each share a 3 x 3 face with a; the edge x = y = 1 they touch along is a's too.
  EXPECT_EQ(m.n_nodes(), 27 + 18 + 18);
  EXPECT_EQ(m.n_elements(), 24);
  EXPECT_NEAR(total_volume(m), 3.0, 1e-12);
  // Surface of the L-shaped prism: 2 x 3 (ends) + 8 x 1 (sides) = 14 m^2 in 0.25 m^2 faces.
  EXPECT_EQ(boundary_faces(m), 56);
  // Element ids are 1..24 in one block.
  ASSERT_EQ(m.blocks.size(), 1u);
  for (size_t e = 0; e < 24; ++e) EXPECT_EQ(m.blocks[0].ids[e], static_cast<long>(e) + 1);
}

TEST(MergeMeshes, ElementsAreGroupedIntoOneBlockPerType) {
  const Mesh a = generate_hex_block(box(Vec3(0, 0, 0), Vec3(1, 1, 1), 1, 1, 1, ElementType::hex20));
  const Mesh b = generate_hex_block(box(Vec3(1, 0, 0), Vec3(1, 1, 1), 2, 1, 1, ElementType::hex8));
  const Mesh c = generate_hex_block(box(Vec3(0, 0, 1), Vec3(1, 1, 1), 1, 1, 1, ElementType::hex20));
  const Mesh m = merge_meshes({a, b, c}, 1e-9);
  ASSERT_EQ(m.blocks.size(), 2u);
  EXPECT_EQ(m.blocks[0].type, ElementType::hex20);
  EXPECT_EQ(m.blocks[0].ids, (std::vector<long>{1, 2}));
  EXPECT_EQ(m.blocks[1].type, ElementType::hex8);
  EXPECT_EQ(m.blocks[1].ids, (std::vector<long>{3, 4}));
  // Corners of the hex20 on x = 1 (4) merge with the hex8 corners; its mid-edge nodes do not.
  EXPECT_EQ(m.n_nodes(), 20 + 12 - 4 + 20 - 8);
}

TEST(MergeMeshes, MismatchedDimensionsOrCollapsingToleranceThrow) {
  const Mesh hex = generate_hex_block(box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2));
  const Mesh quad =
      test::make_mesh({{1, {0, 0}}, {2, {1, 0}}, {3, {1, 1}}, {4, {0, 1}}}, {{ElementType::q4, {{1, 2, 3, 4}}}});
  EXPECT_THROW(merge_meshes({hex, quad}, 1e-9), std::invalid_argument);
  EXPECT_THROW(merge_meshes({}, 1e-9), std::invalid_argument);
  EXPECT_THROW(merge_meshes({hex}, -1.0), std::invalid_argument);
  // Elements are 0.5 m wide: a 0.6 m tolerance would collapse them.
  EXPECT_THROW(merge_meshes({hex}, 0.6), std::invalid_argument);
  // 2D meshes merge too.
  const Mesh right =
      test::make_mesh({{1, {1, 0}}, {2, {2, 0}}, {3, {2, 1}}, {4, {1, 1}}}, {{ElementType::q4, {{1, 2, 3, 4}}}});
  const Mesh plane = merge_meshes({quad, right}, 1e-9);
  EXPECT_EQ(plane.dim, 2);
  EXPECT_EQ(plane.n_nodes(), 6);
}

TEST(MergeMeshes, StackedBlocksMergeLikeOneTallBlock) {
  // Four 12 x 12 x 12 hex20 blocks, 33k nodes: also a smoke test of the hashing at some size.
  std::vector<Mesh> parts;
  for (int k = 0; k < 4; ++k)
    parts.push_back(generate_hex_block(box(Vec3(0, 0, k), Vec3(1, 1, 1), 12, 12, 12, ElementType::hex20)));
  const Mesh m = merge_meshes(parts, 1e-9);
  EXPECT_EQ(m.n_nodes(), hex20_node_count(12, 12, 48));
}

}  // namespace
}  // namespace bb
