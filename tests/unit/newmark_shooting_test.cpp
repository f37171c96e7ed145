// Shooting on the Newmark / HHT period map (timeint/newmark_shooting.hpp): the monodromy against
// central differences of the map through stick, slip and lift-off; the multipliers of a linear
// oscillator against the trapezoidal rule's amplification to the power of the steps; the periodic
// state against the same integrator marched to its steady state; the sweep's pass back down from
// the frequencies that converged.
#include "timeint/newmark_shooting.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/constants.hpp"
#include "common/csv_reader.hpp"
#include "friction_oscillator.hpp"
#include "oscillator_case.hpp"
#include "pipeline/run_case.hpp"
#include "temp_folder.hpp"
#include "timeint/steady_state.hpp"

namespace bb {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Two DOFs: x along the contact, y pressing it (N = 5 N + kn y, opening when y < -5e-6 m), both
// driven, so that the contact sticks, slips both ways and lifts off within a period at 150 Hz.
friction::FrictionModel pressed_slider() {
  friction::FrictionModel m;
  m.mass = MatrixXd::Identity(2, 2);
  m.stiffness = (MatrixXd(2, 2) << 1e6, 2e5, 2e5, 2e6).finished();
  m.damping = 2e-4 * m.stiffness;
  m.contacts.push_back({.point = {.kn = 1e6, .kt = 5e5, .mu = 0.4, .n0 = 5.0},
                        .tangential = (Eigen::RowVectorXd(2) << 1.0, 0.0).finished(),
                        .normal = (Eigen::RowVectorXd(2) << 0.0, 1.0).finished()});
  m.harmonic_load = (Eigen::VectorXcd(2) << 10.0, std::polar(8.0, 0.7)).finished();
  return m;
}

timeint::ShootingOptions options(int steps) {
  timeint::ShootingOptions o;
  o.dofs = {0, 1};
  o.steps_per_period = steps;
  o.harmonics = 3;
  o.floquet = true;
  o.warmup_periods = 50;
  return o;
}

// Each column of the monodromy equals a one-sided difference of the map. With fixed steps and a
// piecewise-linear law the map is piecewise affine, so a one-sided difference is exact to rounding;
// a periodic orbit may sit on a kink (here with alpha = -0.1 a contact closes at the slip limit), where
// only the side the Newton iteration stands on agrees.
TEST(NewmarkShooting, MonodromyEqualsDifferencesOfTheMapThroughStickSlipAndLiftOff) {
  const friction::FrictionModel m = pressed_slider();
  const double omega = kTwoPi * 150.0;
  for (const double alpha : {0.0, -0.1}) {
    const timeint::NewmarkShootingResult s = timeint::newmark_shooting(m, omega, options(256), alpha);
    ASSERT_TRUE(s.result.steady.converged) << s.result.steady.failure;
    int slips = 0, lifts = 0;
    for (const auto& c : s.result.steady.contacts[0]) {
      slips += c.state == friction::ContactState::slip_positive || c.state == friction::ContactState::slip_negative;
      lifts += c.state == friction::ContactState::lift_off;
    }
    EXPECT_GT(slips, 0);
    EXPECT_GT(lifts, 0);
    const timeint::PeriodMap map = timeint::newmark_period_map(m, omega, 256, alpha);
    const timeint::PeriodEval at = map(s.state, true);
    const double h = 1e-6 * s.state.head(2).cwiseAbs().maxCoeff();
    double worst = 0.0;
    for (Eigen::Index j = 0; j < s.state.size(); ++j) {
      VectorXd plus = s.state, minus = s.state;
      plus[j] += h;
      minus[j] -= h;
      const VectorXd forward = (map(plus, false).end - at.end) / h, backward = (at.end - map(minus, false).end) / h;
      const double scale = std::max(1.0, at.monodromy.col(j).cwiseAbs().maxCoeff());
      worst = std::max(worst, std::min((forward - at.monodromy.col(j)).cwiseAbs().maxCoeff(),
                                       (backward - at.monodromy.col(j)).cwiseAbs().maxCoeff()) /
                                  scale);
    }
    EXPECT_LT(worst, 1e-5) << "alpha = " << alpha;
  }
}

// A contact that never slips leaves a linear oscillator (k + kt): the trapezoidal rule maps each
// eigenvalue s of the first-order system to z = (1 + s h / 2) / (1 - s h / 2) per step, so the two
// largest multipliers are z^N; the stuck slider's multiplier 1 is left out.
TEST(NewmarkShooting, MultipliersOfALinearOscillatorAreTheTrapezoidalAmplificationToThePeriod) {
  test::FrictionOscillator o{.mass = 2.0, .damping = 8.0, .stiffness = 1e6, .force = 1.0, .contact = {}};
  o.contact = {.kn = 0.0, .kt = 1e6, .mu = 1e3, .n0 = 10.0};
  const double omega = kTwoPi * 120.0;
  const int steps = 128;
  timeint::ShootingOptions opt = options(steps);
  opt.dofs = {0};
  const timeint::NewmarkShootingResult s = timeint::newmark_shooting(o.model(), omega, opt, 0.0);
  ASSERT_TRUE(s.result.steady.converged) << s.result.steady.failure;
  const double wn = std::sqrt(2e6 / 2.0), zeta = 8.0 / (2 * 2.0 * wn);
  const std::complex<double> root(-zeta * wn, wn * std::sqrt(1 - zeta * zeta));
  const double h = kTwoPi / (omega * steps);
  const std::complex<double> z = std::pow((1.0 + root * h / 2.0) / (1.0 - root * h / 2.0), steps);
  ASSERT_GE(s.result.multipliers.size(), 2);
  EXPECT_NEAR(std::abs(s.result.multipliers[0]), std::abs(z), 1e-10);
  EXPECT_NEAR(std::abs(s.result.multipliers[1]), std::abs(z), 1e-10);
  EXPECT_NEAR(std::abs(s.result.multipliers[0].real()), std::abs(z.real()), 1e-9);
  EXPECT_TRUE(s.result.stable);
  // The periodic amplitude: the linear response to the step's second-order error.
  const double exact = 1.0 / std::abs(std::complex<double>(2e6 - 2.0 * omega * omega, 8.0 * omega));
  EXPECT_NEAR(s.result.steady.amplitude(0, 1) / exact, 1.0, 1e-3);
}

// The periodic state Newton finds is the one the same integrator reaches by marching (stable, so it
// attracts), with or without HHT damping.
TEST(NewmarkShooting, EqualsTheSameIntegratorMarchedToItsSteadyState) {
  const friction::FrictionModel m = pressed_slider();
  const double omega = kTwoPi * 150.0;
  for (const double alpha : {0.0, -0.1}) {
    const timeint::NewmarkShootingResult s = timeint::newmark_shooting(m, omega, options(256), alpha);
    ASSERT_TRUE(s.result.steady.converged) << s.result.steady.failure;
    EXPECT_TRUE(s.result.stable) << s.result.largest_multiplier;
    EXPECT_LE(s.result.steady.total_iterations, 8);
    timeint::SteadyStateOptions so;
    so.dofs = {0, 1};
    so.steps_per_period = 256;
    so.harmonics = 3;
    so.tolerance = 1e-11;
    so.max_cycles = 20000;
    so.newmark.alpha = alpha;
    const timeint::SteadyState marched = timeint::steady_state(m, omega, so);
    ASSERT_TRUE(marched.converged) << marched.failure;
    for (Eigen::Index d = 0; d < 2; ++d)
      for (Eigen::Index h = 1; h <= 3; ++h)
        EXPECT_NEAR(s.result.steady.amplitude(d, h), marched.amplitude(d, h), 1e-7 * marched.amplitude(d, 1))
            << "alpha " << alpha << " DOF " << d << " harmonic " << h;
  }
}

class NewmarkShootingCase : public test::TempFolderTest {};

// The oscillator's frf rows by column name (the project's CSV reading; "nan" cells read as NaN).
std::vector<std::map<std::string, double>> frf_rows(const std::filesystem::path& file) {
  const std::vector<std::string> names = read_csv_header(file);
  LineSource in(file);
  (void)in.next_content();  // the header
  std::vector<std::map<std::string, double>> rows;
  while (const std::optional<std::string_view> line = in.next_content()) {
    const std::vector<std::string_view> cells = split_csv(*line);
    std::map<std::string, double> row;
    for (size_t k = 0; k < names.size() && k < cells.size(); ++k) row[names[k]] = std::stod(std::string(cells[k]));
    rows.push_back(std::move(row));
  }
  return rows;
}

// The friction oscillator at 20 N, every 5 Hz over `range`, by shooting on the Newmark map with
// Floquet multipliers, plus `keys`.
std::string newmark_map_case(const std::string& range, const std::string& keys) {
  test::OscillatorCase c;
  c.levels = "[20.0]";
  c.range = range;
  c.step = "5.0";
  c.samples = "0";
  std::string text = test::oscillator_case_text(c);
  const std::string from = "type = \"hbm\"";
  text.replace(
      text.find(from), from.size(),
      "type = \"time\"\nmethod = \"shooting\"\nperiod_map = \"newmark\"\nalpha = -0.05\nfloquet = true\n" + keys);
  return text;
}

// Through a case: each frequency starts from the harmonic balance's solution there (compare_harmonics),
// Newton needs at most one correction from it (a run is the period evaluated, corrected, recorded),
// and the periodic amplitude agrees with the H = 9 balance to its truncation (3e-4 measured).
TEST_F(NewmarkShootingCase, EachFrequencyStartsFromTheHarmonicBalanceAndAgreesWithIt) {
  std::string text = newmark_map_case("[130.0, 260.0]", "steps_per_period = 512\ncompare_harmonics = 9\n");
  text.replace(text.find("harmonics = 1\n"), 14, "harmonics = 3\n");
  const RunOutcome o = run_case(write(text), {.out_dir = dir_ / "out", .study = false, .plots = false});
  ASSERT_EQ(o.record.status, RunStatus::no_checks) << o.record.message;
  const auto rows = frf_rows(o.out_dir / "frf.csv");
  EXPECT_EQ(rows.size(), 27u);
  for (const auto& r : rows) {
    const double hz = r.at("frequency_hz");
    EXPECT_EQ(r.at("steady"), 1.0) << hz;
    EXPECT_LE(r.at("cycles"), 4.0) << hz;
    EXPECT_TRUE(std::isnan(r.at("change"))) << hz;  // not marched
    EXPECT_NEAR(r.at("A.x_amp_m") / r.at("hbm_A.x_amp_m"), 1.0, 1e-3) << hz;
    EXPECT_EQ(r.at("stable"), 1.0) << hz;
  }
}

// Where Newton cannot reach the orbit (one iteration allowed, from 400 periods marched to 1e-3), the
// march to the steady state stands in, and Newton from its orbit needs no more than that one: every
// frequency periodic and stable, its amplitude that of the march, which the frf row keeps.
TEST_F(NewmarkShootingCase, WhereNewtonFailsTheMarchFindsTheOrbitAndNewtonFinishesFromIt) {
  const RunOutcome o =
      run_case(write(newmark_map_case("[150.0, 170.0]",
                                      "steps_per_period = 256\nmax_iterations = 1\nsteady_tolerance = 1e-9\n")),
               {.out_dir = dir_ / "out", .study = false, .plots = false});
  ASSERT_EQ(o.record.status, RunStatus::no_checks) << o.record.message;
  const auto rows = frf_rows(o.out_dir / "frf.csv");
  ASSERT_EQ(rows.size(), 5u);
  int marched = 0;
  for (const auto& r : rows) {
    EXPECT_EQ(r.at("steady"), 1.0) << r.at("frequency_hz");
    EXPECT_EQ(r.at("stable"), 1.0) << r.at("frequency_hz");
    EXPECT_EQ(r.at("period_multiple"), 1.0) << r.at("frequency_hz");
    EXPECT_LT(r.at("floquet_max"), 1.0) << r.at("frequency_hz");
    if (std::isfinite(r.at("change"))) {
      ++marched;
      EXPECT_LE(r.at("change"), 1e-9) << r.at("frequency_hz");
      EXPECT_NEAR(r.at("A.x_amp_m") / r.at("A.x_env_max_m"), 1.0, 1e-7) << r.at("frequency_hz");
    }
  }
  EXPECT_GE(marched, 1);
}

// A march that cannot settle (two periods allowed) leaves the frequency without a periodic solution:
// the frf row keeps what the motion did, and a peak resting on it leaves the run without a verdict.
TEST_F(NewmarkShootingCase, WhereTheMarchDoesNotSettleThereIsNoPeriodicSolutionAndNoVerdict) {
  const RunOutcome o = run_case(
      write(newmark_map_case("[150.0, 170.0]", "steps_per_period = 256\nmax_iterations = 1\nmax_cycles = 2\n")),
      {.out_dir = dir_ / "out", .study = false, .plots = false});
  EXPECT_EQ(o.record.status, RunStatus::solver_failed) << o.record.message;
  EXPECT_NE(o.record.message.find("no periodic solution found"), std::string::npos) << o.record.message;
  const auto rows = frf_rows(o.out_dir / "frf.csv");
  ASSERT_EQ(rows.size(), 5u);
  int without = 0;
  for (const auto& r : rows) {
    if (r.at("steady") == 1.0) continue;
    ++without;
    EXPECT_TRUE(std::isnan(r.at("floquet_max"))) << r.at("frequency_hz");
    EXPECT_TRUE(std::isfinite(r.at("change"))) << r.at("frequency_hz");
    EXPECT_GT(r.at("A.x_amp_m"), 0.0) << r.at("frequency_hz");  // the march's last period
  }
  EXPECT_GE(without, 1);
}

// Where the march settles but Newton cannot finish from its orbit (a tolerance below rounding), the
// report says so instead of calling the motion one that never repeats.
TEST_F(NewmarkShootingCase, AMarchThatSettlesWhereNewtonFailsIsReportedAsSettled) {
  const RunOutcome o = run_case(write(newmark_map_case("[150.0, 160.0]",
                                                       "steps_per_period = 256\nmax_iterations = 2\n"
                                                       "tolerance = 1e-30\nsteady_tolerance = 1e-6\n")),
                                {.out_dir = dir_ / "out", .study = false, .plots = false});
  bool settled = false, never = false;
  for (const std::string& w : o.record.warnings) {
    settled |= w.find("settled in the march but Newton failed from its orbit as well") != w.npos;
    never |= w.find("repeat within no period") != w.npos;
  }
  EXPECT_TRUE(settled) << o.record.message;
  EXPECT_FALSE(never) << o.record.message;
  const auto rows = frf_rows(o.out_dir / "frf.csv");
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& r : rows) {
    EXPECT_EQ(r.at("steady"), 0.0) << r.at("frequency_hz");
    EXPECT_EQ(r.at("period_multiple"), 1.0) << r.at("frequency_hz");
    EXPECT_LE(r.at("change"), 1e-6) << r.at("frequency_hz");
  }
}

