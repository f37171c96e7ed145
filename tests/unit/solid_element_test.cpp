// Element matrices of fe/solid (hex8, hex8 with incompatible modes, hex20): the properties any
// correct 3D solid element must have (symmetry, definiteness, exactly the six rigid-body modes in
// the null space, exact constant-strain energy, objectivity, total mass), checked on a unit cube
// and on distorted shapes; closed forms on boxes; patch tests on distorted 2x2x2 patches; and the
// bending behaviour that distinguishes the three elements on a slender cantilever.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fe/solid.hpp"
#include "solid_test_support.hpp"
#include "stiffness_checks.hpp"

namespace bb {
namespace {

using test::LinearField3;
using test::SolidKind;

struct SolidShape {
  std::string name;
  SolidKind kind;
  Eigen::MatrixXd xyz;
  double exact_volume = 0.0;  // known in closed form, or 0 when not

  // The exact volume where known; otherwise the element's own Gauss volume, which is what its
  // matrices integrate (exact anyway for straight-edged shapes, see HexVolume below).
  double volume() const { return exact_volume > 0.0 ? exact_volume : test::solid_volume(kind, xyz); }
};

void PrintTo(const SolidShape& s, std::ostream* os) { *os << s.name; }

fe::Hex8Coords unit_cube() {
  fe::Hex8Coords xyz = 0.5 * (test::hex20_natural_nodes().topRows<8>().array() + 1.0);
  return xyz;
}

// Unit cube with every corner moved by up to 15% of the edge: no face is planar, no two edges are
// parallel, so the Jacobian varies over the element in every direction.
fe::Hex8Coords distorted_hex8() {
  fe::Hex8Coords perturbation;
  perturbation << 0.08, -0.11, 0.05, -0.12, 0.07, -0.09, 0.13, 0.10, 0.06, -0.06, -0.14, 0.11,  //
      0.10, 0.04, -0.13, -0.09, 0.12, 0.14, 0.05, -0.08, -0.07, 0.14, 0.09, -0.12;
  return unit_cube() + perturbation;
}

// The distorted corners, with every mid-edge node moved off its edge's midpoint (curved edges).
fe::Hex20Coords distorted_hex20() {
  fe::Hex20Coords xyz = test::hex20_from_corners(distorted_hex8());
  Eigen::Matrix<double, 12, 3> offset;
  offset << 0.03, -0.02, 0.04, -0.04, 0.03, 0.01, 0.02, 0.04, -0.03, -0.01, -0.03, 0.02,  //
      0.04, 0.01, -0.02, -0.03, -0.04, 0.03, 0.01, 0.02, 0.04, -0.02, 0.03, -0.04,        //
      0.03, -0.01, 0.02, -0.04, 0.02, -0.01, 0.02, 0.03, 0.01, -0.01, -0.04, -0.03;
  xyz.bottomRows<12>() += offset;
  return xyz;
}

// Affine image of the unit cube: volume det(A), constant Jacobian.
Eigen::Matrix3d parallelepiped_map() {
  Eigen::Matrix3d a;
  a << 1.2, 0.3, -0.2, 0.1, 0.9, 0.25, 0.15, -0.1, 1.1;
  return a;
}

fe::Hex8Coords parallelepiped_hex8() {
  fe::Hex8Coords xyz = unit_cube() * parallelepiped_map().transpose();
  return xyz.rowwise() + Eigen::RowVector3d(0.4, -1.0, 2.0);
}

SolidShape shape(SolidKind kind, const std::string& geometry, const fe::Hex8Coords& corners,
                 double exact_volume = 0.0) {
  SolidShape s{test::solid_kind_name(kind) + geometry, kind, corners, exact_volume};
  if (kind == SolidKind::hex20) s.xyz = test::hex20_from_corners(corners);
  return s;
}

std::vector<SolidShape> stiffness_shapes() {
  std::vector<SolidShape> out;
  for (SolidKind kind : {SolidKind::hex8, SolidKind::hex8i, SolidKind::hex20}) {
    out.push_back(shape(kind, "UnitCube", unit_cube(), 1.0));
    out.push_back(shape(kind, "Distorted", distorted_hex8()));
  }
  out.push_back({"Hex20DistortedCurvedEdges", SolidKind::hex20, distorted_hex20(), 0.0});
  return out;
}

std::vector<SolidShape> mass_shapes() {
  std::vector<SolidShape> out;
  for (SolidKind kind : {SolidKind::hex8, SolidKind::hex20}) {
    out.push_back(shape(kind, "Parallelepiped", parallelepiped_hex8(), parallelepiped_map().determinant()));
    out.push_back(shape(kind, "Distorted", distorted_hex8()));
  }
  out.push_back({"Hex20DistortedCurvedEdges", SolidKind::hex20, distorted_hex20(), 0.0});
  return out;
}

Eigen::Matrix3d rotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
}

// Element-level properties of the stiffness.
class SolidElementStiffness : public ::testing::TestWithParam<SolidShape> {
 protected:
  fe::SolidMaterial material = test::steel_solid();
  Eigen::MatrixXd k() const { return test::solid_stiffness(GetParam().kind, GetParam().xyz, material); }
};

TEST_P(SolidElementStiffness, IsSymmetric) {
  const Eigen::MatrixXd kk = k();
  EXPECT_EQ((kk - kk.transpose()).norm(), 0.0);
}

TEST_P(SolidElementStiffness, HasExactlySixZeroEnergyModesAndIsOtherwisePositive) {
  // The seventh is a genuine deformation mode (no hourglass mode), well clear of round-off.
  EXPECT_TRUE(test::has_exactly_zero_energy_modes(k(), 6, 1e-3));
}

TEST_P(SolidElementStiffness, RigidBodyMotionsAreInTheNullSpace) {
  const Eigen::MatrixXd kk = k();
  const Eigen::MatrixXd r = test::rigid_body_modes_3d(GetParam().xyz);
  for (int c = 0; c < 6; ++c) {
    EXPECT_LE((kk * r.col(c)).norm(), 1e-12 * kk.norm() * r.col(c).norm()) << "rigid mode " << c;
  }
  // Rotation about an axis far from the element: large translation plus rotation.
  const Eigen::VectorXd moved =
      r.rightCols<3>() * Eigen::Vector3d(0.3, -1.0, 0.6) + r.leftCols<3>() * Eigen::Vector3d(7.0, -3.0, 5.0);
  EXPECT_LE((kk * moved).norm(), 1e-12 * kk.norm() * moved.norm());
}

TEST_P(SolidElementStiffness, UniformStrainEnergyEqualsHalfEpsDEpsTimesVolume) {
  // The single-element patch test. Isoparametric interpolation reproduces a linear field exactly,
  // so B u = eps at every Gauss point and u^T K u = eps^T D eps * sum(w det J), whatever the shape.
  // For hex8i it holds only because Taylor's correction makes the bubbles orthogonal to constant
  // stress; without it the distorted hex8i would come out too soft.
  const SolidShape& s = GetParam();
  const Eigen::MatrixXd kk = k();
  const fe::Matrix6 d = fe::isotropic_elasticity(material.youngs_modulus, material.poisson_ratio);
  const double volume = s.volume();
  Eigen::Matrix3d shear_and_spin;
  shear_and_spin << 0.0, 1e-3, 0.0, 0.5e-3, 0.0, -2e-3, 0.0, 1e-3, 0.0;
  Eigen::Matrix3d general;
  general << 3e-4, 1.2e-3, -4e-4, -2e-4, 7e-4, 5e-4, 9e-4, -6e-4, -1.1e-3;
  const Eigen::Matrix3d stretch_x = Eigen::Vector3d(1e-3, 0, 0).asDiagonal();
  const Eigen::Matrix3d squeeze_z = Eigen::Vector3d(0, 0, -2e-3).asDiagonal();
  for (const Eigen::Matrix3d& grad : {stretch_x, squeeze_z, shear_and_spin, general}) {
    const LinearField3 f{Eigen::Vector3d(1e-3, -2e-3, 4e-4), grad};
    const Eigen::VectorXd u = test::sample_field(f, s.xyz);
    const Eigen::Matrix<double, 6, 1> eps = f.strain();
    const double expected = eps.dot(d * eps) * volume;
    EXPECT_NEAR(u.dot(kk * u), expected, 1e-11 * expected) << "grad =\n" << grad;
  }
}

TEST_P(SolidElementStiffness, IsObjectiveUnderRigidRotationOfTheElement) {
  // Isotropy: rotating and translating the element, x' = R x + c, rotates K as T K T^T with
  // T = blockdiag(R, R, ...).
  const SolidShape& s = GetParam();
  const Eigen::Matrix3d rot = rotation();
  const Eigen::MatrixXd turned = (s.xyz * rot.transpose()).rowwise() + Eigen::RowVector3d(5.0, -2.0, 3.0);
  const Eigen::MatrixXd kk = k();
  const Eigen::MatrixXd k_turned = test::solid_stiffness(s.kind, turned, material);
  const Eigen::Index n = s.xyz.rows();
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (Eigen::Index a = 0; a < n; ++a) t.block<3, 3>(3 * a, 3 * a) = rot;
  EXPECT_LE((k_turned - t * kk * t.transpose()).norm(), 1e-12 * kk.norm());
}

TEST_P(SolidElementStiffness, InvertedElementThrowsDomainErrorNamingTheDeterminant) {
  // Top and bottom faces swapped: the same solid, but the map from natural coordinates turns it
  // inside out, det J < 0 everywhere.
  SolidShape s = GetParam();
  const Eigen::MatrixXd original = s.xyz;
  s.xyz.middleRows(0, 4) = original.middleRows(4, 4);
  s.xyz.middleRows(4, 4) = original.middleRows(0, 4);
  if (s.kind == SolidKind::hex20) {
    s.xyz.middleRows(8, 4) = original.middleRows(12, 4);
    s.xyz.middleRows(12, 4) = original.middleRows(8, 4);
  }
  EXPECT_THROW(test::solid_stiffness(s.kind, s.xyz, material), std::domain_error);
  EXPECT_THROW(test::solid_mass(s.kind, s.xyz, material), std::domain_error);
  EXPECT_THROW(test::solid_volume(s.kind, s.xyz), std::domain_error);
  try {
    test::solid_stiffness(s.kind, s.xyz, material);
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("determinant -"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Solid, SolidElementStiffness, ::testing::ValuesIn(stiffness_shapes()),
                         [](const ::testing::TestParamInfo<SolidShape>& param_info) { return param_info.param.name; });

TEST(SolidElementStiffnessPartiallyInverted, ElementFoldedAtOneCornerThrowsDomainError) {
  // Corner 7 pushed through the opposite corner: det J changes sign inside the element, so only
  // some Gauss points see a negative determinant.
  fe::Hex8Coords xyz = unit_cube();
  xyz.row(6) << -0.2, -0.2, -0.2;
  const fe::SolidMaterial m = test::steel_solid();
  EXPECT_THROW(fe::hex8_stiffness(xyz, m), std::domain_error);
  EXPECT_THROW(fe::hex8_incompatible_stiffness(xyz, m), std::domain_error);
  EXPECT_THROW(fe::hex20_stiffness(test::hex20_from_corners(xyz), m), std::domain_error);
}

// Element-level properties of the consistent mass (hex8i uses the hex8 mass).
class SolidElementMass : public ::testing::TestWithParam<SolidShape> {
 protected:
  fe::SolidMaterial material = test::steel_solid();
  Eigen::MatrixXd m() const { return test::solid_mass(GetParam().kind, GetParam().xyz, material); }
};

TEST_P(SolidElementMass, IsSymmetricPositiveDefinite) {
  const Eigen::MatrixXd mm = m();
  EXPECT_EQ((mm - mm.transpose()).norm(), 0.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(mm);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-4 * eig.eigenvalues().maxCoeff()) << eig.eigenvalues().transpose();
}

TEST_P(SolidElementMass, EachDirectionSumsToTheElementMassWithNoCouplingBetweenDirections) {
  const SolidShape& s = GetParam();
  const Eigen::MatrixXd mm = m();
  const double total = material.density * s.volume();
  const Eigen::Index n = s.xyz.rows();
  Eigen::Vector3d sums = Eigen::Vector3d::Zero();
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index c = 0; c < n; ++c)
      for (int i = 0; i < 3; ++i) {
        sums[i] += mm(3 * a + i, 3 * c + i);
        for (int j = 0; j < 3; ++j) {
          if (i != j) {
            ASSERT_EQ(mm(3 * a + i, 3 * c + j), 0.0) << "direction coupling at nodes " << a << ", " << c;
          }
        }
      }
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(sums[i], total, 1e-13 * total) << "direction " << i;
  // Equivalently: a rigid translation with unit speed carries kinetic energy 1/2 m.
  const Eigen::MatrixXd r = test::rigid_body_modes_3d(s.xyz);
  EXPECT_NEAR(r.col(2).dot(mm * r.col(2)), total, 1e-13 * total);
}

INSTANTIATE_TEST_SUITE_P(Solid, SolidElementMass, ::testing::ValuesIn(mass_shapes()),
                         [](const ::testing::TestParamInfo<SolidShape>& param_info) { return param_info.param.name; });

TEST(SolidElasticity, MatchesHookesLawForUniaxialStressAndPureShear) {
  const double e = 7.0e10, nu = 0.33, s = 1.0e8, g = e / (2 * (1 + nu));
  const fe::Matrix6 d = fe::isotropic_elasticity(e, nu);
  Eigen::Matrix<double, 6, 1> uniaxial;
  uniaxial << -nu * s / e, s / e, -nu * s / e, 0, 0, 0;  // sigma_yy = s, all else free
  Eigen::Matrix<double, 6, 1> expected = Eigen::Matrix<double, 6, 1>::Zero();
  expected[1] = s;
  EXPECT_LE((d * uniaxial - expected).norm(), 1e-9 * s);
  for (int shear = 3; shear < 6; ++shear) {  // engineering shear: tau = G gamma
    const Eigen::Matrix<double, 6, 1> tau = d * Eigen::Matrix<double, 6, 1>::Unit(shear) * 1e-3;
    EXPECT_NEAR(tau[shear], g * 1e-3, 1e-12 * g) << "component " << shear;
    EXPECT_NEAR(tau.norm(), g * 1e-3, 1e-12 * g) << "component " << shear;
  }
  EXPECT_LE((d - d.transpose()).norm(), 0.0);
}

// Box [0, a] x [0, b] x [0, c]: N_i = phi_i(x) psi_i(y) chi_i(z) with linear 1D factors, so
// integral of dN_i/dx_p dN_j/dx_q is a product of three 1D integrals. K_ij = sum_pq E_p^T D E_q
// I_ij(p, q), where B_i = sum_p E_p dN_i/dx_p. Independent of the isoparametric map, the Gauss
// rule and the gradient-product accumulation of the implementation.
fe::Matrix24 box_stiffness_closed_form(const Eigen::Vector3d& size, const fe::SolidMaterial& m) {
  const Eigen::Matrix<double, 8, 3> nat = test::hex20_natural_nodes().topRows<8>();
  const fe::Matrix6 d = fe::isotropic_elasticity(m.youngs_modulus, m.poisson_ratio);
  std::array<Eigen::Matrix<double, 6, 3>, 3> e{};
  for (auto& ep : e) ep.setZero();
  e[0](0, 0) = 1;
  e[0](3, 1) = 1;
  e[0](5, 2) = 1;  // d/dx: xx <- ux, xy <- uy, zx <- uz
  e[1](1, 1) = 1;
  e[1](3, 0) = 1;
  e[1](4, 2) = 1;  // d/dy: yy <- uy, xy <- ux, yz <- uz
  e[2](2, 2) = 1;
  e[2](4, 1) = 1;
  e[2](5, 0) = 1;  // d/dz: zz <- uz, yz <- uy, zx <- ux
  // 1D integrals over [0, L] of linear hats s, t in {-1, +1}: value*value, value*slope, slope*slope.
  auto vv = [](double s, double t, double len) { return s == t ? len / 3 : len / 6; };
  auto vd = [](double, double t, double) { return 0.5 * t; };  // integral of phi_s phi_t' = t/2
  auto dd = [](double s, double t, double len) { return s * t / len; };
  fe::Matrix24 k = fe::Matrix24::Zero();
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      Eigen::Matrix3d integral;  // integral of dN_i/dx_p dN_j/dx_q
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) {
          double prod = 1.0;
          for (int dir = 0; dir < 3; ++dir) {
            const double si = nat(i, dir), sj = nat(j, dir), len = size[dir];
            const bool di = dir == p, dj = dir == q;
            if (di && dj)
              prod *= dd(si, sj, len);
            else if (di)
              prod *= vd(sj, si, len);
            else if (dj)
              prod *= vd(si, sj, len);
            else
              prod *= vv(si, sj, len);
          }
          integral(p, q) = prod;
        }
      Eigen::Matrix3d kij = Eigen::Matrix3d::Zero();
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) kij += e[p].transpose() * d * e[q] * integral(p, q);
      k.block<3, 3>(3 * i, 3 * j) = kij;
    }
  return k;
}

