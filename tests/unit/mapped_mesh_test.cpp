// Structured mapped-quadrilateral meshes (mesh/mapped_quad): counts, the thesis's serpentine node
// numbering, triangle diagonal patterns, orientation, conformity and exact coverage of the domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "mesh/mapped_quad.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

MappedQuadSpec rectangle(double length, double height, int nx, int ny, ElementType type = ElementType::q4) {
  MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(length, 0), Eigen::Vector2d(length, height),
                  Eigen::Vector2d(0, height)};
  spec.nx = nx;
  spec.ny = ny;
  spec.element = type;
  return spec;
}

// A convex quadrilateral with no parallel sides.
MappedQuadSpec skewed(int nx, int ny, ElementType type) {
  MappedQuadSpec spec = rectangle(1, 1, nx, ny, type);
  spec.corners = {Eigen::Vector2d(-0.5, 0.2), Eigen::Vector2d(4.0, -0.3), Eigen::Vector2d(3.2, 2.6),
                  Eigen::Vector2d(0.4, 1.7)};
  return spec;
}

Eigen::MatrixXd element_coords(const Mesh& mesh, const ElementBlock& b, Eigen::Index e) {
  Eigen::MatrixXd xy(b.conn.cols(), 2);
  for (Eigen::Index a = 0; a < b.conn.cols(); ++a) xy.row(a) = mesh.coords.row(b.conn(e, a));
  return xy;
}

Eigen::Vector2d coords_of(const Mesh& mesh, long id) {
  const int n = mesh.index_of(id);
  EXPECT_GE(n, 0) << "node " << id << " missing";
  return n < 0 ? Eigen::Vector2d(NAN, NAN) : Eigen::Vector2d(mesh.coords.row(n).transpose());
}

TEST(MappedQuadMesh, NodeAndElementCountsMatchTheDivisions) {
  for (auto [nx, ny] : {std::pair{1, 1}, std::pair{5, 2}, std::pair{7, 3}}) {
    const Mesh q4 = generate_mapped_quad(rectangle(10, 2, nx, ny, ElementType::q4));
    EXPECT_EQ(q4.n_nodes(), (nx + 1) * (ny + 1));
    EXPECT_EQ(q4.n_elements(), nx * ny);
    ASSERT_EQ(q4.blocks.size(), 1u);
    EXPECT_EQ(q4.blocks[0].conn.cols(), 4);
    const Mesh cst = generate_mapped_quad(rectangle(10, 2, nx, ny, ElementType::cst));
    EXPECT_EQ(cst.n_nodes(), (nx + 1) * (ny + 1));
    EXPECT_EQ(cst.n_elements(), 2 * nx * ny);
    EXPECT_EQ(cst.blocks[0].conn.cols(), 3);
  }
}

TEST(MappedQuadMesh, SerpentineNumberingMatchesThesisTableTwo) {
  // 10 m x 2 m, 5 x 2 elements: nodes 1-6 along the bottom from x = 0, 7-12 along the middle line
  // from the tip back, 13-18 along the top from x = 0.
  MappedQuadSpec spec = rectangle(10, 2, 5, 2);
  spec.numbering = NodeNumbering::serpentine;
  const Mesh mesh = generate_mapped_quad(spec);
  const std::map<long, Eigen::Vector2d> expected = {{1, {0, 0}},  {6, {10, 0}}, {7, {10, 1}}, {9, {6, 1}},
                                                    {12, {0, 1}}, {13, {0, 2}}, {18, {10, 2}}};
  for (const auto& [id, xy] : expected) EXPECT_LE((coords_of(mesh, id) - xy).norm(), 1e-12) << "node " << id;
  std::set<long> ids(mesh.node_ids.begin(), mesh.node_ids.end());
  EXPECT_EQ(ids.size(), 18u);
  EXPECT_EQ(*ids.begin(), 1);
  EXPECT_EQ(*ids.rbegin(), 18);
}