// The sweep's pass back down (analysis/time_shooting.cpp, both maps): Coulomb's oscillator at
// Ff/F0 = 0.5 below resonance on the exact flow, kt = 1e14 N/m, where the stuck mass rings on kt.
// From the warm start Newton misses 80 Hz (measured: line search failed, |R| = 1.5e-10 m); shot
// again from 84 Hz's orbit it converges, within 2e-3 of the exact motion with one stop per half
// period (references/verification/coulomb_den_hartog_fp0.5_below.csv, first harmonic 8.8066e-6 m).
TEST_F(NewmarkShootingCase, AFrequencyMissedFromBelowIsShotAgainFromTheOrbitAboveIt) {
  const std::string text =
      "[case]\nname = \"stops\"\n[analysis]\ntype = \"time\"\nmethod = \"shooting\"\nfrequency_hz = [80.0, 84.0]\n"
      "step_hz = 4.0\nsweep = \"grid\"\nharmonics = 3\nsteps_per_period = 256\nmodal_damping = 0.0\n"
      "forces = [{ dof = \"A.x\", amplitude = 1.0 }]\nforce_levels = [6.0]\nresponses = [\"A.x\"]\n"
      "[analysis.model]\nname = \"oscillator\"\ndofs = [\"A.x\"]\nstiffness = [[1.0e6]]\nmass = [[1.0]]\n"
      "[[analysis.contact]]\nname = \"ground\"\ntangential = { \"A.x\" = 1.0 }\nkn = 1.0e12\nkt = 1.0e14\n"
      "mu = 0.3\nn0 = 10.0\n";
  const RunOutcome o = run_case(write(text), {.out_dir = dir_ / "out", .study = false, .plots = false});
  ASSERT_EQ(o.record.status, RunStatus::no_checks) << o.record.message;
  const auto rows = frf_rows(o.out_dir / "frf.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& r : rows) EXPECT_EQ(r.at("steady"), 1.0) << r.at("frequency_hz");
  EXPECT_NEAR(rows[0].at("A.x_amp_m") / 8.806589171106e-06, 1.0, 2e-3);
}

}  // namespace
}  // namespace bb
