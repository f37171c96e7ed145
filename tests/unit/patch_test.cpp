// Patch tests (Irons; MacNeal & Harder 1985) on distorted meshes, through the whole static path:
// hand-built mesh -> bb::assemble -> constraints with prescribed values -> bb::solve_static.
// A conforming element that passes reproduces any linear displacement field exactly, whatever the
// shape of the elements, and with it the constant stress D eps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/static_analysis.hpp"
#include "assembly/assemble.hpp"
#include "assembly/dof_map.hpp"
#include "fe/plane_stress.hpp"
#include "linalg/spd_factor.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

using test::Block;
using test::LinearField;

// MacNeal-Harder patch: a 0.24 x 0.12 rectangle, four boundary nodes (ids 1-4) and four interior
// nodes (ids 5-8) at irregular positions, five quadrilaterals of which none is a parallelogram.
std::vector<std::pair<long, Eigen::Vector2d>> macneal_harder_nodes() {
  return {{1, {0.0, 0.0}},   {2, {0.24, 0.0}},  {3, {0.24, 0.12}}, {4, {0.0, 0.12}},
          {5, {0.04, 0.02}}, {6, {0.18, 0.03}}, {7, {0.16, 0.08}}, {8, {0.08, 0.08}}};
}
const std::vector<std::vector<long>> kMacNealHarderQuads = {
    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}, {5, 6, 7, 8}};
// The same patch triangulated, the diagonals chosen both ways.
const std::vector<std::vector<long>> kMacNealHarderTriangles = {{1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 4, 7},
                                                                {4, 8, 7}, {4, 1, 5}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}};

struct Patch {
  std::string name;
  Mesh mesh;
  std::vector<long> boundary;  // user ids of the nodes whose displacement is prescribed
};

void PrintTo(const Patch& p, std::ostream* os) { *os << p.name; }

Patch macneal_harder(ElementType type) {
  const auto& conn = type == ElementType::q4 ? kMacNealHarderQuads : kMacNealHarderTriangles;
  return {type == ElementType::q4 ? "Q4MacNealHarder" : "CstMacNealHarder",
          test::make_mesh(macneal_harder_nodes(), {Block{type, conn}}),
          {1, 2, 3, 4}};
}

// Unit square, 3 x 3 nodes, every edge node and the interior node pushed off-centre; node ids are
// deliberately not 1..n so that the id -> index mapping is exercised too.
std::vector<std::pair<long, Eigen::Vector2d>> skewed_square_nodes() {
  return {{10, {0.0, 0.0}},  {20, {0.4, 0.0}}, {30, {1.0, 0.0}},  {40, {0.0, 0.3}}, {50, {0.6, 0.45}},
          {60, {1.0, 0.65}}, {70, {0.0, 1.0}}, {80, {0.55, 1.0}}, {90, {1.0, 1.0}}};
}
const std::vector<std::vector<long>> kSkewedQuads = {
    {10, 20, 50, 40}, {20, 30, 60, 50}, {40, 50, 80, 70}, {50, 60, 90, 80}};
const std::vector<std::vector<long>> kSkewedTriangles = {{10, 20, 50}, {10, 50, 40}, {20, 30, 60}, {20, 60, 50},
                                                         {40, 50, 80}, {40, 80, 70}, {50, 60, 90}, {50, 90, 80}};

Patch skewed_square(ElementType type) {
  const auto& conn = type == ElementType::q4 ? kSkewedQuads : kSkewedTriangles;
  return {type == ElementType::q4 ? "Q4SkewedSquare" : "CstSkewedSquare",
          test::make_mesh(skewed_square_nodes(), {Block{type, conn}}),
          {10, 20, 30, 40, 60, 70, 80, 90}};
}

// Q4 and CST in one mesh (two blocks): the two left cells of the skewed square as quads, the
// two right cells as triangles. Both are linear along a shared edge, so the mesh is conforming.
Patch mixed_square() {
  return {"MixedQ4AndCst",
          test::make_mesh(skewed_square_nodes(),
                          {Block{ElementType::q4, {{10, 20, 50, 40}, {40, 50, 80, 70}}},
                           Block{ElementType::cst, {{20, 30, 60}, {20, 60, 50}, {50, 60, 90}, {50, 90, 80}}}}),
          {10, 20, 30, 40, 60, 70, 80, 90}};
}

// Every boundary node gets its own set and one constraint per direction, valued from the field.
Model displacement_patch_model(const Patch& p, const LinearField& f) {
  Model model;
  model.mesh = p.mesh;
  model.section = test::steel_section(0.001);
  for (long id : p.boundary) {
    const int n = model.mesh.index_of(id);
    const std::string set = "node" + std::to_string(id);
    model.node_sets[set] = {n};
    const Eigen::Vector2d u = f.at(model.mesh.coords(n, 0), model.mesh.coords(n, 1));
    model.constraints.push_back({set, {0}, u.x()});
    model.constraints.push_back({set, {1}, u.y()});
  }
  return model;
}