fe::Hex8Coords box(const Eigen::Vector3d& size) {
  fe::Hex8Coords xyz = unit_cube() * size.asDiagonal();
  return xyz;
}

TEST(Hex8Box, StiffnessMatchesClosedFormIntegral) {
  const fe::SolidMaterial m = test::steel_solid();
  const Eigen::Vector3d size(2.0, 0.5, 0.8);
  const fe::Matrix24 k = fe::hex8_stiffness(box(size), m);
  const fe::Matrix24 expected = box_stiffness_closed_form(size, m);
  EXPECT_LE((k - expected).norm(), 1e-13 * expected.norm());
  // Textbook entry of the unit cube: k11 = (lambda + 4 mu) / 9 * a.
  const double lambda = m.youngs_modulus * m.poisson_ratio / ((1 + m.poisson_ratio) * (1 - 2 * m.poisson_ratio));
  const double mu = m.youngs_modulus / (2 * (1 + m.poisson_ratio));
  EXPECT_NEAR(fe::hex8_stiffness(unit_cube(), m)(0, 0), (lambda + 4 * mu) / 9, 1e-13 * mu);
}

TEST(Hex8Box, ConsistentMassMatchesClosedForm) {
  // Per direction: rho * prod over x, y, z of (L/3 if the two nodes share the coordinate, else L/6).
  const fe::SolidMaterial m = test::steel_solid();
  const Eigen::Vector3d size(2.0, 0.5, 0.8);
  const fe::Matrix24 mass = fe::hex8_consistent_mass(box(size), m);
  const Eigen::Matrix<double, 8, 3> nat = test::hex20_natural_nodes().topRows<8>();
  for (int a = 0; a < 8; ++a)
    for (int c = 0; c < 8; ++c) {
      double expected = m.density;
      for (int dir = 0; dir < 3; ++dir) expected *= nat(a, dir) == nat(c, dir) ? size[dir] / 3 : size[dir] / 6;
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(mass(3 * a + i, 3 * c + i), expected, 1e-12 * expected) << a << "," << c;
    }
}

