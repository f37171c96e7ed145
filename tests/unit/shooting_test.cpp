// Shooting on the exact piecewise-linear flow (timeint/shooting.hpp): Den Hartog's closed form, the
// linear limits, the monodromy against differences of the period map, Floquet multipliers of a
// damped oscillator.
#include "timeint/shooting.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "friction_oscillator.hpp"
#include "timeint/piecewise_flow.hpp"

namespace bb {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Den Hartog's largest displacement of the non-stop motion (references/verification/coulomb_den_hartog.py).
double den_hartog(double m, double k, double slip_force, double force, double omega) {
  const double r = omega / std::sqrt(k / m);
  const double t = std::tan(kPi / (2 * r)) / r;
  return force / k * std::sqrt(1 / std::pow(1 - r * r, 2) - std::pow(slip_force / force * t, 2));
}

test::FrictionOscillator coulomb(double slip_force, double kt) {
  test::FrictionOscillator o{.mass = 1.0, .damping = 0.0, .stiffness = 1e6, .force = 10.0, .contact = {}};
  o.contact = {.kn = 1e12, .kt = kt, .mu = slip_force / 10.0, .n0 = 10.0};
  return o;
}

timeint::ShootingOptions options() {
  timeint::ShootingOptions o;
  o.dofs = {0};
  o.floquet = true;
  return o;
}

// The Jenkins element tends to Coulomb's law as kt grows, but not as 1 / kt: where the mass reverses,
// it sticks on the spring kt with its acceleration u'' unbalanced, rings, and leaves the stick with a
// velocity near sqrt(4 mu N u'' / kt) (a stiff spring on a mass), so the largest displacement differs
// from Den Hartog's by about kt^-1/2 (measured at F/P = 0.5, 400 Hz: 4.3e-2 at kt = 1e10, 4.3e-3 at 1e12 = 1e6
// k, 4.3e-4 at 1e14; beyond, kt times the rounding of u - w puts Newton's floor near 1e-9 of the amplitude).
TEST(Shooting, TendsToDenHartogsClosedFormAsTheContactStiffens) {
  for (const double slip_force : {1.0, 3.0, 5.0})
    for (const double hz : {200.0, 300.0, 400.0}) {
      double error[3] = {};
      for (int i = 0; i < 3; ++i) {
        const double kt = std::pow(10.0, 10 + 2 * i);
        const test::FrictionOscillator o = coulomb(slip_force, kt);
        const double omega = 2 * kPi * hz;
        const timeint::ShootingResult s = timeint::shooting(o.model(), omega, options());
        ASSERT_TRUE(s.steady.converged) << s.steady.failure;
        error[i] = std::abs(s.largest[0] / den_hartog(o.mass, o.stiffness, slip_force, o.force, omega) - 1.0);
        EXPECT_LT(s.residual, 1e-8 * s.largest[0]);  // the Newton correction met 1e-9
      }
      EXPECT_LT(error[2], 5e-4) << slip_force << " N at " << hz << " Hz";
      EXPECT_GT(error[0] / error[1], 5.0);
      EXPECT_GT(error[1] / error[2], 5.0);
    }
}

// kn = 0 is a contact of constant normal load N0 (a joint, or a contact without normal terms): it
// neither opens nor closes. Its opening row used to read -N0 / kn = -inf, and the NaN it left in the
// modal weights shrank every piece of the flow to 2^-40 of a step (one frequency ran for minutes).
// The normal stiffness must not matter, so kn = 0 gives kn = 1e12's answer.
TEST(Shooting, ConstantNormalLoadWithoutNormalStiffnessNeedsNoOpeningTransition) {
  test::FrictionOscillator stiff = coulomb(3.0, 1e8), constant = stiff;
  constant.contact.kn = 0.0;
  const double omega = 2 * kPi * 300.0;
  const timeint::ShootingResult a = timeint::shooting(stiff.model(), omega, options());
  const timeint::ShootingResult b = timeint::shooting(constant.model(), omega, options());
  ASSERT_TRUE(a.steady.converged) << a.steady.failure;
  ASSERT_TRUE(b.steady.converged) << b.steady.failure;
  EXPECT_NEAR(b.largest[0], a.largest[0], 1e-9 * a.largest[0]);
}

// A contact so stiff (kt = 1e90, inside the case reader's range) that its motion needs pieces far
// shorter than a step ran until killed (issue 70): the pieces of a period are capped, and the cap,
// named, stops the shooting as a solver failure.
TEST(Shooting, StopsAtThePieceCapForAContactTooStiffToResolve) {
  const test::FrictionOscillator o = coulomb(3.0, 1e90);
  try {
    const timeint::ShootingResult s = timeint::shooting(o.model(), 2 * kPi * 300.0, options());
    ADD_FAILURE() << "kt = 1e90 was shot without reaching the cap: " << s.steady.failure;
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("PiecewiseFlow::kMaxPieces"), std::string::npos) << e.what();
  }
}

