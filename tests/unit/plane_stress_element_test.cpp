// Element matrices of fe/plane_stress: the properties any correct plane-stress element must have
// (symmetry, definiteness, exactly the rigid-body null space, exact constant-strain energy, total
// mass), checked on a rectangle, a distorted convex quadrilateral and a general triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "fe/plane_stress.hpp"
#include "stiffness_checks.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

using test::LinearField;

enum class Kind { q4, cst };

struct Shape {
  std::string name;
  Kind kind;
  Eigen::MatrixXd xy;  // counterclockwise
};

void PrintTo(const Shape& s, std::ostream* os) { *os << s.name; }

Eigen::MatrixXd rows(std::initializer_list<std::pair<double, double>> pts) {
  Eigen::MatrixXd xy(static_cast<Eigen::Index>(pts.size()), 2);
  Eigen::Index i = 0;
  for (auto [x, y] : pts) xy.row(i++) << x, y;
  return xy;
}

Shape q4_rectangle() { return {"Q4Rectangle", Kind::q4, rows({{0.0, 0.0}, {2.0, 0.0}, {2.0, 0.5}, {0.0, 0.5}})}; }
// Convex, no two sides parallel: the Jacobian varies over the element.
Shape q4_distorted() { return {"Q4Distorted", Kind::q4, rows({{0.1, -0.2}, {2.0, 0.3}, {1.7, 1.6}, {-0.3, 0.9}})}; }
Shape cst_general() { return {"CstGeneral", Kind::cst, rows({{0.2, 0.1}, {1.9, 0.6}, {0.7, 1.4}})}; }

Eigen::MatrixXd stiffness(const Shape& s, const fe::PlaneSection& sec) {
  if (s.kind == Kind::q4) return fe::q4_stiffness(fe::Q4Coords(s.xy), sec);
  return fe::cst_stiffness(fe::CstCoords(s.xy), sec);
}

Eigen::MatrixXd mass(const Shape& s, const fe::PlaneSection& sec) {
  if (s.kind == Kind::q4) return fe::q4_consistent_mass(fe::Q4Coords(s.xy), sec);
  return fe::cst_consistent_mass(fe::CstCoords(s.xy), sec);
}

Eigen::VectorXd sample_field(const LinearField& f, const Eigen::MatrixXd& xy) {
  Eigen::VectorXd u(2 * xy.rows());
  for (Eigen::Index a = 0; a < xy.rows(); ++a) u.segment<2>(2 * a) = f.at(xy(a, 0), xy(a, 1));
  return u;
}

class ElementMatrices : public ::testing::TestWithParam<Shape> {
 protected:
  fe::PlaneSection section = test::steel_section(0.05);
};

TEST_P(ElementMatrices, StiffnessIsSymmetric) {
  const Eigen::MatrixXd k = stiffness(GetParam(), section);
  EXPECT_LE((k - k.transpose()).norm(), 1e-14 * k.norm());
}

TEST_P(ElementMatrices, StiffnessHasExactlyThreeZeroEnergyModesAndIsOtherwisePositive) {
  // The fourth eigenvalue is a genuine deformation mode, well separated from round-off.
  EXPECT_TRUE(test::has_exactly_zero_energy_modes(stiffness(GetParam(), section), 3, 1e-4));
}

TEST_P(ElementMatrices, RigidBodyMotionsAreInTheStiffnessNullSpace) {
  const Shape& s = GetParam();
  const Eigen::MatrixXd k = stiffness(s, section);
  const Eigen::MatrixXd r = test::rigid_body_modes(s.xy);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE((k * r.col(c)).norm(), 1e-12 * k.norm() * r.col(c).norm()) << "rigid mode " << c;
  }
  // Also about a point far from the element: translation plus rotation, not only about the origin.
  const Eigen::VectorXd moved = r.col(2) + 7.0 * r.col(0) - 3.0 * r.col(1);
  EXPECT_LE((k * moved).norm(), 1e-12 * k.norm() * moved.norm());
}