TEST(Hex20Parallelepiped, ConsistentMassRowSumsAreMinusOneEighthAtCornersAndOneSixthAtMidEdges) {
  // Row sum = rho * integral of N_a (the N sum to one). For the serendipity brick with a constant
  // Jacobian, the corner integrals are -V/8 and the mid-edge integrals V/6: the reason row-sum
  // lumping is unusable for hex20.
  const fe::SolidMaterial m = test::steel_solid();
  const fe::Matrix60 mass = fe::hex20_consistent_mass(test::hex20_from_corners(parallelepiped_hex8()), m);
  const double total = m.density * parallelepiped_map().determinant();
  for (int a = 0; a < 20; ++a) {
    const double expected = a < 8 ? -total / 8 : total / 6;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mass.row(3 * a + i).sum(), expected, 1e-12 * total) << "node " << a + 1;
  }
}

TEST(HexVolume, ParallelepipedVolumeIsExact) {
  const double exact = parallelepiped_map().determinant();
  EXPECT_NEAR(fe::hex8_volume(parallelepiped_hex8()), exact, 1e-14 * exact);
  EXPECT_NEAR(fe::hex20_volume(test::hex20_from_corners(parallelepiped_hex8())), exact, 1e-14 * exact);
  EXPECT_NEAR(fe::hex8_volume(box(Eigen::Vector3d(2.0, 0.5, 0.8))), 0.8, 1e-15);
}

