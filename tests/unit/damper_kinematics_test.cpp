// Rigid damper kinematics and assembly (damper/rigid_damper): normals and tangents of the platform
// faces, rigid-body motions of blades and damper, the lever arms of a damper rotation, eq 3.43's B
// against the virtual work of the contact forces, and the block-diagonal coupled system. Units: SI.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "common/errors.hpp"
#include "damper/rigid_damper.hpp"
#include "damper_support.hpp"
#include "reduction/reduced_model.hpp"

namespace bb::damper {
namespace {

using test::asymmetric_geometry;
using test::cross2;
using test::rad;

// The asymmetric damper on elastic platforms: 6 blade DOFs, the platform points' (x, y) at
// (0, 1), (2, 3), (4, 5) for L1, L2, R.
RigidDamper elastic_damper() {
  AsymmetricDamperGeometry g = asymmetric_geometry();
  g.l1_x = 0, g.l1_y = 1, g.l2_x = 2, g.l2_y = 3, g.r_x = 4, g.r_y = 5;
  return asymmetric_damper(g);
}

TEST(DamperKinematics, NormalsPointFromThePlatformsIntoTheDamperAndTangentsRunUpTheFaces) {
  const RigidDamper d = asymmetric_damper(asymmetric_geometry());
  const DamperContact& l1 = d.contacts[0];
  const DamperContact& r = d.contacts[2];
  // The platforms overhang the damper: their normals into it point down (-y); the left one to the
  // right (+x, away from blade 1), the right one to the left.
  EXPECT_NEAR(l1.normal.x(), std::sin(rad(40.0)), 1e-15);
  EXPECT_NEAR(l1.normal.y(), -std::cos(rad(40.0)), 1e-15);
  EXPECT_NEAR(r.normal.x(), -std::sin(rad(55.0)), 1e-15);
  EXPECT_NEAR(r.normal.y(), -std::cos(rad(55.0)), 1e-15);
  // t = n rotated +90: along the left face (cos beta_L, sin beta_L), so L1 -> L2 runs along t.
  EXPECT_NEAR(l1.tangent().x(), std::cos(rad(40.0)), 1e-15);
  EXPECT_NEAR(l1.tangent().y(), std::sin(rad(40.0)), 1e-15);
  EXPECT_NEAR((d.contacts[1].position - l1.position).normalized().dot(l1.tangent()), 1.0, 1e-12);
  EXPECT_NEAR(cross2(l1.normal, l1.tangent()), 1.0, 1e-15);
}

TEST(DamperKinematics, CommonTranslationOfBladesAndDamperGivesNoRelativeDisplacement) {
  const RigidDamper d = elastic_damper();
  const ContactKinematics k = contact_kinematics(d, 6);
  ASSERT_EQ(k.normal.rows(), 3);
  ASSERT_EQ(k.normal.cols(), 9);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1e-4, 1e-4);
  for (int trial = 0; trial < 10; ++trial) {
    const double tx = uni(rng), ty = uni(rng);
    Eigen::VectorXd q(9);
    q << tx, ty, tx, ty, tx, ty, tx, ty, 0.0;
    EXPECT_LT((k.tangential * q).cwiseAbs().maxCoeff(), 1e-20);
    EXPECT_LT((k.normal * q).cwiseAbs().maxCoeff(), 1e-20);
  }
  // Moving the platforms alone into the damper presses it: v = n . d_blade.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(9);
  q.segment<2>(4) = 1e-6 * d.contacts[2].normal;
  EXPECT_NEAR((k.normal * q)(2), 1e-6, 1e-21);
  EXPECT_NEAR((k.tangential * q)(2), 0.0, 1e-21);
  // Moving the damper alone against n (into the platform) presses too.
  q.setZero();
  q.segment<2>(6) = -1e-6 * d.contacts[0].normal;
  EXPECT_NEAR((k.normal * q)(0), 1e-6, 1e-21);
  EXPECT_NEAR((k.normal * q)(1), 1e-6, 1e-21);
}

TEST(DamperKinematics, PureRotationMovesEachContactByItsLeverArm) {
  // Contacts on rigid platforms at r = rho n (lever arm 0 for v, rho for u) and r = rho t.
  const Eigen::Vector2d n = left_face_normal(30.0);
  const Eigen::Vector2d t(-n.y(), n.x());
  const double rho = 3e-3, theta = 2e-4;
  RigidDamper d{.mass = 1.0, .inertia = 1.0, .contacts = {{"A", rho * n, n}, {"B", rho * t, n}}};
  const ContactKinematics k = contact_kinematics(d, 0);
  const Eigen::Vector3d q(0.0, 0.0, theta);
  // The damper point moves by theta (e_z x r); relative = blade - damper = -theta (e_z x r).
  EXPECT_NEAR((k.normal * q)(0), 0.0, 1e-20);
  EXPECT_NEAR((k.tangential * q)(0), -theta * rho, 1e-20);
  EXPECT_NEAR((k.normal * q)(1), theta * rho, 1e-20);
  EXPECT_NEAR((k.tangential * q)(1), 0.0, 1e-20);
  // The same from the point displacement formula (x - theta r_y, y + theta r_x).
  const Eigen::Vector2d dp = damper_point_displacement(q, rho * t);
  EXPECT_NEAR(dp.dot(n), -theta * rho, 1e-20);
}

TEST(DamperKinematics, ForceMatrixMatchesVirtualWorkOfTheContactForces) {
  const RigidDamper d = elastic_damper();
  const Eigen::Matrix<double, 3, Eigen::Dynamic> b = contact_force_to_damper(d);
  ASSERT_EQ(b.cols(), 6);
  const ContactKinematics k = contact_kinematics(d, 6);
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss;
  double worst = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd f(6);
    for (Eigen::Index i = 0; i < 6; ++i) f(i) = 100.0 * gauss(rng);
    const Eigen::Vector3d dq(1e-5 * gauss(rng), 1e-5 * gauss(rng), 1e-3 * gauss(rng));
    double work = 0.0;
    for (size_t c = 0; c < 3; ++c) {
      const DamperContact& p = d.contacts[c];
      const Eigen::Vector2d force =
          f(static_cast<Eigen::Index>(2 * c)) * p.tangent() + f(static_cast<Eigen::Index>(2 * c + 1)) * p.normal;
      work += force.dot(damper_point_displacement(dq, p.position));
    }
    const double via_b = dq.dot(b * f);
    worst = std::max(worst, std::abs(via_b - work) / std::abs(work));
    // And on the whole DOF vector: -(A_t^T T + A_n^T N) . dq = - sum (T du + N dv).
    Eigen::VectorXd dfull = Eigen::VectorXd::Zero(9);
    for (Eigen::Index i = 0; i < 9; ++i) dfull(i) = 1e-5 * gauss(rng);
    Eigen::VectorXd t(3), nn(3);
    for (Eigen::Index c = 0; c < 3; ++c) t(c) = f(2 * c), nn(c) = f(2 * c + 1);
    const Eigen::VectorXd gen = -(k.tangential.transpose() * t + k.normal.transpose() * nn);
    double work_full = 0.0;
    for (size_t c = 0; c < 3; ++c) {
      const DamperContact& p = d.contacts[c];
      const Eigen::Vector2d force =
          t(static_cast<Eigen::Index>(c)) * p.tangent() + nn(static_cast<Eigen::Index>(c)) * p.normal;
      const Eigen::Vector2d db(dfull(p.blade_x), dfull(p.blade_y));
      work_full += force.dot(damper_point_displacement(dfull.tail<3>(), p.position)) - force.dot(db);
    }
    EXPECT_NEAR(gen.dot(dfull), work_full, 1e-12 * std::abs(work_full) + 1e-18);
  }
  EXPECT_LT(worst, 1e-12);
  // B = -(damper columns of the interleaved rows)^T.
  for (Eigen::Index c = 0; c < 3; ++c) {
    EXPECT_LT((b.col(2 * c) + k.tangential.row(c).tail<3>().transpose()).norm(), 1e-15);
    EXPECT_LT((b.col(2 * c + 1) + k.normal.row(c).tail<3>().transpose()).norm(), 1e-15);
  }
}