TEST_P(ElementMatrices, UniformStrainEnergyEqualsHalfEpsDEpsTimesVolume) {
  // Both elements represent any linear field exactly, and integrate its constant energy density
  // exactly (2x2 Gauss on a Q4 integrates det J, which is linear in xi and eta, exactly).
  const Shape& s = GetParam();
  const Eigen::MatrixXd k = stiffness(s, section);
  const Eigen::Matrix3d d = fe::plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio);
  const double volume = test::polygon_area(s.xy) * section.thickness;
  for (const LinearField& f :
       {LinearField{0, 1e-3, 0, 0, 0, 0}, LinearField{0, 0, 0, 0, 0, -2e-3}, LinearField{0, 0, 1e-3, 0, 1e-3, 0},
        LinearField{3e-4, 1.2e-3, -4e-4, -2e-4, 7e-4, 5e-4}}) {
    const Eigen::VectorXd u = sample_field(f, s.xy);
    const Eigen::Vector3d eps = f.strain();
    const double expected = 0.5 * eps.dot(d * eps) * volume;
    EXPECT_NEAR(0.5 * u.dot(k * u), expected, 1e-12 * expected);
  }
}

TEST_P(ElementMatrices, ConsistentMassIsSymmetricPositiveDefinite) {
  const Eigen::MatrixXd m = mass(GetParam(), section);
  EXPECT_LE((m - m.transpose()).norm(), 1e-15 * m.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-3 * eig.eigenvalues().maxCoeff());
}

TEST_P(ElementMatrices, ConsistentMassOfEachDirectionSumsToTheElementMass) {
  const Shape& s = GetParam();
  const Eigen::MatrixXd m = mass(s, section);
  const double total = section.density * test::polygon_area(s.xy) * section.thickness;
  const Eigen::Index n = s.xy.rows();
  double xx = 0.0, yy = 0.0;
  for (Eigen::Index a = 0; a < n; ++a) {
    for (Eigen::Index c = 0; c < n; ++c) {
      xx += m(2 * a, 2 * c);
      yy += m(2 * a + 1, 2 * c + 1);
      EXPECT_EQ(m(2 * a, 2 * c + 1), 0.0) << "x-y coupling at nodes " << a << ", " << c;
      EXPECT_EQ(m(2 * a + 1, 2 * c), 0.0) << "y-x coupling at nodes " << a << ", " << c;
    }
  }
  EXPECT_NEAR(xx, total, 1e-13 * total);
  EXPECT_NEAR(yy, total, 1e-13 * total);
  // Equivalently: a rigid translation carries kinetic energy 1/2 m v^2.
  const Eigen::MatrixXd r = test::rigid_body_modes(s.xy);
  EXPECT_NEAR(r.col(0).dot(m * r.col(0)), total, 1e-13 * total);
}

TEST_P(ElementMatrices, StiffnessIsObjectiveUnderRigidRotationOfTheElement) {
  // Isotropy: rotating the element by R rotates K as T^T K T with T = diag(R, R, ...).
  const Shape& s = GetParam();
  const double angle = 0.7;
  Eigen::Matrix2d rot;
  rot << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  Shape turned = s;
  turned.xy = (s.xy * rot.transpose()).rowwise() + Eigen::RowVector2d(5.0, -2.0);
  const Eigen::MatrixXd k = stiffness(s, section);
  const Eigen::MatrixXd k_turned = stiffness(turned, section);
  const Eigen::Index n = s.xy.rows();
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (Eigen::Index a = 0; a < n; ++a) t.block<2, 2>(2 * a, 2 * a) = rot;
  EXPECT_LE((t.transpose() * k_turned * t - k).norm(), 1e-12 * k.norm());
}

TEST_P(ElementMatrices, StressOfALinearFieldIsDTimesItsStrain) {
  const Shape& s = GetParam();
  const LinearField f{1e-3, 2e-4, -3e-4, -1e-3, 5e-4, -1e-4};
  const Eigen::Vector3d expected =
      fe::plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio) * f.strain();
  const Eigen::Vector3d got =
      s.kind == Kind::q4 ? fe::q4_centroid_stress(fe::Q4Coords(s.xy), test::sample<4>(f, fe::Q4Coords(s.xy)), section)
                         : fe::cst_stress(fe::CstCoords(s.xy), test::sample<3>(f, fe::CstCoords(s.xy)), section);
  EXPECT_LE((got - expected).norm(), 1e-10 * expected.norm()) << got.transpose() << " vs " << expected.transpose();
}