// Distorted 2x2x2 patch filling the unit cube: corners move by up to `amplitude` along every
// direction in which they are not on the cube's boundary, so the outer faces stay the cube's.
Eigen::Vector3d patch_offset(int i, int j, int k, int n, double amplitude) {
  Eigen::Vector3d off;
  const int idx[3] = {i, j, k};
  for (int d = 0; d < 3; ++d) {
    const bool on_face = idx[d] == 0 || idx[d] == 2 * n;
    off[d] = on_face ? 0.0 : amplitude * std::sin(1.3 * i + 2.9 * j + 4.7 * k + 2.1 * d + 0.4);
  }
  return off;
}

test::HexGrid distorted_patch(int nodes_per_element, bool curved_edges) {
  constexpr int n = 2;
  auto corner = [](int i, int j, int k) -> Eigen::Vector3d {  // a plain vector, not an expression
    return Eigen::Vector3d(i, j, k) / (2.0 * n) + patch_offset(i, j, k, n, 0.1);
  };
  test::LatticeMap midedge = nullptr;
  if (curved_edges) midedge = [](int i, int j, int k) { return patch_offset(i, j, k, n, 0.03); };
  return test::make_hex_grid(n, n, n, nodes_per_element, corner, midedge);
}

TEST(HexVolume, DistortedPatchVolumesSumToTheCube) {
  // 2x2x2 Gauss integrates det J of a trilinear map exactly, as does 3x3x3 for a hex20 with
  // straight edges: the distorted elements must tile the unit cube exactly.
  for (int nodes : {8, 20}) {
    const test::HexGrid g = distorted_patch(nodes, false);
    double total = 0.0;
    for (size_t e = 0; e < g.elements.size(); ++e) {
      total += test::solid_volume(nodes == 8 ? SolidKind::hex8 : SolidKind::hex20, g.element_coords(e));
    }
    EXPECT_NEAR(total, 1.0, 1e-14) << nodes << "-node patch";
  }
}