// Centroid stress of every element, from the solved nodal displacements.
std::vector<Eigen::Vector3d> element_stresses(const Model& model, const Eigen::MatrixXd& displacements) {
  std::vector<Eigen::Vector3d> out;
  for (const ElementBlock& b : model.mesh.blocks) {
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
      if (b.type == ElementType::q4) {
        fe::Q4Coords xy;
        Eigen::Matrix<double, 8, 1> u;
        for (int a = 0; a < 4; ++a) {
          xy.row(a) = model.mesh.coords.row(b.conn(e, a));
          u.segment<2>(2 * a) = displacements.row(b.conn(e, a)).transpose();
        }
        out.push_back(fe::q4_centroid_stress(xy, u, model.section));
      } else {
        fe::CstCoords xy;
        Eigen::Matrix<double, 6, 1> u;
        for (int a = 0; a < 3; ++a) {
          xy.row(a) = model.mesh.coords.row(b.conn(e, a));
          u.segment<2>(2 * a) = displacements.row(b.conn(e, a)).transpose();
        }
        out.push_back(fe::cst_stress(xy, u, model.section));
      }
    }
  }
  return out;
}

class DistortedPatch : public ::testing::TestWithParam<Patch> {};

TEST_P(DistortedPatch, InteriorNodesReproduceAPrescribedLinearDisplacementField) {
  const Patch& p = GetParam();
  // Rigid translation, rotation, both normal strains and shear, all at once.
  const LinearField f{1.0e-4, 2.0e-3, -1.5e-3, -5.0e-4, 3.0e-3, -1.0e-3};
  const Model model = displacement_patch_model(p, f);
  const StaticSolution sol = solve_static(model);
  ASSERT_EQ(sol.n_free_dofs, 2 * (model.mesh.n_nodes() - static_cast<int>(p.boundary.size())));
  double scale = 0.0;
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    scale = std::max(scale, f.at(model.mesh.coords(n, 0), model.mesh.coords(n, 1)).norm());
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Eigen::Vector2d expected = f.at(model.mesh.coords(n, 0), model.mesh.coords(n, 1));
    const Eigen::Vector2d got = sol.displacements.row(n).transpose();
    EXPECT_LE((got - expected).norm(), 1e-10 * scale)
        << "node " << model.mesh.node_ids[n] << ": " << got.transpose() << " vs " << expected.transpose();
  }
}

TEST_P(DistortedPatch, EveryElementCarriesTheConstantStressDEps) {
  const Patch& p = GetParam();
  const LinearField f{0.0, 1.0e-3, 4.0e-4, 0.0, -2.0e-4, -6.0e-4};
  const Model model = displacement_patch_model(p, f);
  const StaticSolution sol = solve_static(model);
  const Eigen::Vector3d expected =
      fe::plane_stress_elasticity(model.section.youngs_modulus, model.section.poisson_ratio) * f.strain();
  const auto stresses = element_stresses(model, sol.displacements);
  ASSERT_EQ(static_cast<int>(stresses.size()), model.mesh.n_elements());
  for (size_t e = 0; e < stresses.size(); ++e) {
    EXPECT_LE((stresses[e] - expected).norm(), 1e-9 * expected.norm())
        << "element " << e + 1 << ": " << stresses[e].transpose() << " vs " << expected.transpose();
  }
}

TEST_P(DistortedPatch, ReactionsOfAConstantStressStateAreSelfEquilibrated) {
  // No body force: the boundary reactions alone must balance in force and moment.
  const Patch& p = GetParam();
  const LinearField f{2e-4, 1.0e-3, 2.0e-4, 0.0, 5.0e-4, -7.0e-4};
  const Model model = displacement_patch_model(p, f);
  const StaticSolution sol = solve_static(model);
  const double scale = sol.reactions.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LE(std::abs(sol.reactions.col(0).sum()), 1e-10 * scale);
  EXPECT_LE(std::abs(sol.reactions.col(1).sum()), 1e-10 * scale);
  double moment = 0.0;
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    moment += model.mesh.coords(n, 0) * sol.reactions(n, 1) - model.mesh.coords(n, 1) * sol.reactions(n, 0);
  EXPECT_LE(std::abs(moment), 1e-10 * scale);
}

INSTANTIATE_TEST_SUITE_P(PatchTest, DistortedPatch,
                         ::testing::Values(macneal_harder(ElementType::q4), macneal_harder(ElementType::cst),
                                           skewed_square(ElementType::q4), skewed_square(ElementType::cst),
                                           mixed_square()),
                         [](const ::testing::TestParamInfo<Patch>& p) { return p.param.name; });

