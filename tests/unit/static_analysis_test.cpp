// Linear static analysis (analysis/static_analysis, assembly/): equilibrium of reactions and loads,
// detection of rigid-body motions and mechanisms, symmetry and reciprocity of the assembled
// stiffness, work-equivalent edge loads, and the monotone convergence of compliance.
#include "analysis/static_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "mesh/mapped_quad.hpp"
#include "study/timoshenko.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

std::vector<int> nodes_where(const Mesh& mesh, double x, double y, bool match_x, bool match_y) {
  std::vector<int> out;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    if (match_x && std::abs(mesh.coords(n, 0) - x) > 1e-9) continue;
    if (match_y && std::abs(mesh.coords(n, 1) - y) > 1e-9) continue;
    out.push_back(n);
  }
  return out;
}

std::vector<int> nodes_at_x(const Mesh& mesh, double x) { return nodes_where(mesh, x, 0, true, false); }
std::vector<int> node_at(const Mesh& mesh, double x, double y) { return nodes_where(mesh, x, y, true, true); }

// A rectangular cantilever L x H, clamped at x = 0, sets "clamp" and "tip" (x = L).
Model cantilever(double length, double height, int nx, int ny, ElementType element = ElementType::q4,
                 TriangleDiagonal diagonal = TriangleDiagonal::alternating) {
  MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(length, 0), Eigen::Vector2d(length, height),
                  Eigen::Vector2d(0, height)};
  spec.nx = nx;
  spec.ny = ny;
  spec.element = element;
  spec.diagonal = diagonal;
  Model model;
  model.mesh = generate_mapped_quad(spec);
  model.section = test::steel_section(0.1);
  model.node_sets["clamp"] = nodes_at_x(model.mesh, 0.0);
  model.node_sets["tip"] = nodes_at_x(model.mesh, length);
  model.constraints = {{"clamp", {0, 1}, 0.0}};
  return model;
}

TEST(StaticEquilibrium, CantileverReactionsBalanceTheAppliedLoadsInForceAndMoment) {
  for (ElementType type : {ElementType::q4, ElementType::cst}) {
    Model model = cantilever(10.0, 1.0, 20, 4, type);
    model.node_sets["top_mid"] = node_at(model.mesh, 5.0, 1.0);
    // The last load acts on constrained DOFs: it goes straight into the support, and must show
    // up in the reactions as such.
    model.loads = {{"tip", 1, -1.0e5, LoadSplit::consistent_edge},
                   {"tip", 0, 3.0e4, LoadSplit::equal},
                   {"top_mid", 1, 2.0e4, LoadSplit::equal},
                   {"clamp", 0, -5.0e3, LoadSplit::equal}};
    const StaticSolution sol = solve_static(model);
    EXPECT_LT(sol.relative_residual, 1e-10);
    const Mesh& mesh = model.mesh;
    Eigen::Vector3d load_resultant = Eigen::Vector3d::Zero(), reaction_resultant = Eigen::Vector3d::Zero();
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      const double x = mesh.coords(n, 0), y = mesh.coords(n, 1);
      const double fx = sol.loads[2 * n], fy = sol.loads[2 * n + 1];
      const double rx = sol.reactions(n, 0), ry = sol.reactions(n, 1);
      load_resultant += Eigen::Vector3d(fx, fy, x * fy - y * fx);
      reaction_resultant += Eigen::Vector3d(rx, ry, x * ry - y * rx);
    }
    EXPECT_NEAR(load_resultant[0], 2.5e4, 1e-6);
    EXPECT_NEAR(load_resultant[1], -8.0e4, 1e-6);
    EXPECT_LE((reaction_resultant + load_resultant).norm(), 1e-9 * 1e5 * 10.0) << element_name(type);
    // Reactions live only on the clamp.
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      if (mesh.coords(n, 0) < 1e-9) continue;
      EXPECT_EQ(sol.reactions.row(n).norm(), 0.0) << "node " << mesh.node_ids[n];
    }
  }
}