TEST(Hex8Incompatible, CondensedBubblesOnlySoftenTheHex8ByAtMostNineModes) {
  // K_hex8 - K_hex8i = K_ua K_aa^-1 K_au: positive semi-definite, rank <= 9 (one per bubble DOF).
  const fe::SolidMaterial m = test::steel_solid();
  for (const fe::Hex8Coords& xyz : {unit_cube(), distorted_hex8()}) {
    const fe::Matrix24 diff = fe::hex8_stiffness(xyz, m) - fe::hex8_incompatible_stiffness(xyz, m);
    const Eigen::SelfAdjointEigenSolver<fe::Matrix24> eig(diff);
    const double largest = eig.eigenvalues().maxCoeff();
    ASSERT_GT(largest, 0.0);
    int nonzero = 0;
    for (Eigen::Index i = 0; i < 24; ++i) {
      EXPECT_GT(eig.eigenvalues()[i], -1e-10 * largest);
      if (eig.eigenvalues()[i] > 1e-10 * largest) ++nonzero;
    }
    EXPECT_LE(nonzero, 9);
  }
}

// Patch test on a distorted 2x2x2 mesh: a linear field prescribed on the boundary nodes must be
// reproduced exactly at the interior nodes (the interior corner, and for hex20 the mid-edge nodes
// around it), for any admissible distortion.
struct PatchCase {
  std::string name;
  SolidKind kind;
  bool curved_edges;
};

