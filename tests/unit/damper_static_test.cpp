// Static pre-solve of the rigid damper (damper/rigid_damper, thesis eq 3.49): the frictionless
// wedge N = CF / (2 cos beta), force and moment equilibrium of an asymmetric damper, elastic
// platforms, a CF that pulls the damper away, a damper that cannot be balanced, and accuracy from
// soft to very stiff contacts and from tiny to large CF. Units: SI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "articles/two_blade.hpp"
#include "damper/rigid_damper.hpp"
#include "damper_support.hpp"

namespace bb::damper {
namespace {

using test::asymmetric_geometry;
using test::rad;
using test::symmetric_geometry;
using test::three_point_statics;

DamperStaticState solve_rigid(const RigidDamper& d, double cf, double kn) {
  return solve_damper_static(Eigen::MatrixXd(0, 0), d, centrifugal_load(0, cf), {.kn = kn});
}

class DamperStaticSymmetric : public ::testing::TestWithParam<double> {};

TEST_P(DamperStaticSymmetric, WedgeCarriesCFOverTwoCosBetaPerSideWithoutRotation) {
  const double beta = GetParam(), cf = 300.0, kn = 1e8;
  const RigidDamper d = asymmetric_damper(symmetric_geometry(beta));
  const DamperStaticState s = solve_rigid(d, cf, kn);
  ASSERT_TRUE(s.converged) << s.failure;
  const double side = cf / (2.0 * std::cos(rad(beta)));
  EXPECT_NEAR(s.normal_preload(0), 0.5 * side, 1e-12 * side);  // L1: half of the flat face's load
  EXPECT_NEAR(s.normal_preload(1), 0.5 * side, 1e-12 * side);  // L2
  EXPECT_NEAR(s.normal_preload(2), side, 1e-12 * side);        // R
  EXPECT_NEAR(s.damper(2), 0.0, 1e-14 * cf / kn / 1e-3);       // no rotation
  // The flat face is twice as stiff (two springs), so G drifts towards the right face:
  // x = CF / (8 kn sin cos), y = 3 CF / (8 kn cos^2).
  const double c = std::cos(rad(beta)), sn = std::sin(rad(beta));
  EXPECT_NEAR(s.damper(0), cf / (8.0 * kn * sn * c), 1e-12 * cf / kn);
  EXPECT_NEAR(s.damper(1), 3.0 * cf / (8.0 * kn * c * c), 1e-12 * cf / kn);
  EXPECT_FALSE(s.open[0] || s.open[1] || s.open[2]);
  EXPECT_EQ(s.iterations, 1);
}

INSTANTIATE_TEST_SUITE_P(DamperBeta, DamperStaticSymmetric, ::testing::Values(20.0, 30.0, 45.0, 60.0, 75.0));

TEST(DamperStatic, AsymmetricDamperIsInForceAndMomentEquilibrium) {
  const double cf = 180.0;
  const RigidDamper d = asymmetric_damper(asymmetric_geometry());
  const DamperStaticState s = solve_rigid(d, cf, 5e8);
  ASSERT_TRUE(s.converged) << s.failure;
  Eigen::Vector2d force(0.0, cf);
  double moment = 0.0, scale_m = 0.0;
  for (size_t c = 0; c < 3; ++c) {
    const Eigen::Vector2d fc = s.normal_preload(static_cast<Eigen::Index>(c)) * d.contacts[c].normal;
    EXPECT_GT(s.normal_preload(static_cast<Eigen::Index>(c)), 0.0) << d.contacts[c].name;
    force += fc;
    moment += test::cross2(d.contacts[c].position, fc);
    scale_m += d.contacts[c].position.norm() * fc.norm();
  }
  std::printf("asymmetric: N0 = (%.10g, %.10g, %.10g) N, |F| = %.3g N, |M| = %.3g N m, theta = %.4g rad\n",
              s.normal_preload(0), s.normal_preload(1), s.normal_preload(2), force.norm(), std::abs(moment),
              s.damper(2));
  EXPECT_LT(force.norm(), 1e-10 * cf);
  EXPECT_LT(std::abs(moment), 1e-10 * scale_m);  // the moment about G of the contact forces vanishes
  EXPECT_LT(s.force_residual, 1e-10 * cf);
  EXPECT_LT(s.moment_residual, 1e-10 * scale_m);
  const Eigen::Vector3d hand = three_point_statics(d, cf);
  for (Eigen::Index c = 0; c < 3; ++c) EXPECT_NEAR(s.normal_preload(c), hand(c), 1e-10 * hand.norm());
  EXPECT_NE(s.damper(2), 0.0);  // asymmetric: the damper rolls a little into its seat
}

TEST(DamperStatic, ElasticPlatformsCarryTheSameStaticallyDeterminateLoads) {
  // Three contacts hold the three damper DOFs: without friction the loads follow from the damper's
  // equilibrium alone, whatever the blade compliance; the blades then balance them.
  AsymmetricDamperGeometry g = asymmetric_geometry();
  g.l1_x = 0, g.l1_y = 1, g.l2_x = 2, g.l2_y = 3, g.r_x = 4, g.r_y = 5;
  const RigidDamper d = asymmetric_damper(g);
  Eigen::MatrixXd kb(6, 6);
  kb.setRandom();
  kb = 1e7 * (kb * kb.transpose() + 6.0 * Eigen::MatrixXd::Identity(6, 6));
  const double cf = 180.0;
  const DamperStaticState s = solve_damper_static(kb, d, centrifugal_load(6, cf), {.kn = 2e8});
  ASSERT_TRUE(s.converged) << s.failure;
  const Eigen::Vector3d hand = three_point_statics(d, cf);
  for (Eigen::Index c = 0; c < 3; ++c) EXPECT_NEAR(s.normal_preload(c), hand(c), 1e-10 * hand.norm());
  // Blades: K_b q_b = -(A_n^T N)_b, the reactions of the damper on the platforms.
  const ContactKinematics k = contact_kinematics(d, 6);
  const Eigen::VectorXd reaction = -(k.normal.transpose() * s.normal_preload).head(6);
  EXPECT_LT((kb * s.q.head(6) - reaction).norm(), 1e-10 * reaction.norm());
  // v = N / kn at each closed contact.
  for (Eigen::Index c = 0; c < 3; ++c)
    EXPECT_NEAR(s.normal_displacement(c), s.normal_preload(c) / 2e8, 1e-10 * hand.norm() / 2e8);
}

TEST(DamperStatic, ReversedCentrifugalForceOpensEveryContactAndIsReportedNotNaN) {
  const RigidDamper d = asymmetric_damper(asymmetric_geometry());
  const DamperStaticState s = solve_rigid(d, -180.0, 1e8);
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.failure.find("pulls the damper away"), std::string::npos) << s.failure;
  ASSERT_EQ(s.open.size(), 3u);
  EXPECT_TRUE(s.open[0] && s.open[1] && s.open[2]);
  EXPECT_TRUE(s.q.allFinite());
  EXPECT_TRUE(s.normal_preload.allFinite());
  EXPECT_EQ(s.normal_preload.norm(), 0.0);
  std::printf("reversed CF: %s\n", s.failure.c_str());
}

TEST(DamperStatic, DamperWhoseFlatFaceWouldPullIsReportedAsAMechanism) {
  // Both flat-face points far up the face: balancing the moment would need L2 to pull (N < 0), so
  // L2 opens and the damper pivots freely on L1 and R.
  AsymmetricDamperGeometry g = asymmetric_geometry();
  const Eigen::Vector2d t(std::cos(rad(40.0)), std::sin(rad(40.0)));
  g.l1 = Eigen::Vector2d(-4e-3, 1.5e-3) + 4.0e-3 * t;
  g.l2 = Eigen::Vector2d(-4e-3, 1.5e-3) + 6.0e-3 * t;
  const RigidDamper d = asymmetric_damper(g);
  const Eigen::Vector3d hand = three_point_statics(d, 180.0);
  ASSERT_LT(hand.minCoeff(), 0.0);  // no compressive equilibrium exists
  const DamperStaticState s = solve_rigid(d, 180.0, 1e8);
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.failure.find("mechanism"), std::string::npos) << s.failure;
  EXPECT_TRUE(s.q.allFinite());
  std::printf("unbalanced damper: %s\n", s.failure.c_str());
}