TEST(StaticEquilibrium, PrescribedEndDisplacementGivesTheUniaxialReactionEAEpsilon) {
  // A plate pulled by ux = delta at x = L, ux = 0 at x = 0, one node pinned in y: uniform uniaxial
  // stress E delta / L, total reaction E (delta / L) H t, exact for both element types.
  const double length = 2.0, height = 0.5, delta = 1e-3;
  for (ElementType type : {ElementType::q4, ElementType::cst}) {
    Model model = cantilever(length, height, 8, 2, type);
    model.node_sets["origin"] = node_at(model.mesh, 0.0, 0.0);
    model.constraints = {{"clamp", {0}, 0.0}, {"origin", {1}, 0.0}, {"tip", {0}, delta}};
    const StaticSolution sol = solve_static(model);
    const double expected = model.section.youngs_modulus * delta / length * height * model.section.thickness;
    double right = 0.0, left = 0.0;
    for (int n : model.node_sets["tip"]) right += sol.reactions(n, 0);
    for (int n : model.node_sets["clamp"]) left += sol.reactions(n, 0);
    EXPECT_NEAR(right, expected, 1e-9 * expected) << element_name(type);
    EXPECT_NEAR(left, -expected, 1e-9 * expected) << element_name(type);
    // Lateral contraction -nu delta / L at the top edge.
    for (int n = 0; n < model.mesh.n_nodes(); ++n)
      EXPECT_NEAR(sol.displacements(n, 1), -model.section.poisson_ratio * delta / length * model.mesh.coords(n, 1),
                  1e-12);
  }
}

TEST(StaticSingularity, UnconstrainedModelThrowsInputErrorNamingANode) {
  Model model = cantilever(10.0, 1.0, 10, 2);
  model.constraints.clear();
  model.loads = {{"tip", 1, -1.0e3, LoadSplit::equal}};
  try {
    solve_static(model);
    FAIL() << "a model without constraints must be rejected as singular";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("singular"), std::string::npos) << msg;
    EXPECT_NE(msg.find("node "), std::string::npos) << msg;
  }
}

TEST(StaticSingularity, ModelConstrainedOnlyInXIsAMechanismInYAndThrows) {
  Model model = cantilever(10.0, 1.0, 10, 2);
  model.constraints = {{"clamp", {0}, 0.0}};
  model.loads = {{"tip", 1, -1.0e3, LoadSplit::equal}};
  try {
    solve_static(model);
    FAIL() << "free rigid translation in y must be rejected";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("singular"), std::string::npos) << msg;
    EXPECT_NE(msg.find("node "), std::string::npos) << msg;
  }
}

TEST(StaticSingularity, ModelPinnedAtASingleNodeCanStillRotateAndThrows) {
  Model model = cantilever(10.0, 1.0, 10, 2);
  model.node_sets["pin"] = node_at(model.mesh, 0.0, 0.0);
  model.constraints = {{"pin", {0, 1}, 0.0}};
  model.loads = {{"tip", 1, -1.0e3, LoadSplit::equal}};
  EXPECT_THROW(solve_static(model), InputError);
}

TEST(StaticSingularity, ThreeIndependentSupportsAreEnoughForAUniqueSolution) {
  // The control: a pin plus a roller removes exactly the three rigid motions.
  Model model = cantilever(10.0, 1.0, 10, 2);
  model.node_sets["pin"] = node_at(model.mesh, 0.0, 0.0);
  model.node_sets["roller"] = node_at(model.mesh, 10.0, 0.0);
  model.constraints = {{"pin", {0, 1}, 0.0}, {"roller", {1}, 0.0}};
  model.node_sets["top_mid"] = node_at(model.mesh, 5.0, 1.0);
  model.loads = {{"top_mid", 1, -1.0e3, LoadSplit::equal}};
  const StaticSolution sol = solve_static(model);
  EXPECT_LT(sol.relative_residual, 1e-10);
  // Simply supported: the two vertical reactions share the central load equally.
  EXPECT_NEAR(sol.reactions(model.node_sets["pin"][0], 1), 500.0, 1e-6);
  EXPECT_NEAR(sol.reactions(model.node_sets["roller"][0], 1), 500.0, 1e-6);
}

// A trapezoid so that no two elements are alike.
Mesh distorted_mesh(ElementType type) {
  MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0.5), Eigen::Vector2d(3.5, 2.0), Eigen::Vector2d(0.3, 1.5)};
  spec.nx = 6;
  spec.ny = 3;
  spec.element = type;
  spec.diagonal = TriangleDiagonal::alternating;
  return generate_mapped_quad(spec);
}

TEST(GlobalAssembly, StiffnessAndMassAreSymmetric) {
  for (ElementType type : {ElementType::q4, ElementType::cst}) {
    const GlobalMatrices g = assemble(distorted_mesh(type), test::steel_section());
    const SparseMatrix kt = g.stiffness.transpose(), mt = g.mass.transpose();
    EXPECT_LE((g.stiffness - kt).norm(), 1e-14 * g.stiffness.norm()) << element_name(type);
    EXPECT_LE((g.mass - mt).norm(), 1e-15 * g.mass.norm()) << element_name(type);
  }
}

TEST(GlobalAssembly, RigidBodyMotionsCostNoEnergyAndCarryTheTotalMass) {
  const fe::PlaneSection sec = test::steel_section(0.03);
  for (ElementType type : {ElementType::q4, ElementType::cst}) {
    const Mesh mesh = distorted_mesh(type);
    const GlobalMatrices g = assemble(mesh, sec);
    const Eigen::MatrixXd r = test::rigid_body_modes(mesh.coords);
    for (int c = 0; c < 3; ++c)
      EXPECT_LE((g.stiffness * r.col(c)).norm(), 1e-12 * g.stiffness.norm() * r.col(c).norm()) << element_name(type);
    Eigen::MatrixXd corners(4, 2);
    corners << 0, 0, 4, 0.5, 3.5, 2.0, 0.3, 1.5;
    const double total = sec.density * sec.thickness * test::polygon_area(corners);
    EXPECT_NEAR(r.col(0).dot(g.mass * r.col(0)), total, 1e-12 * total);
    EXPECT_NEAR(r.col(1).dot(g.mass * r.col(1)), total, 1e-12 * total);
    EXPECT_NEAR(r.col(0).dot(g.mass * r.col(1)), 0.0, 1e-12 * total);
  }
}

TEST(GlobalAssembly, InvertedElementIsReportedAsInputErrorNamingTheElement) {
  Mesh mesh = distorted_mesh(ElementType::q4);
  auto row = mesh.blocks[0].conn.row(4);
  std::swap(row(1), row(3));  // element 5 now runs clockwise
  try {
    assemble(mesh, test::steel_section());
    FAIL() << "a clockwise element must be rejected";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 5"), std::string::npos) << e.what();
  }
}

TEST(StaticReciprocity, MaxwellBettiDisplacementAtADueToLoadAtBEqualsDisplacementAtBDueToLoadAtA) {
  for (ElementType type : {ElementType::q4, ElementType::cst}) {
    Model base = cantilever(6.0, 1.0, 12, 3, type);
    base.node_sets["A"] = node_at(base.mesh, 6.0, 1.0);  // tip, top corner
    base.node_sets["B"] = node_at(base.mesh, 3.0, 0.0);  // mid-span, bottom
    ASSERT_EQ(base.node_sets["A"].size(), 1u);
    ASSERT_EQ(base.node_sets["B"].size(), 1u);
    const int a = base.node_sets["A"][0], b = base.node_sets["B"][0];
    // Unit force at B along x; read the y displacement at A. Then unit force at A along y; read x at B.
    Model at_b = base, at_a = base;
    at_b.loads = {{"B", 0, 1.0, LoadSplit::equal}};
    at_a.loads = {{"A", 1, 1.0, LoadSplit::equal}};
    const double u_a = solve_static(at_b).displacements(a, 1);
    const double u_b = solve_static(at_a).displacements(b, 0);
    ASSERT_GT(std::abs(u_a), 0.0);
    EXPECT_NEAR(u_a, u_b, 1e-10 * std::abs(u_a)) << element_name(type);
  }
}

TEST(ConsistentEdgeLoad, TwoElementEdgeSplitsQuarterHalfQuarter) {
  // Thesis Table II mesh: 5 x 2 elements on 10 m x 2 m, the tip edge holds two element edges.
  Model model = cantilever(10.0, 2.0, 5, 2);
  model.loads = {{"tip", 1, -1.0e5, LoadSplit::consistent_edge}};
  const Eigen::VectorXd f = load_vector(model);
  const std::vector<int> tip = model.node_sets["tip"];
  ASSERT_EQ(tip.size(), 3u);
  std::map<double, double> by_height;
  for (int n : tip) by_height[model.mesh.coords(n, 1)] = f[2 * n + 1];
  EXPECT_NEAR(by_height[0.0], -2.5e4, 1e-9);
  EXPECT_NEAR(by_height[1.0], -5.0e4, 1e-9);
  EXPECT_NEAR(by_height[2.0], -2.5e4, 1e-9);
  EXPECT_NEAR(f.sum(), -1.0e5, 1e-9);
  EXPECT_NEAR(f.cwiseAbs().sum(), 1.0e5, 1e-9) << "no load outside the tip's y DOFs";
  // An equal split gives a third each.
  model.loads[0].split = LoadSplit::equal;
  const Eigen::VectorXd g = load_vector(model);
  for (int n : tip) EXPECT_NEAR(g[2 * n + 1], -1.0e5 / 3.0, 1e-9);
}