void PrintTo(const PatchCase& p, std::ostream* os) { *os << p.name; }

class SolidPatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(SolidPatchTest, LinearFieldOnTheBoundaryIsReproducedInside) {
  const PatchCase& pc = GetParam();
  const fe::SolidMaterial m = test::steel_solid();
  const test::HexGrid g = distorted_patch(test::solid_kind_nodes(pc.kind), pc.curved_edges);
  const Eigen::MatrixXd k = test::assemble_dense(g, pc.kind, m);
  Eigen::Matrix3d grad;
  grad << 1.1e-3, -0.4e-3, 0.7e-3, 0.3e-3, -0.8e-3, 0.2e-3, -0.5e-3, 0.9e-3, 0.6e-3;
  const LinearField3 f{Eigen::Vector3d(2e-3, -1e-3, 0.5e-3), grad};
  const Eigen::VectorXd exact = test::sample_field(f, g.coords);
  std::vector<bool> fixed(static_cast<size_t>(g.n_dofs()), false);
  int interior = 0;
  for (int a = 0; a < static_cast<int>(g.coords.rows()); ++a) {
    const bool boundary = g.on_boundary(a);
    interior += boundary ? 0 : 1;
    for (int d = 0; d < 3; ++d) fixed[static_cast<size_t>(3 * a + d)] = boundary;
  }
  ASSERT_EQ(interior, pc.kind == SolidKind::hex20 ? 7 : 1);  // centre corner (+ 6 mid-edge nodes)
  Eigen::VectorXd prescribed = exact;
  for (size_t i = 0; i < fixed.size(); ++i) {
    if (!fixed[i]) prescribed[static_cast<Eigen::Index>(i)] = 0.0;  // not used, but no hint either
  }
  const Eigen::VectorXd u = test::solve_with_prescribed(k, Eigen::VectorXd::Zero(g.n_dofs()), fixed, prescribed);
  EXPECT_LE((u - exact).lpNorm<Eigen::Infinity>(), 1e-9 * exact.lpNorm<Eigen::Infinity>());
  if (!pc.curved_edges) {
    // The strain is uniform, so the total energy is eps^T D eps times the cube's volume.
    const Eigen::Matrix<double, 6, 1> eps = f.strain();
    const double expected = eps.dot(fe::isotropic_elasticity(m.youngs_modulus, m.poisson_ratio) * eps);
    EXPECT_NEAR(u.dot(k * u), expected, 1e-10 * expected);
  }
}