TEST(MappedQuadMesh, SerpentineNumberingMatchesThesisTableFour) {
  // 5 m x 1 m, 5 x 1 cells of triangles: nodes 1-6 along the bottom, 7-12 along the top from the tip.
  MappedQuadSpec spec = rectangle(5, 1, 5, 1, ElementType::cst);
  spec.numbering = NodeNumbering::serpentine;
  spec.diagonal = TriangleDiagonal::bottom_right_to_top_left;
  const Mesh mesh = generate_mapped_quad(spec);
  EXPECT_LE((coords_of(mesh, 6) - Eigen::Vector2d(5, 0)).norm(), 1e-12);
  EXPECT_LE((coords_of(mesh, 7) - Eigen::Vector2d(5, 1)).norm(), 1e-12);
  EXPECT_LE((coords_of(mesh, 12) - Eigen::Vector2d(0, 1)).norm(), 1e-12);
}

TEST(MappedQuadMesh, RowNumberingRunsEveryRowFromTheFirstCornerAndHonoursTheFirstId) {
  MappedQuadSpec spec = rectangle(10, 2, 5, 2);
  spec.first_node_id = 101;
  spec.first_element_id = 7;
  const Mesh mesh = generate_mapped_quad(spec);
  EXPECT_LE((coords_of(mesh, 101) - Eigen::Vector2d(0, 0)).norm(), 1e-12);
  EXPECT_LE((coords_of(mesh, 107) - Eigen::Vector2d(0, 1)).norm(), 1e-12);
  EXPECT_LE((coords_of(mesh, 112) - Eigen::Vector2d(10, 1)).norm(), 1e-12);
  EXPECT_LE((coords_of(mesh, 118) - Eigen::Vector2d(10, 2)).norm(), 1e-12);
  EXPECT_EQ(mesh.index_of(100), -1);
  EXPECT_EQ(mesh.blocks[0].ids.front(), 7);
  EXPECT_EQ(mesh.blocks[0].ids.back(), 16);
}

struct Pattern {
  ElementType type;
  TriangleDiagonal diagonal;
  const char* name;
};

void PrintTo(const Pattern& p, std::ostream* os) { *os << p.name; }

class MeshPatterns : public ::testing::TestWithParam<Pattern> {
 protected:
  Mesh mesh() const {
    MappedQuadSpec spec = skewed(7, 4, GetParam().type);
    spec.diagonal = GetParam().diagonal;
    spec.numbering = NodeNumbering::serpentine;
    return generate_mapped_quad(spec);
  }
};

TEST_P(MeshPatterns, EveryElementIsCounterclockwiseWithPositiveArea) {
  const Mesh m = mesh();
  const ElementBlock& b = m.blocks[0];
  for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
    const Eigen::MatrixXd xy = element_coords(m, b, e);
    EXPECT_GT(test::polygon_area(xy), 0.0) << "element " << b.ids[static_cast<size_t>(e)];
    if (b.type == ElementType::q4) {  // convex too: every corner turns left
      for (int a = 0; a < 4; ++a) {
        const Eigen::RowVector2d p = xy.row(a), q = xy.row((a + 1) % 4), r = xy.row((a + 2) % 4);
        const double turn = (q - p).x() * (r - q).y() - (q - p).y() * (r - q).x();
        EXPECT_GT(turn, 0.0) << "element " << b.ids[static_cast<size_t>(e)] << " corner " << a;
      }
    }
  }
}

TEST_P(MeshPatterns, ElementAreasSumToTheDomainArea) {
  const Mesh m = mesh();
  const ElementBlock& b = m.blocks[0];
  double total = 0.0;
  for (Eigen::Index e = 0; e < b.conn.rows(); ++e) total += test::polygon_area(element_coords(m, b, e));
  Eigen::MatrixXd corners(4, 2);
  const MappedQuadSpec spec = skewed(1, 1, ElementType::q4);
  for (int i = 0; i < 4; ++i) corners.row(i) = spec.corners[static_cast<size_t>(i)].transpose();
  const double domain = test::polygon_area(corners);
  EXPECT_NEAR(total, domain, 1e-12 * domain);
}

