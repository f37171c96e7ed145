// Base excitation (forced/base_motion_spec.hpp): an excitation of several harmonics in the friction
// model (friction/friction_system.hpp), the harmonic balance and Newmark driven by it, against
// closed forms; and a measured period of the table's acceleration read into its harmonics
// (cases/base_motion_file.hpp). Units: SI.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "cases/base_motion_file.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "frf/receptance.hpp"
#include "hbm/cycle_energy.hpp"
#include "hbm/harmonic_balance.hpp"
#include "temp_folder.hpp"
#include "timeint/newmark.hpp"

namespace bb {
namespace base_motion_test {
namespace {

using Complex = std::complex<double>;

// Two masses in a chain to the ground; the contact between them never slips (mu N0 = 3e5 N), so
// the balance is linear and each harmonic has its closed form.
friction::FrictionModel chain() {
  friction::FrictionModel m;
  m.mass = Eigen::Matrix2d{{1.0, 0.0}, {0.0, 0.5}};
  m.stiffness = Eigen::Matrix2d{{1.4e6, -4.0e5}, {-4.0e5, 4.0e5}};
  m.damping = Eigen::Matrix2d{{48.0, -8.0}, {-8.0, 8.0}};
  friction::ContactElement c{
      {.kn = 1e6, .kt = 2e5, .mu = 0.3, .n0 = 1e6}, Eigen::RowVector2d{-1.0, 1.0}, Eigen::RowVector2d::Zero()};
  m.contacts.push_back(c);
  const Eigen::Vector2d inertia = -(m.mass * Eigen::Vector2d::Ones());  // -M r per m/s^2
  m.harmonic_load = inertia.cast<Complex>() * 5.0;
  m.higher_loads = {Eigen::VectorXcd(), inertia.cast<Complex>() * std::polar(1.0, 40.0 * kRadPerDeg)};
  return m;
}

Eigen::VectorXcd closed_form(const friction::FrictionModel& m, int h, double omega) {
  Eigen::MatrixXd k = m.stiffness;
  k += 2e5 * Eigen::Matrix2d{{1.0, -1.0}, {-1.0, 1.0}};
  const double hw = h * omega;
  const Eigen::MatrixXcd d = k.cast<Complex>() - hw * hw * m.mass.cast<Complex>() + Complex(0.0, hw) * m.damping;
  return d.partialPivLu().solve(friction::excitation_at(m, h));
}

TEST(BaseMotion, ExcitationOfSeveralHarmonicsIsScaledAndReadAsOne) {
  friction::FrictionModel m = chain();
  EXPECT_TRUE(friction::excitation_at(m, 2).isZero(0.0));  // empty: zero, sized
  EXPECT_EQ(friction::excitation_at(m, 2).size(), 2);
  EXPECT_TRUE(friction::excitation_at(m, 7).isZero(0.0));  // beyond the last
  friction::scale_excitation(m, 3.0);
  EXPECT_EQ(friction::excitation_at(m, 1), chain().harmonic_load * 3.0);
  EXPECT_EQ(friction::excitation_at(m, 3), chain().higher_loads[1] * 3.0);
  friction::FrictionModel cyclic = chain();
  cyclic.nodal_diameters.sectors = 4;
  cyclic.nodal_diameters.diameters.resize(3);
  try {
    friction::validate_model(cyclic, "test", true);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("harmonic 1 only"), std::string::npos) << e.what();
  }
}

TEST(BaseMotion, HarmonicBalanceCarriesEveryHarmonicOfTheLoadExactly) {
  const friction::FrictionModel m = chain();
  const hbm::HarmonicBalance system(m, {.harmonics = 3, .tolerance = 1e-13});
  for (double f : {40.0, 80.0, 115.0, 240.0}) {
    const double omega = kTwoPi * f;
    const hbm::HbmSolution s = hbm::solve_at_frequency(system, omega);
    ASSERT_TRUE(s.converged) << s.failure;
    const Eigen::MatrixXd q = system.recover(s.x, omega);
    for (int h = 1; h <= 3; ++h) {
      const Eigen::VectorXcd z = closed_form(m, h, omega);
      const Eigen::VectorXcd got = q.col(2 * h - 1).cast<Complex>() - Complex(0.0, 1.0) * q.col(2 * h).cast<Complex>();
      EXPECT_LT((got - z).norm(), 1e-10 * closed_form(m, 1, omega).norm()) << f << " Hz, harmonic " << h;
    }
    // The table's work through both harmonics is what the dampers take.
    const hbm::CycleEnergy e = hbm::cycle_energy(system, s);
    EXPECT_NEAR(e.excitation, e.viscous + e.friction, 1e-10 * e.excitation) << f << " Hz";
  }
}

TEST(BaseMotion, NewmarkExcitationSumsTheHarmonics) {
  const friction::FrictionModel m = chain();
  const double omega = 500.0;
  const timeint::Excitation f = timeint::model_excitation(m, omega);
  for (double t : {0.0, 1.3e-3, 7.7e-3}) {
    const Eigen::VectorXd expected = (m.harmonic_load * std::polar(1.0, omega * t)).real() +
                                     (m.higher_loads[1] * std::polar(1.0, 3.0 * omega * t)).real();
    EXPECT_LT((f(t) - expected).norm(), 1e-14 * expected.norm() + 1e-14) << t;
  }
}

class BaseMotionFile : public test::TempFolderTest {
 protected:
  // a(t) = 5 cos(w t + phi) + 1 cos(3 w t + 3 phi + 40 deg) + tiny cos(5 ...) over `periods` periods.
  std::filesystem::path period(int periods, int per_period, double tiny, double phi = 0.7) const {
    std::string text = "# shaker table\ntime [ms],acceleration [g]\n";
    const int n = periods * per_period;
    for (int j = 0; j < n; ++j) {
      const double theta = kTwoPi * j / per_period, t = 0.01 * j / per_period;
      const double a = 5.0 * std::cos(theta + phi) + std::cos(3.0 * (theta + phi) + 40.0 * kRadPerDeg) +
                       tiny * std::cos(5.0 * (theta + phi));
      text += fmt::format("{:.17g},{:.17g}\n", 1e3 * t, a / 9.80665);
    }
    return write(text, "period.csv");
  }
  std::vector<BaseHarmonic> read(const std::filesystem::path& file, int periods, int highest, double& level) const {
    toml::table t;
    TomlReader r(t, "analysis.base_motion", dir_ / "case.toml");
    return base_harmonics_from_file(r, file, periods, highest, level);
  }
};

TEST_F(BaseMotionFile, RecoversEachHarmonicRelativeToTheFirstAndDropsTheNoiseFloor) {
  double level = 0.0;
  const std::vector<BaseHarmonic> h = read(period(2, 64, 1e-4), 2, 5, level);
  EXPECT_NEAR(level, 5.0, 1e-12);
  ASSERT_EQ(h.size(), 2u);  // harmonics 2 and 4 are zero, 5 below the floor (2e-5 of the first)
  EXPECT_EQ(h[0].order, 1);
  EXPECT_EQ(h[1].order, 3);
  EXPECT_NEAR(h[1].ratio, 0.2, 1e-13);
  EXPECT_NEAR(h[1].phase_deg, 40.0, 1e-10);  // the first's phase (0.7 rad) is the time origin
  const std::vector<BaseHarmonic> kept = read(period(1, 64, 0.05), 1, 5, level);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_NEAR(kept[2].ratio, 0.01, 1e-13);
  EXPECT_NEAR(kept[2].phase_deg, 0.0, 1e-9);
}

TEST_F(BaseMotionFile, RefusesTooFewSamplesAndTheWrongNumberOfPeriods) {
  double level = 0.0;
  EXPECT_THROW(read(period(1, 8, 0.0), 1, 5, level), InputError);  // 8 samples cannot resolve harmonic 5
  try {
    read(period(2, 64, 0.0), 1, 3, level);  // two periods read as one: no harmonic 1, energy in bin 2
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is `periods` the number of periods"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace base_motion_test
}  // namespace bb