INSTANTIATE_TEST_SUITE_P(Solid, SolidPatchTest,
                         ::testing::Values(PatchCase{"Hex8", SolidKind::hex8, false},
                                           PatchCase{"Hex8Incompatible", SolidKind::hex8i, false},
                                           PatchCase{"Hex20", SolidKind::hex20, false},
                                           PatchCase{"Hex20CurvedEdges", SolidKind::hex20, true}),
                         [](const ::testing::TestParamInfo<PatchCase>& param_info) { return param_info.param.name; });

// Slender cantilever L x h x h = 10 x 1 x 1 (one row of ten cubes), clamped at x = 0, with a
// transverse tip force P in z. Reference: Timoshenko beam, P L^3 / (3 E I) + P L / (kappa G A),
// kappa = 10 (1 + nu) / (12 + 11 nu) (Cowper). The shear term is ~1% of the bending term here.
class HexCantilever : public ::testing::Test {
 protected:
  static constexpr int kElements = 10;
  static constexpr double kLength = 10.0, kHeight = 1.0, kForce = 1.0e5;
  fe::SolidMaterial material = test::steel_solid();

  double timoshenko_tip_deflection() const {
    const double e = material.youngs_modulus, nu = material.poisson_ratio;
    const double inertia = kHeight * kHeight * kHeight * kHeight / 12, area = kHeight * kHeight;
    const double kappa = 10 * (1 + nu) / (12 + 11 * nu);
    const double shear_modulus = e / (2 * (1 + nu));
    return kForce * kLength * kLength * kLength / (3 * e * inertia) + kForce * kLength / (kappa * shear_modulus * area);
  }