TEST_P(ElementMatrices, ClockwiseNodeOrderThrowsDomainError) {
  Shape s = GetParam();
  s.xy = s.xy.colwise().reverse().eval();  // same element, nodes clockwise
  EXPECT_THROW(stiffness(s, section), std::domain_error);
  EXPECT_THROW(mass(s, section), std::domain_error);
}

INSTANTIATE_TEST_SUITE_P(PlaneStress, ElementMatrices, ::testing::Values(q4_rectangle(), q4_distorted(), cst_general()),
                         [](const ::testing::TestParamInfo<Shape>& p) { return p.param.name; });

TEST(PlaneStressElasticity, MatchesHookesLawForUniaxialStress) {
  // Uniaxial stress sigma_xx: eps_xx = s/E, eps_yy = -nu s/E, no shear.
  const double e = 7.0e10, nu = 0.33, s = 1.0e8;
  const Eigen::Vector3d stress = fe::plane_stress_elasticity(e, nu) * Eigen::Vector3d(s / e, -nu * s / e, 0.0);
  EXPECT_NEAR(stress[0], s, 1e-9 * s);
  EXPECT_NEAR(stress[1], 0.0, 1e-9 * s);
  EXPECT_EQ(stress[2], 0.0);
  // Pure shear: tau = G gamma with G = E / (2 (1 + nu)).
  const Eigen::Vector3d shear = fe::plane_stress_elasticity(e, nu) * Eigen::Vector3d(0.0, 0.0, 1e-3);
  EXPECT_NEAR(shear[2], e / (2 * (1 + nu)) * 1e-3, 1e-9 * shear[2]);
}

// Closed-form stiffness of an a x b rectangle: with N_i = c0 + cx x + cy y + cxy x y, the strain-
// displacement matrix is B = B0 + Bx x + By y, and K = t * sum of exact monomial integrals over
// [0, a] x [0, b]. Independent of isoparametric mapping and Gauss quadrature.
fe::Matrix8 rectangle_stiffness_closed_form(double a, double b, const fe::PlaneSection& sec) {
  // Node i: (1 - x/a)(1 - y/b), (x/a)(1 - y/b), (x/a)(y/b), (1 - x/a)(y/b).
  const double cx[4] = {-1 / a, 1 / a, 0, 0}, cy[4] = {-1 / b, 0, 0, 1 / b};
  const double cxy[4] = {1 / (a * b), -1 / (a * b), 1 / (a * b), -1 / (a * b)};
  Eigen::Matrix<double, 3, 8> b0 = Eigen::Matrix<double, 3, 8>::Zero(), bx = b0, by = b0;
  for (int i = 0; i < 4; ++i) {
    // dN/dx = cx + cxy y ; dN/dy = cy + cxy x.
    b0(0, 2 * i) = cx[i];
    by(0, 2 * i) = cxy[i];
    b0(1, 2 * i + 1) = cy[i];
    bx(1, 2 * i + 1) = cxy[i];
    b0(2, 2 * i) = cy[i];
    bx(2, 2 * i) = cxy[i];
    b0(2, 2 * i + 1) = cx[i];
    by(2, 2 * i + 1) = cxy[i];
  }
  const Eigen::Matrix3d d = fe::plane_stress_elasticity(sec.youngs_modulus, sec.poisson_ratio);
  const double i1 = a * b, ix = a * a * b / 2, iy = a * b * b / 2, ixx = a * a * a * b / 3, iyy = a * b * b * b / 3,
               ixy = a * a * b * b / 4;
  const fe::Matrix8 k = b0.transpose() * d * b0 * i1 + (b0.transpose() * d * bx + bx.transpose() * d * b0) * ix +
                        (b0.transpose() * d * by + by.transpose() * d * b0) * iy + bx.transpose() * d * bx * ixx +
                        by.transpose() * d * by * iyy + (bx.transpose() * d * by + by.transpose() * d * bx) * ixy;
  return sec.thickness * k;
}