// A load so large (1e90 N against a slip force of 3 N) that the exponential of the flow's generator
// loses its accuracy came back as a "converged" motion of 0 (issue 70). It is a solver failure
// naming the exponential, never a converged result.
TEST(Shooting, RefusesAnExponentialThatLostItsAccuracyInsteadOfConvergingToZero) {
  test::FrictionOscillator o = coulomb(3.0, 1e14);
  o.force = 1e90;
  try {
    const timeint::ShootingResult s = timeint::shooting(o.model(), 2 * kPi * 300.0, options());
    EXPECT_FALSE(s.steady.converged) << "converged to " << s.largest[0] << " m";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("exponential"), std::string::npos) << e.what();
  }
}

TEST(Shooting, StuckContactIsTheLinearSpringExactly) {
  test::FrictionOscillator o{.mass = 2.0, .damping = 30.0, .stiffness = 1e6, .force = 1.0, .contact = {}};
  o.contact = {.kn = 1e8, .kt = 4e5, .mu = 1.0, .n0 = 1e3};  // mu N far above any spring force
  for (const double hz : {50.0, 130.0, 300.0}) {
    const double omega = 2 * kPi * hz;
    const timeint::ShootingResult s = timeint::shooting(o.model(), omega, options());
    ASSERT_TRUE(s.steady.converged) << s.steady.failure;
    const std::complex<double> d(o.stiffness + o.contact.kt - o.mass * omega * omega, omega * o.damping);
    EXPECT_NEAR(s.steady.amplitude(0, 1) / (o.force / std::abs(d)), 1.0, 1e-9);
    EXPECT_NEAR(s.largest[0] / (o.force / std::abs(d)), 1.0, 1e-9);
    EXPECT_EQ(s.transitions, 0);
    // The slider is free (neutral): left out; what remains are the two multipliers exp(lambda T).
    ASSERT_EQ(s.multipliers.size(), 2);
    const double zeta_wn = o.damping / (2 * o.mass);
    EXPECT_NEAR(std::abs(s.multipliers[0]), std::exp(-zeta_wn * 2 * kPi / omega), 1e-10);
    EXPECT_TRUE(s.stable);
  }
}

TEST(Shooting, FrictionlessContactIsTheBareOscillator) {
  test::FrictionOscillator o{.mass = 1.0, .damping = 20.0, .stiffness = 1e6, .force = 5.0, .contact = {}};
  o.contact = {.kn = 1e8, .kt = 1e9, .mu = 0.0, .n0 = 10.0};
  const double omega = 2 * kPi * 170.0;
  const timeint::ShootingResult s = timeint::shooting(o.model(), omega, options());
  ASSERT_TRUE(s.steady.converged) << s.steady.failure;
  const std::complex<double> d(o.stiffness - o.mass * omega * omega, omega * o.damping);
  EXPECT_NEAR(s.steady.amplitude(0, 1) / (o.force / std::abs(d)), 1.0, 1e-9);
}