  // Tip deflection (mean u_z of the four tip corners). `skew` tilts the interior cross-sections
  // alternately (trapezoidal elements).
  double tip_deflection(SolidKind kind, double skew) const {
    const int n = kElements;
    auto corner = [skew](int i, int j, int k) {
      const double y = 0.5 * j * kHeight, z = 0.5 * k * kHeight;
      const int section = i / 2;
      double x = section * kLength / n;
      if (section > 0 && section < n) x += (section % 2 == 0 ? skew : -skew) * ((y - 0.5) + 0.6 * (z - 0.5));
      return Eigen::Vector3d(x, y, z);
    };
    const test::HexGrid g = test::make_hex_grid(n, 1, 1, test::solid_kind_nodes(kind), corner);
    const Eigen::MatrixXd k = test::assemble_dense(g, kind, material);
    std::vector<bool> fixed(static_cast<size_t>(g.n_dofs()), false);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(g.n_dofs());
    std::vector<int> tip_corners;
    for (int a = 0; a < static_cast<int>(g.coords.rows()); ++a) {
      const Eigen::Vector3i& l = g.lattice[static_cast<size_t>(a)];
      if (l[0] == 0) {
        for (int d = 0; d < 3; ++d) fixed[static_cast<size_t>(3 * a + d)] = true;
      } else if (l[0] == 2 * n) {
        // Consistent nodal forces of a uniform traction on the tip face: 1/4 per corner of a
        // bilinear face; -1/12 per corner and 1/3 per mid-edge node of a serendipity face.
        const bool is_corner = l[1] % 2 == 0 && l[2] % 2 == 0;
        if (is_corner) tip_corners.push_back(a);
        const double share = kind != SolidKind::hex20 ? 0.25 : (is_corner ? -1.0 / 12 : 1.0 / 3);
        f[3 * a + 2] = share * kForce;
      }
    }
    EXPECT_NEAR(f.sum(), kForce, 1e-9 * kForce);
    const Eigen::VectorXd u = test::solve_with_prescribed(k, f, fixed, Eigen::VectorXd::Zero(g.n_dofs()));
    double tip = 0.0;
    for (int a : tip_corners) tip += u[3 * a + 2];
    return tip / static_cast<double>(tip_corners.size());
  }
};

TEST_F(HexCantilever, Hex8LocksInShearAndIsFarTooStiff) {
  const double ratio = tip_deflection(SolidKind::hex8, 0.0) / timoshenko_tip_deflection();
  EXPECT_LT(ratio, 0.8) << "hex8 / Timoshenko = " << ratio;
  EXPECT_GT(ratio, 0.3) << "hex8 / Timoshenko = " << ratio;
}

TEST_F(HexCantilever, Hex8IncompatibleMatchesBeamTheory) {
  const double ratio = tip_deflection(SolidKind::hex8i, 0.0) / timoshenko_tip_deflection();
  EXPECT_NEAR(ratio, 1.0, 0.03) << "hex8i / Timoshenko = " << ratio;
}

TEST_F(HexCantilever, Hex20MatchesBeamTheory) {
  const double ratio = tip_deflection(SolidKind::hex20, 0.0) / timoshenko_tip_deflection();
  EXPECT_NEAR(ratio, 1.0, 0.03) << "hex20 / Timoshenko = " << ratio;
}

TEST_F(HexCantilever, Hex20OnTrapezoidalElementsStillMatchesBeamTheory) {
  const double ratio = tip_deflection(SolidKind::hex20, 0.3) / timoshenko_tip_deflection();
  EXPECT_NEAR(ratio, 1.0, 0.03) << "distorted hex20 / Timoshenko = " << ratio;
}

}  // namespace
}  // namespace bb
