// Gmsh MSH 4.1 import (mesh/gmsh_import) against the committed fixtures in tests/data/gmsh:
// counts, volume, orientation, physical groups as node sets, the hex20 node reordering, and
// malformed files naming their file and line. Units: m.
#include "mesh/gmsh_import.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "hex20_checks.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

using Vec3 = Eigen::Vector3d;

std::filesystem::path fixture(const std::string& name) {
  return std::filesystem::path(BB_SOURCE_DIR) / "tests" / "data" / "gmsh" / name;
}

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

Vec3 node(const Mesh& mesh, int n) { return mesh.coords.row(n).transpose(); }

// Volumes of the six tetrahedra around the corner 1 -> 7 diagonal (straight-edged hexes).
std::array<double, 6> split_volumes(const Mesh& mesh, const ElementBlock& b, Eigen::Index e) {
  std::array<Vec3, 8> x;
  for (int a = 0; a < 8; ++a) x[static_cast<size_t>(a)] = node(mesh, b.conn(e, a));
  constexpr std::array<std::array<int, 2>, 6> ring = {{{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}}};
  std::array<double, 6> v{};
  for (size_t t = 0; t < 6; ++t) {
    const Vec3 p = x[static_cast<size_t>(ring[t][0])] - x[0], q = x[static_cast<size_t>(ring[t][1])] - x[0];
    v[t] = p.dot(q.cross(x[6] - x[0])) / 6.0;
  }
  return v;
}

// Nodes whose coordinate `axis` equals `value`, sorted internal indices.
std::vector<int> nodes_where(const Mesh& mesh, int axis, double value) {
  std::vector<int> out;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (std::abs(mesh.coords(n, axis) - value) < 1e-12) out.push_back(n);
  return out;
}

std::vector<int> all_nodes(const Mesh& mesh) {
  std::vector<int> out(static_cast<size_t>(mesh.n_nodes()));
  for (int n = 0; n < mesh.n_nodes(); ++n) out[static_cast<size_t>(n)] = n;
  return out;
}

const std::vector<int>& group(const GmshMesh& g, const std::string& name) {
  static const std::vector<int> none;
  const auto it = g.node_groups.find(name);
  EXPECT_NE(it, g.node_groups.end()) << "no node group '" << name << "'";
  return it == g.node_groups.end() ? none : it->second;
}

// The message of the InputError reading `name` throws, or "" when it does not throw.
std::string input_error(const std::string& name) {
  try {
    read_gmsh_msh41(fixture(name));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshImport, Hex8BoxHasTheExpectedCountsAndVolumeWithRightHandedElements) {
  // 2 x 1 x 0.5 m, 4 x 2 x 2 hexahedra.
  const GmshMesh g = read_gmsh_msh41(fixture("box_hex8.msh"));
  const Mesh& m = g.mesh;
  EXPECT_EQ(m.dim, 3);
  EXPECT_EQ(m.n_nodes(), 5 * 3 * 3);
  EXPECT_EQ(m.n_elements(), 16);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].type, ElementType::hex8);
  double volume = 0.0;
  for (Eigen::Index e = 0; e < m.blocks[0].conn.rows(); ++e)
    for (double v : split_volumes(m, m.blocks[0], e)) {
      EXPECT_GT(v, 0.0) << "element " << m.blocks[0].ids[static_cast<size_t>(e)];
      volume += v;
    }
  EXPECT_NEAR(volume, 2.0 * 1.0 * 0.5, 1e-12);
  // Node ids are the Gmsh tags: the file numbers them 1..45.
  std::set<long> ids(m.node_ids.begin(), m.node_ids.end());
  EXPECT_EQ(ids.size(), 45u);
  EXPECT_EQ(*ids.begin(), 1);
  EXPECT_EQ(*ids.rbegin(), 45);
  ASSERT_GE(m.index_of(2), 0);
  EXPECT_LE((node(m, m.index_of(2)) - Vec3(2, 0, 0)).norm(), 1e-12);
}

