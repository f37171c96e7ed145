// Distributed and body loads (fe/surface_load, assembly/load_vector): consistent shares on one facet,
// resultants that are exact whatever the mesh, and a closed-form pressure vessel (Lame) meshed with
// curved hex20 faces.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/static_analysis.hpp"
#include "assembly/load_vector.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "fe/surface_load.hpp"
#include "mesh/boundary.hpp"
#include "mesh/element_topology.hpp"
#include "mesh/hex_block.hpp"
#include "mesh/mapped_quad.hpp"
#include "solid_test_support.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

// A flat square 8-node face under a uniform pressure: the serendipity shares, -1/12 of p A at each
// corner and 1/3 at each mid-edge node (against the outward normal), the textbook result.
TEST(FacetLoad, FlatHex20FaceSplitsAPressureMinusOneTwelfthAndOneThird) {
  const double a = 0.4, p = 2.5e6, area = a * a;
  Eigen::Matrix<double, 8, 3> xyz;
  xyz << 0, 0, 0, a, 0, 0, a, a, 0, 0, a, 0, a / 2, 0, 0, a, a / 2, 0, a / 2, a, 0, 0, a / 2, 0;  // normal +z
  const Eigen::Matrix<double, 24, 1> f = fe::quad8_face_load(xyz, p, Eigen::Vector3d::Zero());
  for (int n = 0; n < 8; ++n) {
    EXPECT_NEAR(f[3 * n], 0.0, 1e-9 * p * area);
    EXPECT_NEAR(f[3 * n + 1], 0.0, 1e-9 * p * area);
    EXPECT_NEAR(f[3 * n + 2], (n < 4 ? 1.0 / 12.0 : -1.0 / 3.0) * p * area, 1e-9 * p * area) << "node " << n + 1;
  }
  // A traction along x on the same face: corners -1/12, mid-edge nodes +1/3 of t A, along +x.
  const Eigen::Matrix<double, 24, 1> g = fe::quad8_face_load(xyz, 0.0, Eigen::Vector3d(1e6, 0, 0));
  for (int n = 0; n < 8; ++n) EXPECT_NEAR(g[3 * n], (n < 4 ? -1.0 / 12.0 : 1.0 / 3.0) * 1e6 * area, 1e-9 * 1e6 * area);
}

TEST(FacetLoad, BilinearFaceAndEdgeSplitAUniformLoadEqually) {
  const double p = 1e5;
  Eigen::Matrix<double, 4, 3> quad;
  quad << 0, 0, 1, 2, 0, 1, 3, 2, 1, 1, 2, 1;  // a parallelogram in z = 1, counterclockwise from +z: normal +z
  const double area = 2.0 * 2.0;
  const Eigen::Matrix<double, 12, 1> f = fe::quad4_face_load(quad, p, Eigen::Vector3d::Zero());
  for (int n = 0; n < 4; ++n) EXPECT_NEAR(f[3 * n + 2], -0.25 * p * area, 1e-9 * p * area);
  Eigen::Matrix<double, 2, 2> edge;
  edge << 0, 0, 3, 4;  // length 5, outward (right-hand) normal (0.8, -0.6)
  const Eigen::Matrix<double, 4, 1> e = fe::edge2_load(edge, 0.1, p, Eigen::Vector2d(0, 2e5));
  const Eigen::Vector2d per_node = 0.5 * 0.1 * 5.0 * (Eigen::Vector2d(0, 2e5) - p * Eigen::Vector2d(0.8, -0.6));
  EXPECT_NEAR((e.head<2>() - per_node).norm(), 0.0, 1e-9 * p);
  EXPECT_NEAR((e.tail<2>() - per_node).norm(), 0.0, 1e-9 * p);
}

// The quarter of a thick ring, inner radius a, outer b, length L along z: hex elements, mid-edge
// nodes of hex20 on the arcs (curved faces).
Mesh quarter_ring(ElementType type, double a, double b, double length, int nr, int nt, int nz) {
  auto point = [&](int i, int j, int k) {
    const double r = a + (b - a) * i / (2.0 * nr), t = 0.5 * kPi * j / (2.0 * nt);
    return Eigen::Vector3d(r * std::cos(t), r * std::sin(t), length * k / (2.0 * nz));
  };
  const test::HexGrid grid = test::make_hex_grid(nr, nt, nz, nodes_per_element(type), point, [&](int i, int j, int k) {
    const Eigen::Vector3i s(i % 2, j % 2, k % 2);
    return Eigen::Vector3d(point(i, j, k) -
                           0.5 * (point(i - s[0], j - s[1], k - s[2]) + point(i + s[0], j + s[1], k + s[2])));
  });
  return test::mesh_from_grid(grid, type);
}

std::vector<int> nodes_at_radius(const Mesh& mesh, double r) {
  std::vector<int> out;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (std::abs(std::hypot(mesh.coords(n, 0), mesh.coords(n, 1)) - r) < 1e-9) out.push_back(n);
  return out;
}

Eigen::Vector3d resultant(const Eigen::VectorXd& f, int dim) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < f.size(); ++i) r[i % dim] += f[i];
  return r;
}

