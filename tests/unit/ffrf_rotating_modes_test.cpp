// Rotating modal analysis (ffrf/rotating_modes): Southwell-type frequencies of a uniform cantilever
// rotating about an axis through its root against published values, the in-plane (chordwise) law
// omega_c^2 = omega_f^2 - Omega^2, the Campbell diagram at rest against the non-rotating modal solver,
// the spin-softening divergence without stiffening at the predicted speed, the modal basis against
// the full model, engine-order crossings, and invariance under a rigid rotation of body and axis.
// Units: SI.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "ffrf/rotating_modes.hpp"
#include "ffrf_test_models.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {
namespace {

// Slender square beam (L / h = 50), hub radius 0: the axis z passes through the root-face centre.
test::BeamSpec southwell_beam() {
  test::BeamSpec b;
  b.length = 1.0;
  b.width = b.depth = 0.02;
  b.youngs_modulus = 2.0e11;
  b.poisson_ratio = 0.3;
  b.density = 7800.0;
  b.element = ElementType::hex8i;
  b.nx = 50;
  return b;
}

// sqrt(EI / (rho A L^4)) [rad/s]: dimensionless omega_bar = omega / this.
double frequency_unit(const test::BeamSpec& b) {
  const double i = b.depth * std::pow(b.width, 3) / 12.0, a = b.width * b.depth;
  return std::sqrt(b.youngs_modulus * i / (b.density * a * std::pow(b.length, 4)));
}

// Dimensionless first flapwise frequency of a uniform Euler-Bernoulli cantilever, hub radius 0.
// Omega_bar = 0: (beta L)^2 = 3.5160 (Thomson, Theory of Vibration with Applications, App. D.3).
// Omega_bar = 2..10: Hamza-Cherif & Houmat, ICAS 2004, "Natural frequencies of rotating cantilever
// flexible beams by using the p-version of the FEM", Table 2, as quoted in the test suite of
// octave-user/mboct-fem-pkg (inst/fem_tests_060.tst); they agree with Wright et al. (1982).
struct Southwell {
  double speed, flap;
};
const std::vector<Southwell> kSouthwell = {{0.0, 3.5160}, {2.0, 4.1373}, {4.0, 5.5850},
                                           {6.0, 7.3603}, {8.0, 9.2568}, {10.0, 11.2023}};

TEST(FfrfRotatingModes, CantileverFlapAndChordFrequenciesMatchSouthwellValues) {
  const test::BeamSpec b = southwell_beam();
  const test::FfrfSetup s = test::ffrf_setup(test::beam_model(b), test::modal_basis(24));
  const double unit = frequency_unit(b);
  for (const Southwell& ref : kSouthwell) {
    const ffrf::RotatingModes m = ffrf::rotating_modes(*s.projected, ref.speed * unit, {.n_modes = 4});
    // Square section: the in-plane (chord, y) mode is softened below the flap (z) mode.
    const double chord = m.frequencies_hz[0] * kTwoPi / unit, flap = m.frequencies_hz[1] * kTwoPi / unit;
    const double chord_ref = std::sqrt(ref.flap * ref.flap - ref.speed * ref.speed);
    std::printf(
        "  Omega_bar %4.1f: flap %.4f (published %.4f, %+.3f %%), chord %.4f (sqrt(flap^2 - Omega^2) %.4f, "
        "%+.3f %%)\n",
        ref.speed, flap, ref.flap, 100 * (flap / ref.flap - 1), chord, chord_ref, 100 * (chord / chord_ref - 1));
    EXPECT_NEAR(flap / ref.flap, 1.0, 2e-3) << "Omega_bar " << ref.speed;
    EXPECT_NEAR(chord / chord_ref, 1.0, 3e-3) << "Omega_bar " << ref.speed;
    EXPECT_TRUE(m.stable);
  }
}

TEST(FfrfRotatingModes, CampbellAtRestEqualsTheNonRotatingModalSolver) {
  test::BeamSpec b = southwell_beam();
  b.width = 0.03;  // separate the two bending directions
  b.nx = 30;
  for (const bool modal : {true, false}) {
    const test::FfrfSetup s =
        test::ffrf_setup(test::beam_model(b), modal ? test::modal_basis(12) : ffrf::ElasticBasisOptions{});
    const ffrf::CampbellDiagram c = ffrf::campbell_diagram(*s.projected, {0.0, 50.0}, {.n_modes = 6});
    const ModalSolution ref = lowest_modes(s.body->stiffness, s.body->mass, {.n_modes = 6});
    for (int k = 0; k < 6; ++k) {
      const double f_ref = std::sqrt(ref.eigenvalues[k]) / kTwoPi;
      EXPECT_NEAR(c.frequencies_hz(0, k), f_ref, 1e-8 * f_ref) << (modal ? "modal" : "nodal") << " mode " << k + 1;
    }
  }
}

// 2D: every motion is in the plane of rotation, M_p = M, so without stiffening
// K - Omega^2 M loses definiteness exactly at the first natural frequency at rest, and the
// gyroscopic term cannot stabilize a single negative stiffness (Thomson-Tait-Chetaev).
TEST(FfrfRotatingModes, SpinSofteningWithoutStiffeningDivergesAtTheFirstInPlaneFrequency) {
  test::BeamSpec b;
  b.length = 1.0;
  b.width = 0.1;
  b.element = ElementType::q4;
  b.nx = 40;
  b.ny = 4;
  const test::FfrfSetup s = test::ffrf_setup(test::beam_model(b), test::modal_basis(10));
  const double w1 = kTwoPi * s.basis->frequencies_hz[0];
  const double predicted = ffrf::divergence_speed(*s.projected, false);
  EXPECT_NEAR(predicted, w1, 1e-8 * w1);
  ffrf::RotatingModesOptions soft{.n_modes = 3, .stiffening = false};
  const ffrf::RotatingModes below = ffrf::rotating_modes(*s.projected, 0.98 * w1, soft);
  const ffrf::RotatingModes above = ffrf::rotating_modes(*s.projected, 1.02 * w1, soft);
  std::printf(
      "  omega_1 %.4f rad/s: at 0.98 omega_1 f1 = %.4f Hz (stable %d); at 1.02 omega_1 f1 = %.4f Hz, growth "
      "%.4f 1/s (stable %d)\n",
      w1, below.frequencies_hz[0], below.stable, above.frequencies_hz[0], above.max_growth_rate, above.stable);
  EXPECT_TRUE(below.stable);
  EXPECT_FALSE(above.stable);
  EXPECT_EQ(above.frequencies_hz[0], 0.0);
  EXPECT_GT(above.growth_rates[0], 0.0);
  // The static deflection exists below the divergence and is refused above it.
  EXPECT_NO_THROW((void)ffrf::centrifugal_deflection(*s.body, 0.98 * w1, {.stiffening = false}));
  try {
    (void)ffrf::centrifugal_deflection(*s.body, 1.02 * w1, {.stiffening = false});
    ADD_FAILURE() << "expected SolverError above the divergence speed";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
  // With stiffening the same speed is harmless.
  EXPECT_TRUE(ffrf::rotating_modes(*s.projected, 1.02 * w1, {.n_modes = 3}).stable);
  EXPECT_NO_THROW((void)ffrf::centrifugal_deflection(*s.body, 1.02 * w1, {.stiffening = true}));
}

// Without Coriolis the rotating eigenproblem is symmetric, (K + Omega^2 K_s1 - Omega^2 M_p) phi =
// omega^2 M phi, and the full model can be solved by Lanczos: the modal basis's error is measured.
TEST(FfrfRotatingModes, ModalBasisMatchesTheFullModelForTheLowestRotatingModes) {
  const test::BeamSpec b = southwell_beam();
  const Model model = test::beam_model(b);
  const ffrf::RotatingBody body = ffrf::build_rotating_body(model);
  const double speed = 8.0 * frequency_unit(b);
  Eigen::SparseMatrix<double> k_eff = body.stiffness + speed * speed * (body.geometric_stiffness - body.projected_mass);
  const ModalSolution full = lowest_modes(k_eff, body.mass, {.n_modes = 4});
  for (const int n_modes : {8, 16, 24}) {
    const ffrf::ElasticBasis basis = ffrf::make_elastic_basis(body, test::modal_basis(n_modes));
    const ffrf::ProjectedBody p = ffrf::project(body, basis);
    const ffrf::RotatingModes m = ffrf::rotating_modes(p, speed, {.n_modes = 4, .coriolis = false});
    double worst = 0.0;
    for (int k = 0; k < 4; ++k)
      worst = std::max(worst, std::abs(m.frequencies_hz[k] * kTwoPi / std::sqrt(full.eigenvalues[k]) - 1));
    std::printf("  %2d modes + %d static shapes: worst relative error of the 4 lowest rotating frequencies %.2e\n",
                n_modes, basis.static_shapes, worst);
    if (n_modes == 24) {
      EXPECT_LT(worst, 1e-4);
    }
  }
}

TEST(FfrfRotatingModes, EngineOrderCrossingsLieOnTheModeLines) {
  const test::BeamSpec b = southwell_beam();
  const test::FfrfSetup s = test::ffrf_setup(test::beam_model(b), test::modal_basis(12));
  const double unit = frequency_unit(b);
  std::vector<double> speeds;
  for (int i = 0; i <= 20; ++i) speeds.push_back(i * 0.6 * unit);
  const ffrf::CampbellDiagram c = ffrf::campbell_diagram(*s.projected, speeds, {.n_modes = 2});
  const auto crossings = ffrf::engine_order_crossings(*s.projected, c, {2, 3}, {.n_modes = 2});
  // Flap: f^2 grows like (1.19 Omega)^2 at high speed (Southwell coefficient), so EO 2 and 3 cross both
  // lines once each in this range; the chord line (f^2 = f_flap^2 - Omega^2) crosses too.
  EXPECT_GE(crossings.size(), 3u);
  for (const auto& x : crossings) {
    const ffrf::RotatingModes m = ffrf::rotating_modes(*s.projected, x.speed, {.n_modes = 2});
    std::printf("  EO %d x mode %d at %.5f rad/s, %.5f Hz\n", x.engine_order, x.mode, x.speed, x.frequency_hz);
    EXPECT_NEAR(m.frequencies_hz[x.mode - 1], x.engine_order * x.speed / kTwoPi, 1e-7 * x.frequency_hz);
  }
}

TEST(FfrfRotatingModes, AreInvariantUnderARigidRotationOfBodyAndAxis) {
  test::BeamSpec b = southwell_beam();
  b.nx = 20;
  b.width = 0.03;
  const Model model = test::beam_model(b);
  const test::FfrfSetup plain = test::ffrf_setup(model, test::modal_basis(10));
  const Eigen::Matrix3d q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  Model turned = model;
  turned.mesh.coords = (model.mesh.coords * q.transpose()).eval();
  ffrf::RotationAxis axis;
  axis.direction = q * Eigen::Vector3d::UnitZ();
  const test::FfrfSetup rotated = test::ffrf_setup(turned, test::modal_basis(10), axis);
  const double speed = 6.0 * frequency_unit(b);
  const auto a = ffrf::rotating_modes(*plain.projected, speed, {.n_modes = 5});
  const auto r = ffrf::rotating_modes(*rotated.projected, speed, {.n_modes = 5});
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(r.frequencies_hz[k], a.frequencies_hz[k], 1e-8 * a.frequencies_hz[k]);
  EXPECT_NEAR(rotated.body->mass_properties.axis_inertia, plain.body->mass_properties.axis_inertia,
              1e-12 * plain.body->mass_properties.axis_inertia);
}

TEST(FfrfRotatingModes, TimeStepResolvesTheRequestedRotatingMode) {
  const test::BeamSpec b = southwell_beam();
  const test::FfrfSetup s = test::ffrf_setup(test::beam_model(b), test::modal_basis(8));
  const double speed = 4.0 * frequency_unit(b);
  const ffrf::RotatingModes m = ffrf::rotating_modes(*s.projected, speed, {.n_modes = 3});
  EXPECT_DOUBLE_EQ(ffrf::time_step_resolving(*s.projected, speed), 1.0 / (40.0 * m.frequencies_hz[0]));
  EXPECT_DOUBLE_EQ(ffrf::time_step_resolving(*s.projected, speed, 3, 20), 1.0 / (20.0 * m.frequencies_hz[2]));
}

TEST(FfrfRotatingModes, LargeNodalBasisAsksForAModalOne) {
  test::BeamSpec b = southwell_beam();
  const test::FfrfSetup s = test::ffrf_setup(test::beam_model(b));
  try {
    (void)ffrf::rotating_modes(*s.projected, 10.0, {.max_dense_size = 100});
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("modal elastic basis"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb
