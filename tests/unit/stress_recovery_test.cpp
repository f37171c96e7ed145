// Stress recovery (fe/stress_recovery, assembly/stress_recovery): extrapolation from the integration
// points to the nodes, averaging, invariants, and the whole static path (distributed load -> solve ->
// recovery) on distorted patches, where every element must return the exact constant stress.
#include "assembly/stress_recovery.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/static_analysis.hpp"
#include "analysis/stress_tables.hpp"
#include "fe/solid.hpp"
#include "fe/stress_recovery.hpp"
#include "mesh/hex_block.hpp"
#include "mesh/mapped_quad.hpp"
#include "solid_test_support.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

constexpr double kG2 = 0.57735026918962576451;
constexpr double kG3 = 0.77459666924148337704;

TEST(StressExtrapolation, EveryRowSumsToOneSoAConstantIsKept) {
  EXPECT_NEAR((fe::q4_extrapolation().rowwise().sum().array() - 1).abs().maxCoeff(), 0.0, 1e-14);
  EXPECT_NEAR((fe::cst_extrapolation().rowwise().sum().array() - 1).abs().maxCoeff(), 0.0, 1e-14);
  EXPECT_NEAR((fe::hex8_extrapolation().rowwise().sum().array() - 1).abs().maxCoeff(), 0.0, 1e-14);
  EXPECT_NEAR((fe::hex20_extrapolation().rowwise().sum().array() - 1).abs().maxCoeff(), 0.0, 1e-13);
}