// Two masses, a contact between them whose normal load follows their relative motion (it opens
// and closes every period), so every kind of transition occurs.
friction::FrictionModel lift_off_pair() {
  friction::FrictionModel m;
  m.mass = MatrixXd::Identity(2, 2);
  m.damping = 5.0 * MatrixXd::Identity(2, 2);
  m.stiffness = (MatrixXd(2, 2) << 2e6, -1e5, -1e5, 1e6).finished();
  friction::ContactElement c;
  c.point = {.kn = 5e5, .kt = 2e6, .mu = 0.4, .n0 = 3.0};
  c.tangential = (Eigen::RowVectorXd(2) << 1.0, -1.0).finished();
  c.normal = (Eigen::RowVectorXd(2) << 0.6, 0.3).finished();
  m.contacts.push_back(c);
  m.harmonic_load = (Eigen::VectorXcd(2) << std::complex<double>(20.0, 0.0), std::complex<double>(0.0, 8.0)).finished();
  return m;
}

// The period map of lift_off_pair() (2 DOFs, 1 contact) from x = (q, p, w), with its monodromy in j.
VectorXd pair_period(const timeint::PiecewiseFlow& flow, int steps, const VectorXd& x, MatrixXd* j) {
  timeint::FlowState st;
  st.q = x.head(2), st.p = x.segment(2, 2), st.w = x.tail(1);
  flow.settle(st);
  if (j) *j = flow.start_jacobian(st);
  timeint::PiecewiseFlow::Advance log;
  for (int k = 1; k <= steps; ++k) flow.advance(st, 2 * kPi * k / steps, j, 1000, log);
  VectorXd out(5);
  out << st.q, st.p, st.w;
  return out;
}

// Every column of the monodromy at `start` against central differences of the period map.
void expect_monodromy_equals_differences(const timeint::PiecewiseFlow& flow, int steps,
                                         const timeint::FlowState& start) {
  VectorXd x(5);
  x << start.q, start.p, start.w;
  MatrixXd j;
  pair_period(flow, steps, x, &j);
  for (int c = 0; c < 5; ++c) {
    const double h = 1e-7 * x.head(4).cwiseAbs().maxCoeff();
    VectorXd xp = x, xm = x;
    xp[c] += h, xm[c] -= h;
    const VectorXd fd = (pair_period(flow, steps, xp, nullptr) - pair_period(flow, steps, xm, nullptr)) / (2 * h);
    EXPECT_LT((fd - j.col(c)).norm(), 1e-5 * std::max(1.0, j.col(c).norm())) << "column " << c;
  }
}

TEST(Shooting, MonodromyEqualsDifferencesOfThePeriodMap) {
  friction::FrictionModel m = lift_off_pair();
  friction::validate_model(m, "test");
  const double omega = 2 * kPi * 180.0;
  timeint::ShootingOptions o = options();
  const timeint::ShootingResult s = timeint::shooting(m, omega, o);
  ASSERT_TRUE(s.steady.converged) << s.steady.failure;
  bool opened = false, slipped = false;
  for (const timeint::ContactSample& c : s.steady.contacts[0]) {
    opened |= c.state == friction::ContactState::lift_off;
    slipped |= c.state == friction::ContactState::slip_positive || c.state == friction::ContactState::slip_negative;
  }
  ASSERT_TRUE(opened && slipped) << "the test needs lift-off and slip";
  const timeint::PiecewiseFlow flow(m, omega, 2 * kPi / o.steps_per_period);
  expect_monodromy_equals_differences(flow, o.steps_per_period, s.start);
}