TEST(DamperStatic, FlatFacePointThatWouldPullOpensAndTheOthersCarryTheLoad) {
  // A third point far up the flat face: with all four closed the face's load spreads linearly
  // along it and the far end would pull; the active set opens it and the three remaining points
  // carry the loads of their own statics.
  // The flat face's resultant lies about 2.1 mm up the face from its centre c: L1 and L2 bracket
  // it closely, L3 lies far down the face, on the other side of their mean.
  AsymmetricDamperGeometry g = asymmetric_geometry();
  const Eigen::Vector2d c(-4e-3, 1.5e-3), t(std::cos(rad(40.0)), std::sin(rad(40.0)));
  g.l1 = c + 1.0e-3 * t;
  g.l2 = c + 2.4e-3 * t;
  const RigidDamper three = asymmetric_damper(g);
  RigidDamper four = three;
  four.contacts.push_back({"L3", c - 6e-3 * t, three.contacts[0].normal});
  const double cf = 180.0;
  const DamperStaticState s = solve_rigid(four, cf, 1e8);
  ASSERT_TRUE(s.converged) << s.failure;
  EXPECT_FALSE(s.open[0] || s.open[1] || s.open[2]);
  EXPECT_TRUE(s.open[3]);
  EXPECT_EQ(s.normal_preload(3), 0.0);
  EXPECT_LT(s.normal_displacement(3), 0.0);  // L3 separates: a gap opens there
  EXPECT_EQ(s.iterations, 2);
  const Eigen::Vector3d hand = three_point_statics(three, cf);
  ASSERT_GT(hand.minCoeff(), 0.0);
  for (Eigen::Index k = 0; k < 3; ++k) EXPECT_NEAR(s.normal_preload(k), hand(k), 1e-10 * hand.norm());
}