// A field of the degree the points determine, sampled at the points, must come back exactly at the
// nodes: bilinear on the q4's 2x2, trilinear on the hex8's 2x2x2, triquadratic on the hex20's 3x3x3.
TEST(StressExtrapolation, IsExactForTheDegreeItsPointsDetermine) {
  auto f2 = [](double x, double y) { return 1.5 - 2 * x + 3 * y + 0.7 * x * y; };
  Eigen::Vector4d at_points;
  for (int j = 0, p = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i, ++p) at_points[p] = f2(i ? kG2 : -kG2, j ? kG2 : -kG2);
  const Eigen::Vector4d q4 = fe::q4_extrapolation() * at_points;
  const double quad[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(q4[a], f2(quad[a][0], quad[a][1]), 1e-12) << "q4 node " << a + 1;

  const Eigen::Matrix<double, 20, 3> nodes = test::hex20_natural_nodes();
  auto f3 = [](double x, double y, double z) {
    return 2 + x - y + 0.5 * z + 0.3 * x * y - 0.2 * y * z + 0.1 * x * y * z;
  };
  Eigen::Matrix<double, 8, 1> hex8_points;
  for (int k = 0, p = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i, ++p) hex8_points[p] = f3(i ? kG2 : -kG2, j ? kG2 : -kG2, k ? kG2 : -kG2);
  const Eigen::Matrix<double, 8, 1> hex8 = fe::hex8_extrapolation() * hex8_points;
  for (int a = 0; a < 8; ++a)
    EXPECT_NEAR(hex8[a], f3(nodes(a, 0), nodes(a, 1), nodes(a, 2)), 1e-12) << "hex8 node " << a + 1;

  auto fq = [](double x, double y, double z) {
    return 1 + x * x - 2 * y * y * z + 0.5 * x * x * y * y * z * z + x * y * z;
  };
  const double g[3] = {-kG3, 0.0, kG3};
  Eigen::Matrix<double, 27, 1> hex20_points;
  for (int k = 0, p = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i, ++p) hex20_points[p] = fq(g[i], g[j], g[k]);
  const Eigen::Matrix<double, 20, 1> hex20 = fe::hex20_extrapolation() * hex20_points;
  for (int a = 0; a < 20; ++a)
    EXPECT_NEAR(hex20[a], fq(nodes(a, 0), nodes(a, 1), nodes(a, 2)), 1e-12) << "hex20 node " << a + 1;
}

TEST(StressInvariants, VonMisesAndPrincipalStressesOfKnownStates) {
  // Uniaxial: von Mises = |sigma|.
  EXPECT_NEAR(fe::von_mises_plane({-3e8, 0, 0}), 3e8, 1e-6);
  fe::Vector6 uniaxial;
  uniaxial << 0, 0, 2e8, 0, 0, 0;
  EXPECT_NEAR(fe::von_mises_solid(uniaxial), 2e8, 1e-6);
  // Pure shear tau: von Mises sqrt(3) tau, principal +tau, -tau.
  EXPECT_NEAR(fe::von_mises_plane({0, 0, 1e8}), std::sqrt(3.0) * 1e8, 1e-6);
  const Eigen::Vector2d p = fe::principal_plane({0, 0, 1e8});
  EXPECT_NEAR(p[0], 1e8, 1e-6);
  EXPECT_NEAR(p[1], -1e8, 1e-6);
  // Hydrostatic: no von Mises stress, three equal principal stresses.
  fe::Vector6 hydro;
  hydro << 5e7, 5e7, 5e7, 0, 0, 0;
  EXPECT_NEAR(fe::von_mises_solid(hydro), 0.0, 1e-6);
  EXPECT_NEAR((fe::principal_solid(hydro).array() - 5e7).abs().maxCoeff(), 0.0, 1e-6);
  // A general state: principal stresses are the eigenvalues (trace and determinant kept), sorted,
  // and von Mises from them equals von Mises from the components.
  fe::Vector6 s;
  s << 1.2e8, -0.4e8, 0.3e8, 0.5e8, -0.2e8, 0.7e8;
  const Eigen::Vector3d q = fe::principal_solid(s);
  EXPECT_GE(q[0], q[1]);
  EXPECT_GE(q[1], q[2]);
  EXPECT_NEAR(q.sum(), s[0] + s[1] + s[2], 1e-5);
  Eigen::Matrix3d t;
  t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  EXPECT_NEAR(q.prod() / t.determinant(), 1.0, 1e-12);
  fe::Vector6 principal_state;
  principal_state << q[0], q[1], q[2], 0, 0, 0;
  EXPECT_NEAR(fe::von_mises_solid(principal_state), fe::von_mises_solid(s), 1e-4);
}

TEST(StressInvariants, StrainsFromStressesInvertHookesLaw) {
  const double e = 2.1e11, nu = 0.3;
  const Eigen::Vector3d eps_plane(1e-4, -3e-5, 2e-5);  // exx, eyy, gxy
  const Eigen::Vector3d s = fe::plane_stress_elasticity(e, nu) * eps_plane;
  const Eigen::Vector4d back = fe::plane_stress_strains(s, e, nu);
  EXPECT_NEAR((back.head<3>() - eps_plane).norm(), 0.0, 1e-18);
  EXPECT_NEAR(back[3], -nu / (1 - nu) * (eps_plane[0] + eps_plane[1]), 1e-18);  // plane stress thickness strain
  fe::Vector6 eps;
  eps << 1e-4, -2e-5, 3e-5, 4e-5, -1e-5, 2e-5;
  const fe::Vector6 sigma = fe::isotropic_elasticity(e, nu) * eps;
  EXPECT_NEAR((fe::solid_strains(sigma, e, nu) - eps).norm(), 0.0, 1e-18);
}

// Distorted meshes of every element type whose boundary edges / faces stay on the planes x, y (, z)
// = 0 and = L: each corner inside a boundary plane moves only within it.
Mesh distorted_plane_mesh(ElementType type) {
  MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 0), Eigen::Vector2d(2, 1), Eigen::Vector2d(0, 1)};
  spec.nx = 3;
  spec.ny = 3;
  spec.element = type;
  spec.diagonal = TriangleDiagonal::alternating;
  Mesh mesh = generate_mapped_quad(spec);
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const double x = mesh.coords(n, 0), y = mesh.coords(n, 1);
    if (x > 1e-9 && x < 2 - 1e-9) mesh.coords(n, 0) += 0.15 * std::sin(3.1 * y + 1.3 * x);
    if (y > 1e-9 && y < 1 - 1e-9) mesh.coords(n, 1) += 0.08 * std::cos(2.3 * x - 0.7 * y);
  }
  return mesh;
}