// Coulomb's stick (rigid) is the limit the Jenkins element only approaches as kt^-1/2: the exact flow
// with it meets Den Hartog's closed form to Newton's tolerance, whatever kt says.
TEST(Shooting, RigidStickIsDenHartogsClosedFormToNewtonsTolerance) {
  timeint::ShootingOptions o = options();
  o.rigid_stick = true;
  for (const double slip_force : {1.0, 3.0, 5.0})
    for (const double hz : {200.0, 300.0, 400.0}) {
      const test::FrictionOscillator c = coulomb(slip_force, 1e3);  // kt unused
      const double omega = 2 * kPi * hz;
      const timeint::ShootingResult s = timeint::shooting(c.model(), omega, o);
      ASSERT_TRUE(s.steady.converged) << s.steady.failure;
      EXPECT_NEAR(s.largest[0] / den_hartog(c.mass, c.stiffness, slip_force, c.force, omega), 1.0, 1e-8)
          << slip_force << " N at " << hz << " Hz";
      EXPECT_LE(s.transitions, 2);  // one reversal per half period, no ringing
      EXPECT_TRUE(s.stable);
    }
}

// The monodromy of the rigid flow (saltation where a contact sticks, the stuck rate projected out at
// the start) against central differences of the period map, in a model whose contact sticks, slips,
// opens and closes.
TEST(Shooting, RigidStickMonodromyEqualsDifferencesOfThePeriodMap) {
  friction::FrictionModel m = lift_off_pair();
  m.contacts[0].point.mu = 1.5;  // stuck for a third of the period
  m.contacts[0].point.n0 = 10.0;
  friction::validate_model(m, "test");
  const double omega = 2 * kPi * 180.0;
  timeint::ShootingOptions o = options();
  o.rigid_stick = true;
  const timeint::ShootingResult s = timeint::shooting(m, omega, o);
  ASSERT_TRUE(s.steady.converged) << s.steady.failure;
  bool opened = false, slipped = false, stuck = false;
  for (const timeint::ContactSample& c : s.steady.contacts[0]) {
    opened |= c.state == friction::ContactState::lift_off;
    stuck |= c.state == friction::ContactState::stick;
    slipped |= c.state == friction::ContactState::slip_positive || c.state == friction::ContactState::slip_negative;
    if (c.state == friction::ContactState::stick) EXPECT_LE(std::abs(c.tangential), 1.5 * c.normal * (1 + 1e-9));
  }
  ASSERT_TRUE(opened && slipped && stuck) << "the test needs lift-off, stick and slip";
  const timeint::PiecewiseFlow flow(m, omega, 2 * kPi / o.steps_per_period, true);
  expect_monodromy_equals_differences(flow, o.steps_per_period, s.start);
}

// A contact held rigidly all period stays at any u: Newton holds u where it has it (the period's
// equations are one short), and the answer is the model with the contact's DOFs tied, to rounding.
TEST(Shooting, RigidStickThroughoutIsTheTiedModel) {
  friction::FrictionModel m = lift_off_pair();
  m.contacts[0].point.mu = 3.0;
  m.contacts[0].point.n0 = 30.0;
  friction::validate_model(m, "test");
  timeint::ShootingOptions o = options();
  o.rigid_stick = true;
  for (const double hz : {120.0, 250.0, 300.0}) {
    const double omega = 2 * kPi * hz;
    const timeint::ShootingResult s = timeint::shooting(m, omega, o);
    ASSERT_TRUE(s.steady.converged) << s.steady.failure;
    EXPECT_EQ(s.transitions, 0);
    for (const timeint::ContactSample& c : s.steady.contacts[0]) EXPECT_EQ(c.state, friction::ContactState::stick);
    // q = (y, y) + const: 2 y'' + 10 y' + (2.8e6 + kn 0.9^2) y = 20 cos theta - 8 sin theta
    const std::complex<double> tied =
        std::complex<double>(20.0, 8.0) / std::complex<double>(2.8e6 + 5e5 * 0.81 - 2 * omega * omega, 10 * omega);
    EXPECT_NEAR(s.steady.amplitude(0, 1) / std::abs(tied), 1.0, 1e-9) << hz << " Hz";
    ASSERT_EQ(s.multipliers.size(), 4);  // u held: the neutral 1 left out; the slider's 0 kept
    EXPECT_NEAR(std::abs(s.multipliers[0]), std::exp(-2.5 * 2 * kPi / omega), 1e-9);
    EXPECT_TRUE(s.stable);
  }
}