TEST(DamperStatic, TwoBladeArticlePlatformPointsSeatTheDamperWithTheWedgeLoads) {
  // The article's own contact points (articles/two_blade): L1, L2 at 1/4 and 3/4 of blade 1's
  // right face, R at the middle of blade 2's left face, mirror images about the line midway
  // between the faces. A damper with G on that line, at the level of the faces' lower ends, takes
  // the closed-form wedge loads; the article's points also pass asymmetric_damper's face check.
  for (const double beta : {30.0, 45.0, 60.0}) {
    TwoBladeDimensions dims;
    dims.beta_deg = beta;
    const TwoBladeArticle a = two_blade_article(dims, ElementType::hex8);
    const Eigen::Vector2d l1 = a.points.at("L1").head<2>(), l2 = a.points.at("L2").head<2>(),
                          r = a.points.at("R").head<2>();
    const Eigen::Vector2d centre = 0.5 * (l1 + l2);
    const Eigen::Vector2d g_pos(0.5 * (centre.x() + r.x()), a.levels[5]);
    AsymmetricDamperGeometry g{.mass = 0.05,
                               .inertia = 2e-6,
                               .beta_left_deg = beta,
                               .beta_right_deg = beta,
                               .l1 = l1 - g_pos,
                               .l2 = l2 - g_pos,
                               .r = r - g_pos};
    const RigidDamper d = asymmetric_damper(g);
    const DamperStaticState s = solve_rigid(d, 250.0, 1e9);
    ASSERT_TRUE(s.converged) << s.failure;
    const double side = 250.0 / (2.0 * std::cos(rad(beta)));
    EXPECT_NEAR(s.normal_preload(0), 0.5 * side, 1e-9 * side) << beta;
    EXPECT_NEAR(s.normal_preload(1), 0.5 * side, 1e-9 * side) << beta;
    EXPECT_NEAR(s.normal_preload(2), side, 1e-9 * side) << beta;
    EXPECT_NEAR(s.damper(2), 0.0, 1e-9 * 250.0 / 1e9 / 1e-3) << beta;
  }
}

TEST(DamperStatic, ClosedFormHoldsFromSoftToVeryStiffContactsAndFromTinyToLargeCF) {
  const double beta = 35.0;
  const RigidDamper sym = asymmetric_damper(symmetric_geometry(beta));
  const RigidDamper asym = asymmetric_damper(asymmetric_geometry());
  const Eigen::Vector3d unit_asym = three_point_statics(asym, 1.0);
  double worst_sym = 0.0, worst_asym = 0.0;
  for (double kn = 1e3; kn <= 1e12 * 1.0001; kn *= 10.0) {
    for (double cf = 1e-3; cf <= 1e5 * 1.0001; cf *= 10.0) {
      const DamperStaticState s = solve_rigid(sym, cf, kn);
      ASSERT_TRUE(s.converged) << s.failure;
      const double side = cf / (2.0 * std::cos(rad(beta)));
      const Eigen::Vector3d exact(0.5 * side, 0.5 * side, side);
      worst_sym = std::max(worst_sym, (s.normal_preload - exact).cwiseAbs().maxCoeff() / side);
      const DamperStaticState a = solve_rigid(asym, cf, kn);
      ASSERT_TRUE(a.converged) << a.failure;
      worst_asym =
          std::max(worst_asym, (a.normal_preload - cf * unit_asym).cwiseAbs().maxCoeff() / (cf * unit_asym.norm()));
      EXPECT_TRUE(a.q.allFinite());
    }
  }
  std::printf("kn 1e3..1e12, CF 1e-3..1e5: worst relative N0 error symmetric %.2e, asymmetric %.2e\n", worst_sym,
              worst_asym);
  EXPECT_LT(worst_sym, 1e-8);
  EXPECT_LT(worst_asym, 1e-8);
}

TEST(DamperStatic, InvalidInputsThrowInsteadOfReturningAState) {
  const RigidDamper d = asymmetric_damper(asymmetric_geometry());
  EXPECT_THROW((void)solve_rigid(d, 100.0, 0.0), std::invalid_argument);
  EXPECT_THROW((void)solve_rigid(d, 100.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW((void)solve_damper_static(Eigen::MatrixXd(0, 0), d, Eigen::VectorXd::Zero(4), {.kn = 1e8}),
               std::invalid_argument);
}

}  // namespace
}  // namespace bb::damper