TEST(GmshImport, LinearHexesCanBeReadAsIncompatibleModeHexes) {
  const GmshMesh g = read_gmsh_msh41(fixture("box_hex8.msh"), ElementType::hex8i);
  ASSERT_EQ(g.mesh.blocks.size(), 1u);
  EXPECT_EQ(g.mesh.blocks[0].type, ElementType::hex8i);
  EXPECT_EQ(g.mesh.n_elements(), 16);
}

TEST(GmshImport, PhysicalGroupsGiveTheNodesOfTheirEntities) {
  const GmshMesh g = read_gmsh_msh41(fixture("box_hex8.msh"));
  const Mesh& m = g.mesh;
  EXPECT_EQ(g.node_groups.size(), 4u);
  EXPECT_EQ(group(g, "fixed"), nodes_where(m, 0, 0.0));
  EXPECT_EQ(group(g, "fixed").size(), 9u);
  EXPECT_EQ(group(g, "tip"), nodes_where(m, 0, 2.0));
  EXPECT_EQ(group(g, "body"), all_nodes(m));
  // The unnamed physical curve 7: the z edge at x = y = 0, 3 nodes.
  std::vector<int> edge;
  for (int n : nodes_where(m, 0, 0.0))
    if (m.coords(n, 1) == 0.0) edge.push_back(n);
  EXPECT_EQ(group(g, "physical_7"), edge);
  EXPECT_EQ(edge.size(), 3u);
}

TEST(GmshImport, Hex20BoxHasTheExpectedCountsVolumeAndConformingFaces) {
  // 1.5 x 0.8 x 0.6 m, 3 x 2 x 2 20-node hexahedra.
  const GmshMesh g = read_gmsh_msh41(fixture("box_hex20.msh"));
  const Mesh& m = g.mesh;
  const int nx = 3, ny = 2, nz = 2;
  EXPECT_EQ(m.n_nodes(), (nx + 1) * (ny + 1) * (nz + 1) + nx * (ny + 1) * (nz + 1) + (nx + 1) * ny * (nz + 1) +
                             (nx + 1) * (ny + 1) * nz);
  EXPECT_EQ(m.n_elements(), nx * ny * nz);
  ASSERT_EQ(m.blocks.size(), 1u);
  const ElementBlock& b = m.blocks[0];
  EXPECT_EQ(b.type, ElementType::hex20);
  double volume = 0.0;
  for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
    for (double v : split_volumes(m, b, e)) {
      EXPECT_GT(v, 0.0);
      volume += v;
    }
  EXPECT_NEAR(volume, 1.5 * 0.8 * 0.6, 1e-12);
  // Faces as 8-node sets: the quadratic mesh is conforming only if neighbours share mid-edge nodes
  // in the right places too.
  std::map<std::vector<int>, int> uses;
  for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
    for (size_t f = 0; f < 6; ++f) {
      std::vector<int> face;
      for (int a : kFaceCorners[f]) face.push_back(b.conn(e, a));
      for (int a : kFaceMidEdges[f]) face.push_back(b.conn(e, a));
      std::sort(face.begin(), face.end());
      ++uses[face];
    }
  int boundary = 0, interior = 0;
  for (const auto& [face, count] : uses) {
    EXPECT_LE(count, 2);
    boundary += count == 1;
    interior += count == 2;
  }
  EXPECT_EQ(boundary, 2 * (nx * ny + ny * nz + nx * nz));
  EXPECT_EQ(interior, (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1));
}

TEST(GmshImport, Hex20MidEdgeNodesAreReorderedToTheMidpointsOfTheirCornerPairs) {
  // With Gmsh's own order left in place, node 10 (edge 2-3) would be Gmsh's edge 1-4 node, etc.
  const GmshMesh g = read_gmsh_msh41(fixture("box_hex20.msh"));
  ASSERT_EQ(g.mesh.blocks[0].type, ElementType::hex20);
  EXPECT_TRUE(test::hex20_mid_edge_nodes_at_midpoints(g.mesh));
}