// The first harmonic of q's samples by the DFT (trapezoidal rule over the period).
std::complex<double> sampled_first_harmonic(const MatrixXd& samples) {
  const Eigen::Index n = samples.rows() - 1;
  std::complex<double> sum = 0.0;
  const auto count = static_cast<double>(n);
  for (Eigen::Index k = 0; k < n; ++k)
    sum += samples(k, 0) * std::polar(2.0 / count, -2 * kPi * static_cast<double>(k) / count);
  return sum;
}

// The harmonics are the Fourier integrals of the exact motion, so they do not depend on the
// sub-intervals, and a DFT of many samples tends to them; on Den Hartog's stop motion (each piece by
// its modes) and on a critically damped oscillator, whose defective generator has no well-conditioned
// modal basis (each piece by Gauss-Legendre; its modes would be 3e-9 off).
TEST(Shooting, HarmonicsAreTheFourierIntegralsOfTheExactMotion) {
  test::FrictionOscillator stop = coulomb(3.0, 1e3);
  stop.force = 10.0 / 3.0;  // Ff/F0 = 0.9: one stop per half period at 100 Hz
  test::FrictionOscillator critical{.mass = 1.0, .damping = 2e3, .stiffness = 1e6, .force = 10.0, .contact = {}};
  critical.contact = {.kn = 1e12, .kt = 1e3, .mu = 0.3, .n0 = 10.0};
  for (const auto& [model, frequency] : {std::pair{stop, 100.0}, std::pair{critical, 150.0}}) {
    const test::FrictionOscillator& o = model;
    const double hz = frequency;
    timeint::ShootingOptions opt = options();
    opt.rigid_stick = true;
    opt.harmonics = 3;
    const auto at = [&](int steps) {
      opt.steps_per_period = steps;
      timeint::ShootingResult s = timeint::shooting(o.model(), 2 * kPi * hz, opt);
      EXPECT_TRUE(s.steady.converged) << s.steady.failure;
      return s;
    };
    const timeint::ShootingResult coarse = at(16), fine = at(64), dense = at(8192);
    const double first = fine.steady.amplitude(0, 1);
    // to the Newton tolerance (1e-9 of the motion) of each run
    EXPECT_NEAR(coarse.steady.amplitude(0, 1), first, 1e-8 * first) << hz << " Hz";
    EXPECT_NEAR(coarse.steady.amplitude(0, 3), fine.steady.amplitude(0, 3), 1e-8 * first) << hz << " Hz";
    EXPECT_NEAR(std::abs(sampled_first_harmonic(dense.samples)), first, 1e-9 * first) << hz << " Hz";  // 5e-12, 2e-12
    EXPECT_GT(std::abs(std::abs(sampled_first_harmonic(coarse.samples)) / first - 1.0), 1e-6);  // what the DFT missed
  }
}

TEST(Shooting, FailsWithItsResidualWhenNewtonIsCutShort) {
  const test::FrictionOscillator o = coulomb(3.0, 1e12);
  timeint::ShootingOptions opt = options();
  opt.max_iterations = 1;
  opt.tolerance = 1e-300;
  const timeint::ShootingResult s = timeint::shooting(o.model(), 2 * kPi * 250.0, opt);
  EXPECT_FALSE(s.steady.converged);
  EXPECT_NE(s.steady.failure.find("|R| ="), std::string::npos) << s.steady.failure;
  EXPECT_NE(s.steady.failure.find("1 Newton iterations"), std::string::npos) << s.steady.failure;
}

}  // namespace
}  // namespace bb