TEST(DamperAssembly, CoupledMatricesAreBlockDiagonalWithTheDamperInertiaAndNoDamperStiffness) {
  const RigidDamper d = elastic_damper();
  Eigen::MatrixXd mb = Eigen::MatrixXd::Identity(6, 6) * 0.3, kb = Eigen::MatrixXd::Identity(6, 6) * 1e7;
  mb(0, 1) = mb(1, 0) = 0.01;
  const CoupledSystem s = assemble_coupled_system(mb, kb, d);
  ASSERT_EQ(s.mass.rows(), 9);
  EXPECT_EQ(s.mass.topLeftCorner(6, 6), mb);
  EXPECT_EQ(s.stiffness.topLeftCorner(6, 6), kb);
  EXPECT_EQ(s.mass.bottomRightCorner(3, 3), Eigen::Vector3d(d.mass, d.mass, d.inertia).asDiagonal().toDenseMatrix());
  EXPECT_EQ(s.stiffness.bottomRightCorner(3, 3), Eigen::Matrix3d::Zero());
  EXPECT_EQ(s.mass.topRightCorner(6, 3), Eigen::MatrixXd::Zero(6, 3));
  const Eigen::VectorXd f = centrifugal_load(6, 250.0);
  EXPECT_EQ(f.size(), 9);
  EXPECT_EQ(f(damper_y(6)), 250.0);
  EXPECT_EQ(f.norm(), 250.0);
}

