// A Jenkins slider in parallel with a clearance spring (friction/clearance_spring), a law outside
// the Masing family, through the friction-law interface only: the dead zone's describing function
// (closed form), no dissipation of its own, damping without softening where a Masing law must
// soften, the AFT against an independent march of its time step, the AFT Jacobian and the step's
// tangent against central differences, its own parameters. Units: SI.
#include "friction/clearance_spring.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace bb::friction {
namespace clearance_spring_test {  // named: the unity build joins this file with others
namespace {

// Constant normal load (no normal terms in the AFT: v = 0); slip displacement xs = 1e-5 m.
constexpr PointParameters kPoint{.kn = 1.0e6, .kt = 1.0e6, .mu = 0.5, .n0 = 20.0};
constexpr double kXs = 1.0e-5;
constexpr double kPi = std::numbers::pi;

std::shared_ptr<const FrictionLaw> stiffened(double gap, double k_gap) {
  return with_clearance_spring(jenkins_law(), {gap, k_gap});
}

AftOptions options(int samples) {
  AftOptions o;
  o.samples = samples;
  return o;
}

// u = a cos(theta) + the higher terms given, H harmonics.
Eigen::VectorXd cosine(int harmonics, double a) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * harmonics + 1);
  u[1] = a;
  return u;
}