TEST(Q4Rectangle, StiffnessMatchesClosedFormIntegral) {
  const fe::PlaneSection sec = test::steel_section(0.02);
  const double a = 3.0, b = 0.75;
  fe::Q4Coords xy;
  xy << 0, 0, a, 0, a, b, 0, b;
  const fe::Matrix8 k = fe::q4_stiffness(xy, sec);
  const fe::Matrix8 expected = rectangle_stiffness_closed_form(a, b, sec);
  EXPECT_LE((k - expected).norm(), 1e-12 * expected.norm());
  // Two textbook entries: k11 = E t / (1 - nu^2) (b / 3a + (1 - nu) a / 6b), k12 = E t / (8 (1 - nu)).
  const double e = sec.youngs_modulus, nu = sec.poisson_ratio, t = sec.thickness;
  EXPECT_NEAR(k(0, 0), e * t / (1 - nu * nu) * (b / (3 * a) + (1 - nu) * a / (6 * b)), 1e-12 * k(0, 0));
  EXPECT_NEAR(k(0, 1), e * t / (8 * (1 - nu)), 1e-12 * k(0, 0));
}

TEST(Q4Rectangle, StiffnessIsIndependentOfTranslation) {
  const fe::PlaneSection sec = test::steel_section();
  fe::Q4Coords xy;
  xy << 0, 0, 2, 0, 2, 1, 0, 1;
  const fe::Q4Coords moved = xy.rowwise() + Eigen::RowVector2d(100.0, -40.0);
  EXPECT_LE((fe::q4_stiffness(xy, sec) - fe::q4_stiffness(moved, sec)).norm(),
            1e-10 * fe::q4_stiffness(xy, sec).norm());
}

TEST(Q4Rectangle, ConsistentMassMatchesClosedForm) {
  // rho t A / 36 * [4 2 1 2; 2 4 2 1; 1 2 4 2; 2 1 2 4] per direction.
  const fe::PlaneSection sec = test::steel_section(0.02);
  fe::Q4Coords xy;
  xy << 0, 0, 3, 0, 3, 0.75, 0, 0.75;
  const fe::Matrix8 m = fe::q4_consistent_mass(xy, sec);
  Eigen::Matrix4d pattern;
  pattern << 4, 2, 1, 2, 2, 4, 2, 1, 1, 2, 4, 2, 2, 1, 2, 4;
  const double scale = sec.density * sec.thickness * 3.0 * 0.75 / 36.0;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(m(2 * a, 2 * c), scale * pattern(a, c), 1e-12 * scale) << a << "," << c;
      EXPECT_NEAR(m(2 * a + 1, 2 * c + 1), scale * pattern(a, c), 1e-12 * scale) << a << "," << c;
    }
}

TEST(Cst, ConsistentMassMatchesClosedForm) {
  // rho t A / 12 * [2 1 1; 1 2 1; 1 1 2] per direction.
  const fe::PlaneSection sec = test::steel_section(0.02);
  const Shape s = cst_general();
  const fe::Matrix6 m = fe::cst_consistent_mass(fe::CstCoords(s.xy), sec);
  const double scale = sec.density * sec.thickness * test::polygon_area(s.xy) / 12.0;
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(m(2 * a, 2 * c), scale * (a == c ? 2 : 1), 1e-12 * scale);
      EXPECT_NEAR(m(2 * a + 1, 2 * c + 1), scale * (a == c ? 2 : 1), 1e-12 * scale);
    }
}

TEST(Q4, ReentrantOrSelfIntersectingElementThrowsDomainError) {
  const fe::PlaneSection sec = test::steel_section();
  // Arrow-shaped (re-entrant corner at node 3): det J < 0 at a Gauss point near it.
  fe::Q4Coords reentrant;
  reentrant << 0, 0, 2, 0, 0.3, 0.3, 0, 2;
  EXPECT_THROW(fe::q4_stiffness(reentrant, sec), std::domain_error);
  fe::Q4Coords bowtie;  // self-intersecting
  bowtie << 0, 0, 1, 1, 1, 0, 0, 1;
  EXPECT_THROW(fe::q4_stiffness(bowtie, sec), std::domain_error);
}

TEST(Cst, CollinearNodesThrowDomainError) {
  const fe::PlaneSection sec = test::steel_section();
  fe::CstCoords line;
  line << 0, 0, 1, 1, 2, 2;
  EXPECT_THROW(fe::cst_stiffness(line, sec), std::domain_error);
  EXPECT_THROW(fe::cst_consistent_mass(line, sec), std::domain_error);
}

}  // namespace
}  // namespace bb