// The resultant of a uniform pressure on an open surface is -p times its vector area, which depends
// only on the surface's rim: for the inner quarter cylinder -p (a L, a L, 0) whatever the mesh, as long
// as the facets are integrated exactly (a test of every node's share, hex20's mid-edge nodes included).
TEST(SurfaceLoad, PressureResultantOnACurvedFaceIsPressureTimesItsProjectedArea) {
  const double a = 0.1, b = 0.2, length = 0.3, p = 4e6;
  for (ElementType type : {ElementType::hex8, ElementType::hex20}) {
    const Mesh mesh = quarter_ring(type, a, b, length, 2, 5, 2);
    SurfaceLoad load{"inner", SurfaceLoad::Kind::pressure, p, Eigen::Vector3d::Zero()};
    const Eigen::Vector3d r = resultant(surface_load_vector(mesh, 0.0, load, nodes_at_radius(mesh, a)), 3);
    // Outward from the ring's material at r = a is -e_r: a positive pressure pushes along +e_r.
    EXPECT_NEAR(r.x(), p * a * length, 1e-10 * p * a * length) << element_name(type);
    EXPECT_NEAR(r.y(), p * a * length, 1e-10 * p * a * length) << element_name(type);
    EXPECT_NEAR(r.z(), 0.0, 1e-10 * p * a * length) << element_name(type);
  }
  // In 2D: the q4 edges of the outer arc of a quarter annulus (mapped from a rectangle in r, theta).
  MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(a, 0), Eigen::Vector2d(b, 0), Eigen::Vector2d(b, 0.5 * kPi),
                  Eigen::Vector2d(a, 0.5 * kPi)};
  spec.nx = 3;
  spec.ny = 7;
  Mesh annulus = generate_mapped_quad(spec);
  for (int n = 0; n < annulus.n_nodes(); ++n) {
    const double r = annulus.coords(n, 0), t = annulus.coords(n, 1);
    annulus.coords.row(n) << r * std::cos(t), r * std::sin(t);
  }
  const double thickness = 0.01;
  SurfaceLoad outer{"outer", SurfaceLoad::Kind::pressure, -p, Eigen::Vector3d::Zero()};  // a pull, as NAFEMS LE1's
  const Eigen::Vector3d r = resultant(surface_load_vector(annulus, thickness, outer, nodes_at_radius(annulus, b)), 2);
  EXPECT_NEAR(r.x(), p * b * thickness, 1e-10 * p * b * thickness);
  EXPECT_NEAR(r.y(), p * b * thickness, 1e-10 * p * b * thickness);
}

TEST(SurfaceLoad, OnlyBoundaryFacetsWithEveryNodeInTheSetAreLoaded) {
  HexBlockSpec block;
  block.corners = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(2, 1, 0),
                   Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(2, 0, 1),
                   Eigen::Vector3d(2, 1, 1), Eigen::Vector3d(0, 1, 1)};
  block.nx = 2;
  block.element = ElementType::hex20;
  const Mesh mesh = generate_hex_block(block);
  // The plane x = 1 cuts through the middle: its face is interior, it must carry nothing.
  std::vector<int> middle, top_corners;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    if (std::abs(mesh.coords(n, 0) - 1) < 1e-12) middle.push_back(n);
    const bool corner_x = std::abs(mesh.coords(n, 0)) < 1e-12 || std::abs(mesh.coords(n, 0) - 2) < 1e-12 ||
                          std::abs(mesh.coords(n, 0) - 1) < 1e-12;
    const bool corner_y = std::abs(mesh.coords(n, 1)) < 1e-12 || std::abs(mesh.coords(n, 1) - 1) < 1e-12;
    if (std::abs(mesh.coords(n, 2) - 1) < 1e-12 && corner_x && corner_y) top_corners.push_back(n);
  }
  EXPECT_TRUE(boundary_facets_within(mesh, middle).empty());
  // The top face's corners without its mid-edge nodes: a hex20 face is not loaded without them.
  EXPECT_TRUE(boundary_facets_within(mesh, top_corners).empty());
  const SurfaceLoad load{"middle", SurfaceLoad::Kind::pressure, 1e5, Eigen::Vector3d::Zero()};
  EXPECT_THROW(surface_load_vector(mesh, 0.0, load, middle), InputError);
}

