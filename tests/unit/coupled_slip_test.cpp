// The 2D contact with coupled slip (friction/coupled_slip), through the friction-law interface
// only: the circular Coulomb limit and its closed-form dissipation on a circle, the 1D Jenkins law
// on a straight path, the energy balance of a period, the tangent and the AFT Jacobian against
// central differences. Units: SI.
#include "friction/coupled_slip.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "friction/friction_system.hpp"

namespace bb::friction {
namespace {

// mu N0 / kt = 5e-5 m: the slip distance of the point.
constexpr PointParameters kPoint{.kn = 1.0e7, .kt = 1.0e6, .mu = 0.5, .n0 = 100.0};
constexpr double kPi = std::numbers::pi;

const FrictionLaw& law() { return *coupled_slip_law(); }

TEST(CoupledSlip, ActsAlongTwoDirectionsWithoutAPiecewiseLinearForm) {
  EXPECT_EQ(law().name(), "coupled_slip");
  EXPECT_EQ(law().directions(), 2);
  EXPECT_FALSE(law().piecewise_linear());
  EXPECT_TRUE(jenkins_law()->piecewise_linear());
  EXPECT_EQ(jenkins_law()->directions(), 1);
}

TEST(CoupledSlip, DiagonalSlipHoldsTheCircularLimitWhereTheUncoupledPairExceedsIt) {
  const Eigen::Vector2d u(1e-3, 1e-3);
  const LawStep s = law().step(kPoint, Eigen::Vector2d::Zero(), u, 0.0);
  EXPECT_EQ(s.state, ContactState::slip_positive);
  EXPECT_NEAR(s.tangential.norm(), kPoint.mu * kPoint.n0, 1e-12);
  EXPECT_NEAR(s.tangential[0], s.tangential[1], 1e-12);
  const JenkinsStep2D pair = jenkins_step_2d(kPoint, Eigen::Vector2d::Zero(), u, 0.0);
  EXPECT_NEAR(pair.tangential.norm(), std::sqrt(2.0) * kPoint.mu * kPoint.n0, 1e-9);
  // The slider sits mu N / kt behind u along the force.
  EXPECT_NEAR((kPoint.kt * (u - s.slider) - s.tangential).norm(), 0.0, 1e-10);
}

TEST(CoupledSlip, StickLiftOffAndFrictionless) {
  LawStep s = law().step(kPoint, Eigen::Vector2d::Zero(), Eigen::Vector2d(2e-5, -1e-5), 0.0);
  EXPECT_EQ(s.state, ContactState::stick);
  EXPECT_NEAR(s.tangential[0], 20.0, 1e-12);
  EXPECT_NEAR(s.tangential[1], -10.0, 1e-12);
  EXPECT_EQ(s.dt_du(0, 0), kPoint.kt);
  EXPECT_EQ(s.dt_du(0, 1), 0.0);
  s = law().step(kPoint, Eigen::Vector2d(1e-5, 2e-5), Eigen::Vector2d(3e-5, 4e-5), -2e-5);  // N0 + kn v < 0
  EXPECT_EQ(s.state, ContactState::lift_off);
  EXPECT_EQ(s.tangential.norm(), 0.0);
  EXPECT_EQ(s.normal, 0.0);
  EXPECT_EQ(s.slider, Eigen::Vector2d(3e-5, 4e-5));
  PointParameters frictionless = kPoint;
  frictionless.mu = 0.0;
  s = law().step(frictionless, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), 0.0);
  EXPECT_EQ(s.tangential.norm(), 0.0);
  EXPECT_TRUE(s.dt_du.allFinite());
}

// Along a fixed direction e the slider never leaves the line, so T . e is the 1D Jenkins force and
// T has no other component: at every step of a path that slips both ways and lifts off.
TEST(CoupledSlip, OnAStraightPathIsTheJenkinsLaw) {
  const Eigen::Vector2d e(std::cos(0.7), std::sin(0.7));
  Eigen::Vector2d w2 = Eigen::Vector2d::Zero();
  double w1 = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const double theta = 2.0 * kPi * k / 100.0;
    const double s = 2e-4 * std::sin(theta), v = 1.2e-5 * std::cos(3.0 * theta);
    const LawStep two = law().step(kPoint, w2, s * e, v);
    const JenkinsStep one = jenkins_step(kPoint, w1, s, v);
    ASSERT_NEAR(two.tangential.dot(e), one.tangential, 1e-9) << k;
    ASSERT_NEAR(two.tangential.dot(Eigen::Vector2d(-e.y(), e.x())), 0.0, 1e-9) << k;
    ASSERT_NEAR(two.normal, one.normal, 1e-12) << k;
    ASSERT_EQ(two.state == ContactState::lift_off, one.state == ContactState::lift_off) << k;
    w2 = two.slider;
    w1 = one.slider;
  }
}