Mesh distorted_solid_mesh(ElementType type) {
  const int nodes = type == ElementType::hex20 ? 20 : 8;
  const int n = 2;
  const test::HexGrid grid = test::make_hex_grid(n, n, n, nodes, [&](int i, int j, int k) {
    Eigen::Vector3d x(0.5 * i / n, 0.4 * j / n, 0.3 * k / n);  // 1.0 x 0.8 x 0.6 box, lattice step 2 per element
    const Eigen::Vector3d wobble(0.07 * std::sin(1.7 * j + 2.9 * k), 0.05 * std::cos(2.2 * i - 1.1 * k),
                                 0.04 * std::sin(0.9 * i + 1.9 * j));
    if (i > 0 && i < 2 * n) x.x() += wobble.x();
    if (j > 0 && j < 2 * n) x.y() += wobble.y();
    if (k > 0 && k < 2 * n) x.z() += wobble.z();
    return x;
  });
  return test::mesh_from_grid(grid, type);
}

Mesh distorted_element_mesh(ElementType type) {
  return element_dimension(type) == 2 ? distorted_plane_mesh(type) : distorted_solid_mesh(type);
}

class EveryElement : public ::testing::TestWithParam<ElementType> {};

// u = u0 + G x at every node: a linear field every element reproduces, so every integration point,
// every extrapolated nodal value and every average is D eps exactly, and the elements agree.
TEST_P(EveryElement, LinearFieldGivesTheExactConstantStressAtEveryNodeAndPoint) {
  const ElementType type = GetParam();
  const Mesh mesh = distorted_element_mesh(type);
  const fe::PlaneSection material = test::steel_section(0.02);
  const int dim = mesh.dim;
  Eigen::Matrix3d grad;
  grad << 1.0e-3, -2.0e-4, 3.0e-4, 5.0e-4, -7.0e-4, 1.0e-4, -2.0e-4, 4.0e-4, 6.0e-4;
  const Eigen::Vector3d u0(1e-3, -2e-3, 5e-4);
  Eigen::MatrixXd u(mesh.n_nodes(), dim);
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    x.head(dim) = mesh.coords.row(n).transpose();
    u.row(n) = (u0 + grad * x).head(dim).transpose();
  }
  Eigen::VectorXd exact;
  if (dim == 2) {
    exact = fe::plane_stress_elasticity(material.youngs_modulus, material.poisson_ratio) *
            Eigen::Vector3d(grad(0, 0), grad(1, 1), grad(0, 1) + grad(1, 0));
  } else {
    const test::LinearField3 f{u0, grad};
    exact = fe::isotropic_elasticity(material.youngs_modulus, material.poisson_ratio) * f.strain();
  }
  const StressField field = recover_stresses(mesh, material, u, {.integration_points = true});
  const double scale = exact.norm();
  ASSERT_EQ(field.nodal.cols(), exact.size());
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    EXPECT_LT((field.nodal.row(n).transpose() - exact).norm(), 1e-9 * scale)
        << "node " << mesh.node_ids[static_cast<size_t>(n)];
    EXPECT_LT(field.scatter[n], 1e-9 * scale);
    EXPECT_GT(field.elements[n], 0);
  }
  ASSERT_TRUE(field.points.has_value());
  for (Eigen::Index p = 0; p < field.points->stress.rows(); ++p)
    EXPECT_LT((field.points->stress.row(p).transpose() - exact).norm(), 1e-9 * scale) << "point " << p + 1;
}