TEST(DamperGeometry, PlatformPointsOfAReducedModelGiveTheBladeSideOfTheContacts) {
  ReducedModel m;
  for (const char* label : {"T1", "L1", "L2", "R"})
    for (int dir = 0; dir < 3; ++dir) m.dofs.push_back({.label = label, .direction = dir, .mode = 0});
  m.dofs.push_back({.label = "", .direction = -1, .mode = 1});
  EXPECT_EQ(platform_dofs(m, "L1"), std::make_pair(3, 4));
  EXPECT_EQ(platform_dofs(m, "R"), std::make_pair(9, 10));
  EXPECT_THROW((void)platform_dofs(m, "F"), InputError);
  AsymmetricDamperGeometry g = asymmetric_geometry();
  std::tie(g.l1_x, g.l1_y) = platform_dofs(m, "L1");
  std::tie(g.l2_x, g.l2_y) = platform_dofs(m, "L2");
  std::tie(g.r_x, g.r_y) = platform_dofs(m, "R");
  const ContactKinematics k = contact_kinematics(asymmetric_damper(g), m.size());
  EXPECT_EQ(k.normal.cols(), 16);
  EXPECT_EQ(k.normal(2, 9), -std::sin(rad(55.0)));    // R's n_x on its blade x DOF
  EXPECT_EQ(k.normal.block(0, 0, 3, 3).norm(), 0.0);  // T1 plays no part
  EXPECT_EQ(k.normal.col(5).norm(), 0.0);             // nor any z DOF
}

TEST(DamperGeometry, InvalidDampersAreRejectedWithTheOffendingValue) {
  RigidDamper d = elastic_damper();
  EXPECT_THROW((void)contact_kinematics(d, 5), std::invalid_argument);  // index 5 out of range
  d.mass = 0.0;
  EXPECT_THROW((void)contact_kinematics(d, 6), std::invalid_argument);
  d = elastic_damper();
  d.contacts[1].normal *= 2.0;
  EXPECT_THROW((void)contact_force_to_damper(d), std::invalid_argument);
  AsymmetricDamperGeometry g = asymmetric_geometry();
  std::swap(g.l1, g.l2);  // L1 -> L2 running down the face
  EXPECT_THROW((void)asymmetric_damper(g), std::invalid_argument);
  g = asymmetric_geometry();
  g.beta_right_deg = 90.0;
  EXPECT_THROW((void)asymmetric_damper(g), std::invalid_argument);
}

}  // namespace
}  // namespace bb::damper