// u on a circle of radius r at constant N: once the slider trails on its own circle,
// |T| = mu N everywhere and the work per cycle is mu N 2 pi sqrt(r^2 - (mu N / kt)^2) (rigid
// limit: mu N 2 pi r). Backward steps converge to it as 1 / n.
TEST(CoupledSlip, DissipatesTheClosedFormOnACircleAtConstantLoad) {
  const double r = 2e-4, limit = kPoint.mu * kPoint.n0, d = limit / kPoint.kt;
  const double exact = limit * 2.0 * kPi * std::sqrt(r * r - d * d);
  double previous_error = 0.0;
  for (const int n : {2000, 8000}) {
    Eigen::Vector2d w = Eigen::Vector2d::Zero(), u_before(r, 0.0);
    double work = 0.0, max_deviation = 0.0;
    for (int k = 1; k <= 4 * n; ++k) {
      const double theta = 2.0 * kPi * k / n;
      const Eigen::Vector2d u(r * std::cos(theta), r * std::sin(theta));
      const LawStep s = law().step(kPoint, w, u, 0.0);
      if (k > 3 * n) {
        work += s.tangential.dot(u - u_before);
        max_deviation = std::max(max_deviation, std::abs(s.tangential.norm() - limit));
      }
      w = s.slider;
      u_before = u;
    }
    EXPECT_LT(max_deviation, 1e-9 * limit) << n;
    EXPECT_NEAR(std::hypot(w.x(), w.y()), std::sqrt(r * r - d * d), 1e-3 * r) << n;
    const double error = std::abs(work - exact) / exact;
    EXPECT_LT(error, 5.0 / n) << n;
    if (previous_error > 0.0) EXPECT_LT(error, 0.4 * previous_error);  // first order: 4x the steps, 1/4 the error
    previous_error = error;
  }
}

Eigen::VectorXd coefficients(std::initializer_list<double> values) {
  Eigen::VectorXd c(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double x : values) c[i++] = x;
  return c;
}

// An elliptical path with a normal load that varies (no lift-off) at H = 3.
struct Motion {
  Eigen::VectorXd u, v;
};
Motion elliptical_motion() {
  const Eigen::VectorXd u1 = coefficients({1e-5, 1.5e-4, 0.2e-4, 0.1e-4, 0.0, 0.0, 0.05e-4});
  const Eigen::VectorXd u2 = coefficients({-2e-5, 0.3e-4, 1.0e-4, 0.0, 0.2e-4, 0.0, 0.0});
  Motion m{Eigen::VectorXd(14), coefficients({0.0, 0.0, 0.0, 3e-6, 1e-6, 0.0, 0.0})};
  m.u << u1, u2;
  return m;
}

AftOptions options(int samples) {
  AftOptions o;
  o.samples = samples;
  o.max_periods = 60;
  return o;
}