TEST(GmshImport, Hex20PhysicalSurfacesIncludeTheirMidEdgeNodes) {
  const GmshMesh g = read_gmsh_msh41(fixture("box_hex20.msh"));
  const Mesh& m = g.mesh;
  // x = 0 face of 2 x 2 quadratic faces: a 5 x 5 lattice without its 4 face centres.
  EXPECT_EQ(group(g, "fixed"), nodes_where(m, 0, 0.0));
  EXPECT_EQ(group(g, "fixed").size(), 21u);
  // z = 0.6 face of 3 x 2: a 7 x 5 lattice without 6 face centres.
  EXPECT_EQ(group(g, "top"), nodes_where(m, 2, 0.6));
  EXPECT_EQ(group(g, "top").size(), 29u);
  EXPECT_EQ(group(g, "body"), all_nodes(m));
}

TEST(GmshImport, QuadPlateIsATwoDimensionalMesh) {
  // 2 x 0.5 m in z = 0, 4 x 2 quadrilaterals; lines feed only the "clamped" group.
  const GmshMesh g = read_gmsh_msh41(fixture("plate_quad.msh"));
  const Mesh& m = g.mesh;
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.coords.cols(), 2);
  EXPECT_EQ(m.n_nodes(), 15);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].type, ElementType::q4);
  double area = 0.0;
  for (Eigen::Index e = 0; e < m.blocks[0].conn.rows(); ++e) {
    Eigen::MatrixXd xy(4, 2);
    for (Eigen::Index a = 0; a < 4; ++a) xy.row(a) = m.coords.row(m.blocks[0].conn(e, a));
    EXPECT_GT(test::polygon_area(xy), 0.0);
    area += test::polygon_area(xy);
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_EQ(group(g, "clamped"), nodes_where(m, 0, 0.0));
  EXPECT_EQ(group(g, "clamped").size(), 3u);
  EXPECT_EQ(group(g, "plate"), all_nodes(m));
}

TEST(GmshImport, MalformedFilesThrowInputErrorNamingFileAndLine) {
  const std::string v22 = input_error("version22.msh");
  EXPECT_NE(v22.find("version22.msh:2:"), std::string::npos) << v22;
  EXPECT_NE(v22.find("2.2"), std::string::npos) << v22;

  const std::string undefined = input_error("undefined_node.msh");
  EXPECT_NE(undefined.find("undefined_node.msh:27:"), std::string::npos) << undefined;
  EXPECT_NE(undefined.find("node 9"), std::string::npos) << undefined;

  const std::string binary = input_error("binary_flag.msh");
  EXPECT_NE(binary.find("binary_flag.msh:2:"), std::string::npos) << binary;
  EXPECT_NE(binary.find("binary"), std::string::npos) << binary;

  const std::string tet = input_error("tetrahedron.msh");
  EXPECT_NE(tet.find("tetrahedron.msh:21:"), std::string::npos) << tet;
  EXPECT_NE(tet.find("type 4"), std::string::npos) << tet;

  const std::string duplicate = input_error("duplicate_element.msh");
  EXPECT_NE(duplicate.find("duplicate_element.msh:28:"), std::string::npos) << duplicate;

  const std::string missing = input_error("no_such_file.msh");
  EXPECT_NE(missing.find("no_such_file.msh"), std::string::npos) << missing;
}

// Counts are checked against what the rest of the file can hold before anything is reserved for
// them: 4294967295 elements or 1e12 nodes end in a message naming the line, not std::bad_alloc.
TEST(GmshImport, CountsTheFileCannotHoldAreRefusedNamingTheLine) {
  const std::filesystem::path bad_input = std::filesystem::path(BB_SOURCE_DIR) / "tests" / "bad_input" / "data";
  auto message = [&](const std::string& name) {
    try {
      read_gmsh_msh41(bad_input / name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string elements = message("gmsh_huge_element_count.msh");
  EXPECT_NE(elements.find("gmsh_huge_element_count.msh:68: the number of elements in the block is 4294967295"),
            std::string::npos)
      << elements;
  const std::string nodes = message("gmsh_huge_node_count.msh");
  EXPECT_NE(nodes.find("gmsh_huge_node_count.msh:22: the number of nodes is 1000000000000"), std::string::npos)
      << nodes;
}

}  // namespace
}  // namespace bb