TEST(ConsistentEdgeLoad, SetWithoutElementEdgeIsRejected) {
  Model model = cantilever(10.0, 2.0, 5, 2);
  model.node_sets["corner"] = node_at(model.mesh, 10.0, 2.0);
  model.loads = {{"corner", 1, -1.0, LoadSplit::consistent_edge}};
  EXPECT_THROW(load_vector(model), InputError);
}

TEST(StaticConvergence, CantileverComplianceGrowsMonotonicallyUnderNestedRefinementTowardsTimoshenko) {
  // Conforming displacement elements are too stiff, and nested meshes have nested trial spaces, so
  // the compliance f^T u (= P times the traction-weighted mean tip deflection) increases with
  // every refinement. Its limit is plane-stress elasticity, close to Timoshenko beam theory.
  const double length = 10.0, height = 1.0, load = -1.0e5;
  std::vector<double> compliance;
  for (int level : {1, 2, 4, 8}) {
    Model model = cantilever(length, height, 10 * level, level);
    model.loads = {{"tip", 1, load, LoadSplit::consistent_edge}};
    const StaticSolution sol = solve_static(model);
    double work = 0.0;
    for (int n = 0; n < model.mesh.n_nodes(); ++n)
      work += sol.loads[2 * n] * sol.displacements(n, 0) + sol.loads[2 * n + 1] * sol.displacements(n, 1);
    compliance.push_back(work);
  }
  for (size_t i = 1; i < compliance.size(); ++i) EXPECT_GT(compliance[i], compliance[i - 1]) << "level " << i;
  const fe::PlaneSection sec = test::steel_section(0.1);
  const double inertia = sec.thickness * height * height * height / 12.0;
  const double shear_modulus = sec.youngs_modulus / (2 * (1 + sec.poisson_ratio));
  const double tip = load * length * length * length / (3 * sec.youngs_modulus * inertia) +
                     load * length / (5.0 / 6.0 * shear_modulus * sec.thickness * height);
  const double timoshenko_compliance = load * tip;
  const double error = std::abs(compliance.back() - timoshenko_compliance) / timoshenko_compliance;
  EXPECT_LT(error, 0.02) << "finest compliance " << compliance.back() << " vs Timoshenko " << timoshenko_compliance;
  EXPECT_LT(error, std::abs(compliance.front() - timoshenko_compliance) / timoshenko_compliance);
}

TEST(TimoshenkoTipDeflection, IsEulerBernoulliBendingPlusShearCompliance) {
  // L = 10 m, h = 1 m, t = 0.1 m, E = 200 GPa, nu = 0.25 (G = 80 GPa), k = 5/6, P = 100 kN:
  // P L^3 / 3EI = 1e8 / (3 * 2e11 * 0.1 / 12) = 0.02 m, P L / kGA = 1e6 / (5/6 * 8e10 * 0.1) = 1.5e-4 m.
  const RectangularBeam beam{.length = 10.0,
                             .height = 1.0,
                             .thickness = 0.1,
                             .youngs_modulus = 2.0e11,
                             .poisson_ratio = 0.25,
                             .shear_coefficient = 5.0 / 6.0};
  EXPECT_NEAR(euler_bernoulli_tip_deflection(beam, 1.0e5), 0.02, 1e-15);
  EXPECT_NEAR(timoshenko_tip_deflection(beam, 1.0e5), 0.02 + 1.5e-4, 1e-15);
  EXPECT_NEAR(timoshenko_tip_deflection(beam, -1.0e5), -(0.02 + 1.5e-4), 1e-15) << "linear in the load";
}

}  // namespace
}  // namespace bb