TEST(ClearanceSpring, ForceSlopeAndDescribingFunction) {
  const ClearanceSpring s{2e-5, 3e5};
  EXPECT_EQ(clearance_force(s, 1e-5), 0.0);
  EXPECT_EQ(clearance_force(s, -2e-5), 0.0);
  EXPECT_NEAR(clearance_force(s, 5e-5), 3e5 * 3e-5, 1e-15);
  EXPECT_NEAR(clearance_force(s, -5e-5), -3e5 * 3e-5, 1e-15);
  EXPECT_EQ(clearance_slope(s, 1e-5), 0.0);
  EXPECT_EQ(clearance_slope(s, -5e-5), 3e5);
  EXPECT_EQ(clearance_describing_stiffness(s, 1e-5), 0.0);
  // Far past the gap the spring is linear: K1 -> k_gap (1 - 4 r / pi) to first order in r.
  const double a = 1.0;
  EXPECT_NEAR(clearance_describing_stiffness(s, a), 3e5 * (1.0 - 4.0 * 2e-5 / kPi), 1e-6);
  EXPECT_THROW(validate(ClearanceSpring{0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(validate(ClearanceSpring{1e-5, -1.0}), std::invalid_argument);
  EXPECT_THROW(validate(ClearanceSpring{1e-5, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(with_clearance_spring(jenkins_law(), {-1e-5, 1.0}), std::invalid_argument);
}

// The first harmonic of the law less the slider's is the dead zone's describing function; the
// energy per cycle is the slider's closed form 4 mu N0 (a - xs): the spring dissipates nothing.
TEST(ClearanceSpring, FirstHarmonicIsTheDeadZonesDescribingFunctionAndItDissipatesNothing) {
  const ClearanceSpring spring{1.5e-5, 4e5};
  const auto law = stiffened(spring.gap, spring.stiffness);
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(7);
  for (double a : {0.5e-5, 1.2e-5, 2e-5, 5e-5, 3e-4}) {
    const Eigen::VectorXd u = cosine(3, a);
    // Integrated over its engaged pieces, the spring's harmonics are exact whatever the samples.
    for (int n : {64, 8192}) {
      const AftResult with = law->harmonics(kPoint, u, v, options(n));
      const AftResult without = jenkins_law()->harmonics(kPoint, u, v, options(n));
      const double k1 = (with.tangential[1] - without.tangential[1]) / a;
      EXPECT_NEAR(k1, clearance_describing_stiffness(spring, a), 1e-10 * spring.stiffness) << "a = " << a;
      EXPECT_NEAR(with.tangential[2], without.tangential[2], 1e-12) << "no quadrature term, a = " << a;
      EXPECT_NEAR(with.tangential[3], without.tangential[3], 1e-12) << "odd: no second harmonic, a = " << a;
    }
    const AftResult with = law->harmonics(kPoint, u, v, options(8192));
    const double energy = cycle_work(with.tangential, u);
    const double closed = a > kXs ? 4.0 * kPoint.mu * kPoint.n0 * (a - kXs) : 0.0;
    EXPECT_NEAR(energy, closed, 1e-9 + 1e-6 * closed) << "a = " << a;
  }
}

// A spread of springs: log-spaced gaps sharing k_gap; the describing function is their sum, and the
// AFT integrates each exactly. A spread smooths the stiffening one gap would put at one amplitude.
TEST(ClearanceSpring, ASpreadOfGapsIsTheSumOfItsSprings) {
  const ClearanceSpring spread{.gap = 1e-5, .stiffness = 8e5, .gap_max = 1e-3, .springs = 5};
  const std::vector<SpringShare> shares = clearance_springs(spread);
  ASSERT_EQ(shares.size(), 5u);
  EXPECT_EQ(shares.front().gap, 1e-5);
  EXPECT_NEAR(shares[1].gap, std::sqrt(1e-5 * 1e-4), 1e-18);  // half-decades apart
  EXPECT_NEAR(shares[2].gap, 1e-4, 1e-18);
  EXPECT_NEAR(shares.back().gap, 1e-3, 1e-18);
  double k1 = 0.0;
  for (const SpringShare& k : shares) {
    EXPECT_EQ(k.stiffness, 1.6e5);
    k1 += clearance_describing_stiffness({k.gap, k.stiffness}, 3e-4);
  }
  EXPECT_NEAR(clearance_describing_stiffness(spread, 3e-4), k1, 1e-9);
  // At 2e-4 m the first three springs are engaged.
  EXPECT_NEAR(clearance_force(spread, 2e-4),
              1.6e5 * ((2e-4 - shares[0].gap) + (2e-4 - shares[1].gap) + (2e-4 - shares[2].gap)), 1e-12);
  EXPECT_EQ(clearance_slope(spread, -2e-4), 4.8e5);
  const auto law = with_clearance_spring(jenkins_law(), spread);
  EXPECT_EQ(law->parameter_names(), (std::vector<std::string>{"gap", "gap_max", "k_gap"}));
  PointParameters free = kPoint;
  free.mu = 0.0;
  const AftResult r = law->harmonics(free, cosine(2, 3e-4), Eigen::VectorXd::Zero(5), options(64));
  EXPECT_NEAR(r.tangential[1] / 3e-4, k1, 1e-9 * 8e5);
  EXPECT_THROW(law->with_parameter("gap_max", 1e-6), std::invalid_argument);  // below the gap
  EXPECT_THROW(validate(ClearanceSpring{.gap = 1e-5, .stiffness = 1.0, .gap_max = 0.0, .springs = 3}),
               std::invalid_argument);
  EXPECT_THROW(validate(ClearanceSpring{.gap = 1e-5, .stiffness = 1.0, .gap_max = 2e-5, .springs = 1}),
               std::invalid_argument);
}

// Where the kinks fall between samples, sampling would add a quadrature term; the exact pieces
// do not, at any phase of the motion.
TEST(ClearanceSpring, NoSpuriousQuadratureAtAnyPhase) {
  const ClearanceSpring spring{9e-6, 1e6};
  const auto law = stiffened(spring.gap, spring.stiffness);
  PointParameters free = kPoint;
  free.mu = 0.0;  // the slider carries nothing: the law is the spring alone
  const double a = 3.13e-3;
  for (double phase : {0.0, 0.011, 0.3, 1.0, 2.5}) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3);
    u[1] = a * std::cos(phase);
    u[2] = a * std::sin(phase);
    const AftResult r = law->harmonics(free, u, Eigen::VectorXd::Zero(3), options(256));
    const double in_phase = (r.tangential[1] * u[1] + r.tangential[2] * u[2]) / (a * a);
    const double quadrature = (r.tangential[2] * u[1] - r.tangential[1] * u[2]) / (a * a);
    EXPECT_NEAR(in_phase, clearance_describing_stiffness(spring, a), 1e-9 * spring.stiffness) << phase;
    EXPECT_NEAR(quadrature, 0.0, 1e-9 * spring.stiffness) << phase;
  }
}

// Damping without softening. At the amplitude a the slider alone keeps only k_j(a) < kt in phase;
// a spring whose describing function makes up kt - k_j(a) keeps the joint's first-harmonic
// stiffness at kt while it dissipates as the slider does. A Masing law dissipating that much must
// have softened: for the slider, D = 4 mu N0 (a - xs) comes with kt - k_j(a) > 0.
TEST(ClearanceSpring, DampingGrowsWhileTheFirstHarmonicStiffnessStaysAtKt) {
  const double a = 3.0 * kXs;
  const Eigen::VectorXd u = cosine(1, a), v = Eigen::VectorXd::Zero(3);
  const AftResult slider = jenkins_law()->harmonics(kPoint, u, v, options(16384));
  const double kj = slider.tangential[1] / a;
  ASSERT_LT(kj, 0.8 * kPoint.kt);  // the Masing law has softened by 20 % or more
  const ClearanceSpring unit{kXs, 1.0};
  const double k_gap = (kPoint.kt - kj) / clearance_describing_stiffness(unit, a);
  const AftResult joint = stiffened(kXs, k_gap)->harmonics(kPoint, u, v, options(16384));
  EXPECT_NEAR(joint.tangential[1] / a, kPoint.kt, 1e-5 * kPoint.kt);
  EXPECT_NEAR(cycle_work(joint.tangential, u), 4.0 * kPoint.mu * kPoint.n0 * (a - kXs), 1e-5);
  EXPECT_GT(cycle_work(joint.tangential, u), 0.0);
}

// The AFT's samples against an independent march of the law's own time step over three periods
// of a multi-harmonic path with variable normal load.
TEST(ClearanceSpring, AftMatchesAMarchOfItsTimeStep) {
  const auto law = stiffened(1.2e-5, 7e5);
  const int h = 3, n = 512;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * h + 1), v = Eigen::VectorXd::Zero(2 * h + 1);
  u << 2e-6, 3e-5, -1e-5, 0.0, 4e-6, 2e-6, 0.0;
  v << 0.0, 3e-6, 1e-6, 0.0, 0.0, 0.0, 5e-7;
  const AftResult r = law->harmonics(kPoint, u, v, options(n));
  const auto at = [&](const Eigen::VectorXd& c, int k) {
    const double theta = 2.0 * kPi * k / n;
    double x = c[0];
    for (int j = 1; j <= h; ++j) x += c[2 * j - 1] * std::cos(j * theta) + c[2 * j] * std::sin(j * theta);
    return x;
  };
  Eigen::Vector2d slider = Eigen::Vector2d::Zero();
  double worst = 0.0;
  for (int period = 0; period < 3; ++period)
    for (int k = 0; k < n; ++k) {
      const LawStep s = law->step(kPoint, slider, {at(u, k), 0.0}, at(v, k));
      slider = s.slider;
      if (period == 2) worst = std::max(worst, std::abs(s.tangential[0] - r.t[k]));
    }
  EXPECT_LT(worst, 1e-10);
}

TEST(ClearanceSpring, JacobianAndTangentAgreeWithCentralDifferences) {
  const auto law = stiffened(1.2e-5, 7e5);
  const int h = 3;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * h + 1), v = Eigen::VectorXd::Zero(2 * h + 1);
  u << 1e-6, 3e-5, -1e-5, 0.0, 4e-6, 2e-6, 0.0;
  v << 0.0, 3e-6, 1e-6, 0.0, 0.0, 0.0, 5e-7;
  const AftOptions o = options(1024);
  const AftResult r = law->harmonics(kPoint, u, v, o);
  const double step = 1e-10;
  double worst = 0.0;
  for (Eigen::Index j = 0; j < u.size(); ++j) {
    Eigen::VectorXd up = u, down = u;
    up[j] += step;
    down[j] -= step;
    const Eigen::VectorXd fd =
        (law->harmonics(kPoint, up, v, o).tangential - law->harmonics(kPoint, down, v, o).tangential) / (2 * step);
    worst = std::max(worst, (fd - r.dtangential_du.col(j)).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-4 * kPoint.kt);
  // The step's tangent: past the gap it adds k_gap to the slider's.
  const double x = 2e-5;
  const LawStep s = law->step(kPoint, {0.0, 0.0}, {x, 0.0}, 0.0);
  const double fd = (law->step(kPoint, {0.0, 0.0}, {x + 1e-10, 0.0}, 0.0).tangential[0] -
                     law->step(kPoint, {0.0, 0.0}, {x - 1e-10, 0.0}, 0.0).tangential[0]) /
                    2e-10;
  EXPECT_NEAR(s.dt_du(0, 0), fd, 1e-6 * kPoint.kt);
  EXPECT_EQ(s.dt_du(0, 0), 7e5);  // slipping: the slider adds nothing along u
}

TEST(ClearanceSpring, OwnParametersAndTheSlidersThatCarryIt) {
  const auto law = stiffened(1.2e-5, 7e5);
  EXPECT_EQ(law->name(), "jenkins with a clearance spring");
  EXPECT_EQ(law->directions(), 1);
  EXPECT_FALSE(law->piecewise_linear());
  EXPECT_EQ(law->parameter_names(), (std::vector<std::string>{"gap", "k_gap"}));
  EXPECT_EQ(law->parameter("gap"), 1.2e-5);
  EXPECT_EQ(law->with_parameter("k_gap", 2e5)->parameter("k_gap"), 2e5);
  EXPECT_EQ(law->with_parameter("k_gap", 2e5)->parameter("gap"), 1.2e-5);
  EXPECT_THROW(law->with_parameter("gap", 0.0), std::invalid_argument);
  EXPECT_THROW(law->parameter("chi"), std::invalid_argument);
  EXPECT_THROW(jenkins_law()->parameter("gap"), std::invalid_argument);
  EXPECT_TRUE(jenkins_law()->parameter_names().empty());
  // The spring acts once per point: the first slider of a distribution carries it.
  EXPECT_EQ(slider_law(law, 0), law);
  EXPECT_EQ(slider_law(law, 1), jenkins_law());
  EXPECT_EQ(slider_law(jenkins_law(), 3), jenkins_law());
  EXPECT_THROW(with_clearance_spring(nullptr, {1e-5, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace clearance_spring_test
}  // namespace bb::friction