// The whole static path on the distorted patch: a uniform traction on the face x = L (edge in 2D),
// symmetry supports on x = 0, y = 0 (, z = 0), the consistent facet loads, the solve and the
// recovery: a uniaxial stress sigma_xx = traction everywhere, exactly (the patch test with loads).
TEST_P(EveryElement, PatchUnderUniformTractionRecoversTheExactUniaxialStress) {
  const ElementType type = GetParam();
  Model model;
  model.mesh = distorted_element_mesh(type);
  model.section = test::steel_section(0.02);
  const int dim = model.mesh.dim;
  const double length = dim == 2 ? 2.0 : 1.0;
  const double sigma = 3.0e7;
  for (int d = 0; d < dim; ++d) {
    const std::string name = std::string("sym_") + "xyz"[d];
    for (int n = 0; n < model.mesh.n_nodes(); ++n)
      if (std::abs(model.mesh.coords(n, d)) < 1e-12) model.node_sets[name].push_back(n);
    model.constraints.push_back({name, {d}, 0.0});
  }
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    if (std::abs(model.mesh.coords(n, 0) - length) < 1e-12) model.node_sets["end"].push_back(n);
  SurfaceLoad load;
  load.set = "end";
  load.kind = SurfaceLoad::Kind::traction;
  load.traction = Eigen::Vector3d(sigma, 0, 0);
  model.surface_loads.push_back(load);
  ResultTables tables;
  const StaticOutcome o = run_static(model, StaticSpec{}, tables);
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Eigen::RowVectorXd s = o.stresses.nodal.row(n);
    EXPECT_NEAR(s[0], sigma, 1e-8 * sigma) << "sxx at node " << model.mesh.node_ids[static_cast<size_t>(n)];
    EXPECT_NEAR(s.tail(s.size() - 1).cwiseAbs().maxCoeff(), 0.0, 1e-8 * sigma) << "other components at node " << n;
  }
  // The table reads the same, with von Mises = sigma and s1 = sigma.
  const ResultTable& t = tables.at("nodal_stresses");
  const int vm = *t.column_index("von_mises"), s1 = *t.column_index("s1");
  for (Eigen::Index r = 0; r < t.values.rows(); ++r) {
    EXPECT_NEAR(t.values(r, vm), sigma, 1e-8 * sigma);
    EXPECT_NEAR(t.values(r, s1), sigma, 1e-8 * sigma);
  }
  // Strain table: exx = sigma / E, the lateral strains -nu sigma / E.
  const ResultTable& strains = tables.at("nodal_strains");
  const double e = model.section.youngs_modulus, nu = model.section.poisson_ratio;
  for (Eigen::Index r = 0; r < strains.values.rows(); ++r) {
    EXPECT_NEAR(strains.values(r, *strains.column_index("exx")), sigma / e, 1e-8 * sigma / e);
    EXPECT_NEAR(strains.values(r, *strains.column_index("eyy")), -nu * sigma / e, 1e-8 * sigma / e);
    EXPECT_NEAR(strains.values(r, *strains.column_index("ezz")), -nu * sigma / e, 1e-8 * sigma / e);
  }
}

INSTANTIATE_TEST_SUITE_P(StressRecovery, EveryElement,
                         ::testing::Values(ElementType::q4, ElementType::cst, ElementType::hex8, ElementType::hex8i,
                                           ElementType::hex20),
                         [](const auto& element) { return std::string(element_name(element.param)); });

// Pure bending of a beam one hex8i element deep: the incompatible modes make the element exact in
// bending, and the recovered stress must carry them (sigma_xx linear through the depth, +-M c / I at
// the faces), where the plain hex8's would not: it locks in shear.
TEST(StressRecovery, Hex8iBendingStressesIncludeTheIncompatibleModes) {
  const double length = 1.0, depth = 0.1, width = 0.1, curvature = 2e-3;  // kappa [1/m]
  HexBlockSpec block;
  block.corners = {Eigen::Vector3d(0, 0, 0),
                   Eigen::Vector3d(length, 0, 0),
                   Eigen::Vector3d(length, depth, 0),
                   Eigen::Vector3d(0, depth, 0),
                   Eigen::Vector3d(0, 0, width),
                   Eigen::Vector3d(length, 0, width),
                   Eigen::Vector3d(length, depth, width),
                   Eigen::Vector3d(0, depth, width)};
  block.nx = 4;
  block.ny = 1;
  block.nz = 1;
  block.element = ElementType::hex8i;
  const Mesh mesh = generate_hex_block(block);
  // Pure bending about z through y = depth / 2 with nu = 0: u = -kappa x (y - c), v = kappa x^2 / 2.
  // The nodal values of that field are in the hex8i's condensed space (the bubbles take v's parabola).
  fe::PlaneSection material = test::steel_section();
  material.poisson_ratio = 0.0;
  const double c = depth / 2;
  Eigen::MatrixXd u(mesh.n_nodes(), 3);
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const double x = mesh.coords(n, 0), y = mesh.coords(n, 1);
    u.row(n) << -curvature * x * (y - c), 0.5 * curvature * x * x, 0.0;
  }
  const StressField field = recover_stresses(mesh, material, u);
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const double expected = -material.youngs_modulus * curvature * (mesh.coords(n, 1) - c);
    EXPECT_NEAR(field.nodal(n, 0), expected, 1e-9 * std::abs(expected)) << "node " << n + 1;
    EXPECT_NEAR(field.nodal(n, 3), 0.0, 1e-9 * std::abs(expected)) << "no shear in pure bending, node " << n + 1;
  }
}

}  // namespace
}  // namespace bb