// The work of T on u per period from the harmonics (friction/aft.hpp's cycle_work per direction)
// equals what the slider dissipates, sum T_k . (w_k - w_{k-1}) over the samples: the elastic
// energy |T|^2 / 2 kt returns to its value. Equal up to the O(1 / n_t) of the discrete march.
TEST(CoupledSlip, HarmonicWorkBalancesTheSlidersDissipationOverAPeriod) {
  const Motion m = elliptical_motion();
  const AftResult r = law().harmonics(kPoint, m.u, m.v, options(8192));
  ASSERT_TRUE(r.closed);
  const Eigen::Index c = m.v.size();
  const double harmonic_work =
      cycle_work(r.tangential.head(c), m.u.head(c)) + cycle_work(r.tangential.tail(c), m.u.tail(c));
  EXPECT_GT(harmonic_work, 0.0);
  // Re-march the closed period for the second direction's samples (AftResult keeps the first's).
  const Eigen::MatrixXd e = synthesis_matrix(3, 8192);
  const Eigen::VectorXd u1 = e * m.u.head(c), u2 = e * m.u.tail(c), v = e * m.v;
  Eigen::Vector2d w = Eigen::Vector2d::Zero();
  for (int pass = 0; pass < 2; ++pass) {
    double dissipated = 0.0;
    for (Eigen::Index k = 0; k < u1.size(); ++k) {
      const LawStep s = law().step(kPoint, w, Eigen::Vector2d(u1[k], u2[k]), v[k]);
      dissipated += s.tangential.dot(s.slider - w);
      w = s.slider;
    }
    if (pass == 1) EXPECT_NEAR(dissipated, harmonic_work, 2e-3 * harmonic_work);
  }
}

TEST(CoupledSlip, StepTangentMatchesCentralDifferencesInSlip) {
  const Eigen::Vector2d w(1e-5, -2e-5), u(1.2e-4, 0.7e-4);
  const double v = 2e-6, h = 1e-10;
  const LawStep s = law().step(kPoint, w, u, v);
  ASSERT_EQ(s.state, ContactState::slip_positive);
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d up = u, um = u;
    up[j] += h;
    um[j] -= h;
    const Eigen::Vector2d fd =
        (law().step(kPoint, w, up, v).tangential - law().step(kPoint, w, um, v).tangential) / (2 * h);
    EXPECT_NEAR((fd - s.dt_du.col(j)).norm(), 0.0, 1e-6 * kPoint.kt) << j;
  }
  const Eigen::Vector2d fdv =
      (law().step(kPoint, w, u, v + h).tangential - law().step(kPoint, w, u, v - h).tangential) / (2 * h);
  EXPECT_NEAR((fdv - s.dt_dv).norm(), 0.0, 1e-6 * kPoint.kn);
  EXPECT_EQ(s.dn_dv, kPoint.kn);
}

TEST(CoupledSlip, AftJacobianMatchesCentralDifferences) {
  const Motion m = elliptical_motion();
  const AftOptions o = options(512);
  const AftResult r = law().harmonics(kPoint, m.u, m.v, o);
  ASSERT_TRUE(r.closed);
  const Eigen::Index c = m.v.size();
  Eigen::MatrixXd fd_u(2 * c, 2 * c), fd_v(2 * c, c), fd_n(c, c);
  const double h = 1e-11;
  for (Eigen::Index j = 0; j < 2 * c; ++j) {
    Eigen::VectorXd up = m.u, um = m.u;
    up[j] += h;
    um[j] -= h;
    fd_u.col(j) =
        (law().harmonics(kPoint, up, m.v, o).tangential - law().harmonics(kPoint, um, m.v, o).tangential) / (2 * h);
  }
  for (Eigen::Index j = 0; j < c; ++j) {
    Eigen::VectorXd vp = m.v, vm = m.v;
    vp[j] += h;
    vm[j] -= h;
    const AftResult plus = law().harmonics(kPoint, m.u, vp, o), minus = law().harmonics(kPoint, m.u, vm, o);
    fd_v.col(j) = (plus.tangential - minus.tangential) / (2 * h);
    fd_n.col(j) = (plus.normal - minus.normal) / (2 * h);
  }
  EXPECT_LT((fd_u - r.dtangential_du).norm(), 1e-4 * r.dtangential_du.norm());
  EXPECT_LT((fd_v - r.dtangential_dv).norm(), 1e-4 * r.dtangential_dv.norm());
  EXPECT_LT((fd_n - r.dnormal_dv).norm(), 1e-6 * r.dnormal_dv.norm());
}