// Body loads through the consistent mass: the resultant of gravity is the weight, that of a
// rotation about z the mass times Omega^2 times the distance of the centre of mass from the axis.
TEST(BodyLoad, GravityAndCentrifugalResultantsAreExactForEveryElement) {
  const double rho = 7800.0, omega = 120.0;
  for (ElementType type : {ElementType::hex8, ElementType::hex8i, ElementType::hex20}) {
    HexBlockSpec block;
    block.corners = {Eigen::Vector3d(0.5, 0, 0),     Eigen::Vector3d(1.5, 0, 0),    Eigen::Vector3d(1.5, 0.1, 0),
                     Eigen::Vector3d(0.5, 0.1, 0),   Eigen::Vector3d(0.5, 0, 0.2),  Eigen::Vector3d(1.5, 0, 0.2),
                     Eigen::Vector3d(1.5, 0.1, 0.2), Eigen::Vector3d(0.5, 0.1, 0.2)};
    block.nx = 5;
    block.ny = 2;
    block.nz = 3;
    block.element = type;
    const Mesh mesh = generate_hex_block(block);
    const fe::PlaneSection material{2e11, 0.3, rho, 0.0};
    const double mass = rho * 1.0 * 0.1 * 0.2;
    BodyLoad gravity;
    gravity.acceleration = Eigen::Vector3d(0, -9.81, 0);
    EXPECT_NEAR((resultant(body_load_vector(mesh, material, gravity), 3) - mass * gravity.acceleration).norm(), 0.0,
                1e-9 * mass * 9.81)
        << element_name(type);
    BodyLoad spin;
    spin.kind = BodyLoad::Kind::centrifugal;
    spin.speed = omega;
    spin.axis = Eigen::Vector3d::UnitZ();
    spin.origin = Eigen::Vector3d(0, 0.05, 0);  // through the bar's mid-height: no net y force
    const Eigen::Vector3d r = resultant(body_load_vector(mesh, material, spin), 3);
    EXPECT_NEAR(r.x(), mass * omega * omega * 1.0, 1e-9 * mass * omega * omega) << element_name(type);
    EXPECT_NEAR(r.y(), 0.0, 1e-9 * mass * omega * omega) << element_name(type);
    EXPECT_NEAR(r.z(), 0.0, 1e-9 * mass * omega * omega) << element_name(type);
  }
}

// Lame's thick cylinder under internal pressure p, plane strain (u_z = 0), quarter model of hex20
// with curved faces: u_r(a) = (1 + nu) / E [(1 - 2 nu) A a + B / a], A = p a^2 / (b^2 - a^2),
// B = p a^2 b^2 / (b^2 - a^2), and the hoop stress at the bore A + B / a^2 (Timoshenko & Goodier,
// Theory of Elasticity, sec. 28). The pressure, the curved faces and the recovery together.
TEST(SurfaceLoad, Hex20ThickCylinderMatchesLame) {
  const double a = 0.1, b = 0.2, length = 0.05, p = 1e8, e = 2e11, nu = 0.3;
  Model model;
  model.mesh = quarter_ring(ElementType::hex20, a, b, length, 8, 8, 1);
  model.section = {e, nu, 7800.0, 0.0};
  auto select = [&](const std::string& name, auto&& on) {
    for (int n = 0; n < model.mesh.n_nodes(); ++n)
      if (on(model.mesh.coords.row(n))) model.node_sets[name].push_back(n);
  };
  select("x0", [](const auto& x) { return std::abs(x[0]) < 1e-12; });
  select("y0", [](const auto& x) { return std::abs(x[1]) < 1e-12; });
  select("ends", [&](const auto& x) { return std::abs(x[2]) < 1e-12 || std::abs(x[2] - length) < 1e-12; });
  model.node_sets["bore"] = nodes_at_radius(model.mesh, a);
  model.constraints = {{"x0", {0}, 0.0}, {"y0", {1}, 0.0}, {"ends", {2}, 0.0}};
  model.surface_loads.push_back({"bore", SurfaceLoad::Kind::pressure, p, Eigen::Vector3d::Zero()});
  ResultTables tables;
  const StaticOutcome o = run_static(model, StaticSpec{}, tables);
  const double big_a = p * a * a / (b * b - a * a), big_b = p * a * a * b * b / (b * b - a * a);
  const double u_bore = (1 + nu) / e * ((1 - 2 * nu) * big_a * a + big_b / a);
  const double hoop_bore = big_a + big_b / (a * a);
  for (int n : model.node_sets["bore"]) {
    const Eigen::Vector3d x = model.mesh.coords.row(n).transpose();
    const Eigen::Vector3d radial(x.x() / a, x.y() / a, 0.0);
    const double ur = o.solution.displacements.row(n).dot(radial);
    // 8 quadratic elements through the wall, 8 around the quarter: the displacement within 1e-5
    // (measured -3.8e-7 at the corner nodes, -6.1e-6 at the mid-arc nodes, where the quadratic arc
    // departs most from the circle; with 4 through the wall -4.2e-5).
    EXPECT_NEAR(ur / u_bore, 1.0, 1e-5) << "node " << n + 1;
    // Hoop stress sigma_tt = t^T sigma t with t = (-sin, cos): the extrapolated nodal stress at the
    // bore, where the 1 / r^2 gradient is steepest, within 0.5 % (measured +0.35 to +0.37 %; with 4
    // elements +1.1 to +1.2 %: order 1.7, the derivative's rate on this mesh).
    const Eigen::Vector2d t(-radial.y(), radial.x());
    const Eigen::RowVectorXd s = o.stresses.nodal.row(n);  // xx yy zz xy yz zx
    const double hoop = t.x() * t.x() * s[0] + t.y() * t.y() * s[1] + 2 * t.x() * t.y() * s[3];
    EXPECT_NEAR(hoop / hoop_bore, 1.0, 1e-2) << "node " << n + 1;
  }
}

}  // namespace
}  // namespace bb