// Force patch test: the skewed unit square under uniform biaxial traction, sx on the right edge and
// sy on the top edge, applied as consistent (work-equivalent) nodal loads, with only the symmetry
// supports ux = 0 on the left edge and uy = 0 on the bottom edge. The exact solution is the
// uniform stress (sx, sy, 0); the loaded edges have unequal segments, so an equal split would fail.
class ForcePatch : public ::testing::TestWithParam<ElementType> {
 protected:
  Model model_for(ElementType type) const {
    Model model;
    model.mesh = skewed_square(type).mesh;
    model.section = test::steel_section(0.002);
    model.node_sets["left"] = test::node_set(model.mesh, {10, 40, 70});
    model.node_sets["bottom"] = test::node_set(model.mesh, {10, 20, 30});
    model.node_sets["right"] = test::node_set(model.mesh, {30, 60, 90});
    model.node_sets["top"] = test::node_set(model.mesh, {70, 80, 90});
    model.constraints = {{"left", {0}, 0.0}, {"bottom", {1}, 0.0}};
    // Edge lengths are 1, so the totals are traction times thickness.
    model.loads = {{"right", 0, sx * model.section.thickness, LoadSplit::consistent_edge},
                   {"top", 1, sy * model.section.thickness, LoadSplit::consistent_edge}};
    return model;
  }
  double sx = 8.0e7, sy = -3.0e7;
};

TEST_P(ForcePatch, UniformTractionWithConsistentLoadsGivesUniformStress) {
  const Model model = model_for(GetParam());
  const StaticSolution sol = solve_static(model);
  const Eigen::Vector3d expected(sx, sy, 0.0);
  for (const Eigen::Vector3d& s : element_stresses(model, sol.displacements))
    EXPECT_LE((s - expected).norm(), 1e-9 * expected.norm()) << s.transpose();
  // And the displacement is the matching linear field: eps = D^-1 sigma, zero at the supports.
  const double e = model.section.youngs_modulus, nu = model.section.poisson_ratio;
  const double exx = (sx - nu * sy) / e, eyy = (sy - nu * sx) / e;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    EXPECT_NEAR(sol.displacements(n, 0), exx * model.mesh.coords(n, 0), 1e-10 * std::abs(exx));
    EXPECT_NEAR(sol.displacements(n, 1), eyy * model.mesh.coords(n, 1), 1e-10 * std::abs(exx));
  }
}

TEST_P(ForcePatch, EqualLoadSplitOnUnequalEdgeSegmentsDoesNotGiveUniformStress) {
  // The control experiment: the same totals split equally are not work-equivalent to a uniform
  // traction here, so the stress must vary. This shows the force patch test can fail.
  Model model = model_for(GetParam());
  for (NodalLoad& l : model.loads) l.split = LoadSplit::equal;
  const StaticSolution sol = solve_static(model);
  double worst = 0.0;
  for (const Eigen::Vector3d& s : element_stresses(model, sol.displacements))
    worst = std::max(worst, (s - Eigen::Vector3d(sx, sy, 0.0)).norm());
  EXPECT_GT(worst, 1e-3 * sx);
}

INSTANTIATE_TEST_SUITE_P(PatchTest, ForcePatch, ::testing::Values(ElementType::q4, ElementType::cst),
                         [](const ::testing::TestParamInfo<ElementType>& p) {
                           return p.param == ElementType::q4 ? std::string("Q4") : std::string("Cst");
                         });

TEST(PatchTest, SolvingThePartitionedSystemDirectlyReproducesTheLinearField) {
  // The same displacement patch test one level down: bb::partition and bb::SpdFactorization
  // without solve_static, u_f = K_ff^-1 (-K_fc u_c).
  const Patch p = macneal_harder(ElementType::q4);
  const LinearField f{0.0, -1.0e-3, 2.5e-3, 1.0e-4, 0.5e-3, 1.5e-3};
  const Model model = displacement_patch_model(p, f);
  const DofMap dofs = number_dofs(model);
  const GlobalMatrices g = assemble(model.mesh, model.section, {.stiffness = true, .mass = false});
  const Partitioned k = partition(g.stiffness, dofs);
  SpdFactorization factor;
  ASSERT_TRUE(factor.factorize(k.ff).ok);
  const Eigen::VectorXd u_free = factor.solve(Eigen::VectorXd(-(k.fc * dofs.prescribed)));
  for (int i = 0; i < dofs.n_free; ++i) {
    const int node = dofs.free_dofs[i] / 2, dir = dofs.free_dofs[i] % 2;
    const double expected = f.at(model.mesh.coords(node, 0), model.mesh.coords(node, 1))[dir];
    EXPECT_NEAR(u_free[i], expected, 1e-10 * 1e-3);
  }
}

}  // namespace
}  // namespace bb