// On a straight path the AFT of the law is the Jenkins AFT along the path, to rounding.
TEST(CoupledSlip, AftOnAStraightPathIsTheJenkinsAft) {
  const Eigen::VectorXd s = coefficients({0.0, 1.5e-4, 0.3e-4, 0.0, 0.1e-4, 0.0, 0.0});
  const Eigen::VectorXd v = coefficients({0.0, 0.0, 0.0, 3e-6, 0.0, 0.0, 0.0});
  const double a = 0.3;
  Eigen::VectorXd u(14);
  u << std::cos(a) * s, std::sin(a) * s;
  const AftResult two = law().harmonics(kPoint, u, v, options(256));
  const AftResult one = jenkins_law()->harmonics(kPoint, s, v, options(256));
  EXPECT_LT((std::cos(a) * two.tangential.head(7) + std::sin(a) * two.tangential.tail(7) - one.tangential).norm(),
            1e-9 * one.tangential.norm());
  EXPECT_LT((two.normal - one.normal).norm(), 1e-12 * one.normal.norm());
}

TEST(CoupledSlip, RefusesWhatItDoesNotHave) {
  const Motion m = elliptical_motion();
  AftOptions o = options(256);
  o.resolve_events = true;  // has none: the sampled march, the same numbers
  EXPECT_EQ(law().harmonics(kPoint, m.u, m.v, o).tangential,
            law().harmonics(kPoint, m.u, m.v, options(256)).tangential);
  o = options(256);
  o.law_derivatives = true;
  EXPECT_THROW((void)law().harmonics(kPoint, m.u, m.v, o), std::invalid_argument);
  EXPECT_THROW((void)law().harmonics(kPoint, m.u.head(7), m.v, options(256)), std::invalid_argument);
}

// A contact of two directions in the friction system: its stuck limit adds kt along both tangential
// rows; the time integration refuses it (one slider coordinate per contact), a second row without
// a law of two directions is refused too.
TEST(CoupledSlip, InTheFrictionSystem) {
  FrictionModel model;
  model.mass = Eigen::Matrix2d::Identity();
  model.stiffness = 1e6 * Eigen::Matrix2d::Identity();
  ContactElement c;
  c.point = kPoint;
  c.law = coupled_slip_law();
  c.tangential = Eigen::RowVector2d(1.0, 0.0);
  c.normal = Eigen::RowVector2d::Zero();
  c.tangential_2 = Eigen::RowVector2d(0.6, 0.8);
  model.contacts.push_back(c);
  FrictionModel for_hbm = model;
  validate_model(for_hbm, "test", false, true);
  const Eigen::MatrixXd k = stuck_stiffness(for_hbm);
  const Eigen::MatrixXd expected = model.stiffness + kPoint.kt * (c.tangential.transpose() * c.tangential +
                                                                  c.tangential_2.transpose() * c.tangential_2);
  EXPECT_LT((k - expected).norm(), 1e-9 * expected.norm());
  FrictionModel for_time = model;
  EXPECT_THROW(validate_model(for_time, "Newmark"), std::invalid_argument);
  FrictionModel one_direction = model;
  one_direction.contacts[0].law = jenkins_law();
  EXPECT_THROW(validate_model(one_direction, "test", false, true), std::invalid_argument);
}

}  // namespace
}  // namespace bb::friction