TEST_P(MeshPatterns, MeshIsConformingWithEveryInteriorEdgeSharedByExactlyTwoElements) {
  const Mesh m = mesh();
  const ElementBlock& b = m.blocks[0];
  std::map<std::pair<int, int>, int> uses;
  for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
    for (Eigen::Index a = 0; a < b.conn.cols(); ++a) {
      const int p = b.conn(e, a), q = b.conn(e, (a + 1) % b.conn.cols());
      ++uses[{std::min(p, q), std::max(p, q)}];
    }
  int boundary = 0;
  for (const auto& [edge, count] : uses) {
    EXPECT_LE(count, 2);
    if (count == 1) ++boundary;
  }
  EXPECT_EQ(boundary, 2 * (7 + 4));
  // Every node belongs to some element.
  std::set<int> used(b.conn.data(), b.conn.data() + b.conn.size());
  EXPECT_EQ(static_cast<int>(used.size()), m.n_nodes());
}

INSTANTIATE_TEST_SUITE_P(
    MappedQuad, MeshPatterns,
    ::testing::Values(Pattern{ElementType::q4, TriangleDiagonal::bottom_left_to_top_right, "Q4"},
                      Pattern{ElementType::cst, TriangleDiagonal::bottom_left_to_top_right, "CstBottomLeftToTopRight"},
                      Pattern{ElementType::cst, TriangleDiagonal::bottom_right_to_top_left, "CstBottomRightToTopLeft"},
                      Pattern{ElementType::cst, TriangleDiagonal::alternating, "CstAlternating"}),
    [](const ::testing::TestParamInfo<Pattern>& p) { return std::string(p.param.name); });

// Which diagonal of cell (i, j) the triangles use: true for corner 1 -> corner 3.
bool cell_uses_13_diagonal(const Mesh& mesh, int nx, int i, int j) {
  const ElementBlock& b = mesh.blocks[0];
  const Eigen::Index first = 2 * (j * nx + i);
  const int c1 = j * (nx + 1) + i, c3 = (j + 1) * (nx + 1) + i + 1;
  auto has = [&](Eigen::Index e, int node) {
    for (int a = 0; a < 3; ++a)
      if (b.conn(e, a) == node) return true;
    return false;
  };
  return has(first, c1) && has(first, c3) && has(first + 1, c1) && has(first + 1, c3);
}

TEST(MappedQuadMesh, TriangleDiagonalPatternsSplitCellsAsNamed) {
  const int nx = 4, ny = 3;
  for (TriangleDiagonal d : {TriangleDiagonal::bottom_left_to_top_right, TriangleDiagonal::bottom_right_to_top_left,
                             TriangleDiagonal::alternating}) {
    MappedQuadSpec spec = rectangle(4, 3, nx, ny, ElementType::cst);
    spec.diagonal = d;
    const Mesh mesh = generate_mapped_quad(spec);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const bool expected =
            d == TriangleDiagonal::bottom_left_to_top_right || (d == TriangleDiagonal::alternating && (i + j) % 2 == 0);
        EXPECT_EQ(cell_uses_13_diagonal(mesh, nx, i, j), expected) << "cell " << i << "," << j;
      }
  }
}

TEST(MappedQuadMesh, NodesLieOnTheBilinearMapOfTheCorners) {
  // Edge nodes are evenly spaced along the straight sides; the corners are nodes.
  const MappedQuadSpec spec = skewed(5, 3, ElementType::q4);
  const Mesh mesh = generate_mapped_quad(spec);
  EXPECT_LE((mesh.coords.row(0).transpose() - spec.corners[0]).norm(), 1e-12);
  EXPECT_LE((mesh.coords.row(5).transpose() - spec.corners[1]).norm(), 1e-12);
  EXPECT_LE((mesh.coords.row(23).transpose() - spec.corners[2]).norm(), 1e-12);
  EXPECT_LE((mesh.coords.row(18).transpose() - spec.corners[3]).norm(), 1e-12);
  for (int i = 0; i <= 5; ++i) {
    const Eigen::Vector2d expected = spec.corners[0] + (spec.corners[1] - spec.corners[0]) * (i / 5.0);
    EXPECT_LE((mesh.coords.row(i).transpose() - expected).norm(), 1e-12);
  }
}

TEST(MappedQuadMesh, NonPositiveDivisionsThrowInvalidArgument) {
  EXPECT_THROW(generate_mapped_quad(rectangle(1, 1, 0, 2)), std::invalid_argument);
  EXPECT_THROW(generate_mapped_quad(rectangle(1, 1, 2, -1)), std::invalid_argument);
}

}  // namespace
}  // namespace bb
