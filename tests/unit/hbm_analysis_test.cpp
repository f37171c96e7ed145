// The hbm analysis through the case pipeline (parse_case_file -> build_model -> run_hbm) on lumped
// models written in a temporary case: the stuck and frictionless limits of a friction oscillator
// against their closed forms, the energy balance at every peak, the in-phase peak of two identical
// blades coupled by a contact, and a contact naming an unknown DOF. Units: SI.
#include "analysis/hbm_analysis.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <string>

#include "cases/case_spec.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "forced/hbm_level.hpp"
#include "forced/level_relay.hpp"
#include "model/build_model.hpp"
#include "oscillator_case.hpp"
#include "pipeline/run_case.hpp"
#include "temp_folder.hpp"
#include "two_blades_case.hpp"

namespace bb {
namespace {

// m = 1 kg, k = 1e6 N/m, zeta = 0.01 (c = 20 N s/m); a Jenkins contact to the ground with
// kt = 1e6 N/m and constant normal load n0 = 30 N; mu and the force levels are filled in.
std::string oscillator_case(const std::string& mu, const std::string& levels,
                            const std::string& range = "[130.0, 260.0]") {
  test::OscillatorCase c;
  c.mu = mu;
  c.levels = levels;
  c.range = range;
  c.tolerance = "1e-12";
  return test::oscillator_case_text(c);
}

// Peak of |1 / (k - w^2 m + i w c)| with c = 2 zeta sqrt(k_mode m) (the damping of the mode, here
// the free one): (frequency [Hz], amplitude per newton).
std::pair<double, double> linear_peak(double k, double m, double c) {
  const double zeta = c / (2 * std::sqrt(k * m));
  return {std::sqrt(k / m) * std::sqrt(1 - 2 * zeta * zeta) / kTwoPi, 1 / (2 * zeta * k * std::sqrt(1 - zeta * zeta))};
}

double receptance(double k, double m, double c, double hz) {
  const double w = kTwoPi * hz;
  return 1 / std::abs(std::complex<double>(k - w * w * m, w * c));
}

class HbmAnalysis : public test::TempFolderTest {
 protected:
  HbmOutcome run(const std::string& text) {
    const CaseSpec spec = parse_case_file(write(text));
    return run_hbm(build_model(spec.model), std::get<HbmSpec>(spec.analysis));
  }
  static double column(const ResultTable& t, const std::string& name, int row) {
    const std::optional<int> c = t.column_index(name);
    if (!c) throw std::runtime_error("no column " + name);
    return t.values(row, *c);
  }
};

TEST_F(HbmAnalysis, SmallestLevelIsTheClosedFormStuckOscillator) {
  // 0.01 N moves the contact by 3.5e-7 m, far below mu n0 / kt = 9e-6 m: the contact is a spring
  // kt, so the oscillator is linear with k + kt = 2e6 N/m and the same c = 20 N s/m.
  const HbmOutcome o = run(oscillator_case("0.3", "[0.01]"));
  ASSERT_EQ(o.levels.size(), 1u);
  ASSERT_EQ(o.levels[0].peaks.size(), 1u);
  const HbmPeak& peak = o.levels[0].peaks[0];
  ASSERT_TRUE(peak.solution.converged);
  const auto [hz, per_n] = linear_peak(2.0e6, 1.0, 20.0);
  // The golden-section search ends within ~5e-4 Hz of the peak: 2e-6 in frequency, and
  // 0.5 (df / (zeta f))^2 ~ 5e-8 below the peak in amplitude.
  EXPECT_NEAR(peak.frequency_hz / hz - 1, 0.0, 5e-6);
  EXPECT_NEAR(peak.amplitude / 0.01 / per_n - 1, 0.0, 1e-7);
  // every frequency of the sweep, not only the peak
  const HbmLevel& level = o.levels[0];
  for (size_t i = 0; i < level.frequency_hz.size(); i += 50)
    EXPECT_NEAR(
        level.amplitude(static_cast<Eigen::Index>(i), 0) / 0.01 / receptance(2.0e6, 1.0, 20.0, level.frequency_hz[i]) -
            1,
        0.0, 1e-9)
        << level.frequency_hz[i] << " Hz";
  for (const friction::ContactState s : peak.solution.contacts.at(0).state) EXPECT_EQ(s, friction::ContactState::stick);
}

TEST_F(HbmAnalysis, FrictionlessContactGivesTheFreeLinearOscillatorAtEveryLevel) {
  // mu = 0: the slider always slips with T = 0, so the response is 1 / |k - w^2 m + i w c|.
  const HbmOutcome o = run(oscillator_case("0.0", "[0.01, 100.0, 10000.0]", "[140.0, 180.0]"));
  const auto [hz, per_n] = linear_peak(1.0e6, 1.0, 20.0);
  for (const HbmLevel& level : o.levels) {
    ASSERT_EQ(level.peaks.size(), 1u);
    ASSERT_TRUE(level.peaks[0].solution.converged);
    EXPECT_NEAR(level.peaks[0].frequency_hz / hz - 1, 0.0, 5e-6) << level.force << " N";
    EXPECT_NEAR(level.peaks[0].amplitude / level.force / per_n - 1, 0.0, 1e-7) << level.force << " N";
    for (size_t i = 0; i < level.frequency_hz.size(); i += 20)
      EXPECT_NEAR(level.amplitude(static_cast<Eigen::Index>(i), 0) / level.force /
                          receptance(1.0e6, 1.0, 20.0, level.frequency_hz[i]) -
                      1,
                  0.0, 1e-9)
          << level.force << " N, " << level.frequency_hz[i] << " Hz";
    EXPECT_EQ(level.peaks[0].energy.friction, 0.0);
  }
}

TEST_F(HbmAnalysis, EnergyBalancesAtEveryPeakFromStuckToGrossSlip) {
  for (const std::string& text :
       {oscillator_case("0.3", "[0.01, 1.0, 3.0, 10.0, 100.0, 10000.0]"), std::string(test::kTwoBladesCase)}) {
    const HbmOutcome o = run(text);
    const ResultTable& t = o.tables.at("energy_balance");
    const int expected = static_cast<int>(o.levels.size()) * (o.prepared.ip_oop ? 2 : 1);
    ASSERT_EQ(t.values.rows(), expected);
    for (int r = 0; r < t.values.rows(); ++r) {
      EXPECT_LT(column(t, "relative_error", r), 1e-6) << "peak " << column(t, "peak", r);
      EXPECT_GT(column(t, "excitation_j", r), 0.0);
      EXPECT_GE(column(t, "friction_j", r), -1e-12 * column(t, "excitation_j", r));  // friction dissipates
    }
    // levels that slip dissipate in the contact
    bool slipped = false;
    for (int r = 0; r < t.values.rows(); ++r)
      slipped |= column(t, "friction_j", r) > 0.01 * column(t, "excitation_j", r);
    EXPECT_TRUE(slipped);
  }
}

// The levels share the prepared model (read only) and each level's first solution, handed to the
// next level in list order: swept on three threads they give the tables of the serial run, every
// bit (timings aside).
TEST_F(HbmAnalysis, LevelsSweptInParallelAreTheSerialRunBitForBit) {
  std::string text = test::kTwoBladesCase;
  text.replace(text.find("harmonics = 1\n"), 14, "harmonics = 1\nthreads = 1\n");
  const HbmOutcome serial = run(text);
  std::string parallel_text = text;
  parallel_text.replace(parallel_text.find("threads = 1"), 11, "threads = 3");
  const HbmOutcome parallel = run(parallel_text);
  ASSERT_EQ(serial.tables.size(), parallel.tables.size());
  for (const auto& [name, a] : serial.tables) {
    const ResultTable& b = parallel.tables.at(name);
    ASSERT_EQ(a.columns, b.columns) << name;
    ASSERT_EQ(a.values.rows(), b.values.rows()) << name;
    ASSERT_EQ(a.values.cols(), b.values.cols()) << name;
    for (Eigen::Index r = 0; r < a.values.rows(); ++r)
      for (Eigen::Index c = 0; c < a.values.cols(); ++c) {
        if (a.columns[static_cast<size_t>(c)] == "seconds") continue;  // wall times
        const double x = a.values(r, c), y = b.values(r, c);
        EXPECT_TRUE(x == y || (std::isnan(x) && std::isnan(y)))
            << name << "(" << r << ", " << c << "): " << x << " " << y;
      }
    EXPECT_EQ(a.text, b.text) << name;
  }
}

// A level's first point starts from the previous level's first solution (handed on by the relay):
// given the very solution, the first point takes no Newton iteration and is that solution, where
// the static start needs some (stick-slip at the first frequency, H = 5).
TEST_F(HbmAnalysis, AFirstPointStartsFromThePreviousLevelsSolution) {
  std::string text = test::kTwoBladesCase;
  text.replace(text.find("harmonics = 1\n"), 14, "harmonics = 5\n");
  text.replace(text.find("force_levels = [0.01, 10.0, 1000.0]"), 35, "force_levels = [45.0]");
  const CaseSpec spec = parse_case_file(write(text));
  const HbmSpec& hbm = std::get<HbmSpec>(spec.analysis);
  const PreparedHbm prepared = prepare_hbm(build_model(spec.model), hbm);
  const HbmLevel alone = sweep_hbm_level(prepared, hbm, 45.0, 5);
  const hbm::ContinuationPoint& from_static = alone.path.points.front();
  ASSERT_GT(from_static.iterations, 0);
  LevelRelay relay(2);
  relay.publish(0, LevelStart{from_static.x, 5, 45.0});
  const LevelLink link{relay, 1};
  const HbmLevel chained = sweep_hbm_level(prepared, hbm, 45.0, 5, {}, true, &link);
  const hbm::ContinuationPoint& from_neighbour = chained.path.points.front();
  EXPECT_EQ(from_neighbour.iterations, 0);
  EXPECT_EQ(from_neighbour.x, from_static.x);
}

TEST_F(HbmAnalysis, InPhasePeakOfSymmetricBladesIsTheClosedFormAtEveryLevel) {
  // a_t = (1, -1) is orthogonal to the IP mode (1, 1) and M, C, K are diagonal in (IP, OOP): the IP
  // component (q_A + q_B) / 2 is (F / 2m) / (w1^2 - w^2 + 2 i zeta w1 w), w1^2 = k / m, at any level.
  const HbmOutcome o = run(test::kTwoBladesCase);
  const double c_ip = 2 * 0.01 * std::sqrt(1.0e6 * 1.0);
  const auto [ip_hz, per_n] = linear_peak(1.0e6, 1.0, c_ip);
  ASSERT_EQ(o.levels.size(), 3u);
  for (const HbmLevel& level : o.levels) {
    ASSERT_EQ(level.peaks.size(), 2u);
    const HbmPeak& ip = level.peaks[0];
    ASSERT_EQ(ip.kind, "IP");
    ASSERT_TRUE(ip.solution.converged);
    EXPECT_NEAR(ip.frequency_hz / ip_hz - 1, 0.0, 5e-6) << level.force << " N";
    EXPECT_NEAR(ip.component / level.force / (0.5 * per_n) - 1, 0.0, 1e-7) << level.force << " N";
    for (Eigen::Index i = 0; i < level.components.rows(); i += 25)
      EXPECT_NEAR(level.components(i, 0) / level.force /
                          (0.5 * receptance(1.0e6, 1.0, c_ip, level.frequency_hz[static_cast<size_t>(i)])) -
                      1,
                  0.0, 1e-9);
  }
  // The OOP peak: stuck at 0.01 N (w^2 = (k + 2 kc + 2 kt) / m), near the free one at 1 kN
  // ((k + 2 kc) / m), each within the peak's shift by the damping (8e-5 stuck).
  EXPECT_NEAR(o.levels[0].peaks[1].frequency_hz / (std::sqrt(1.6e6) / kTwoPi) - 1, 0.0, 2e-4);
  EXPECT_NEAR(o.levels[2].peaks[1].frequency_hz / (std::sqrt(1.2e6) / kTwoPi) - 1, 0.0, 2e-3);
  EXPECT_GT(o.levels[1].peaks[1].frequency_hz, o.levels[2].peaks[1].frequency_hz);
  EXPECT_LT(o.levels[1].peaks[1].frequency_hz, o.levels[0].peaks[1].frequency_hz);
}

// With two Newton iterations per start, the 10 Hz grid steps near the slipping resonance cannot be
// taken; the sweep bridges each by arclength to the next grid frequency instead of recording a
// failure, and finds the peak of a sweep whose Newton is allowed enough iterations.
TEST_F(HbmAnalysis, GridStepsNewtonCannotTakeAreBridgedByArclength) {
  test::OscillatorCase c;
  c.levels = "[20.0]";
  c.step = "10.0";
  const HbmOutcome reference = run(test::oscillator_case_text(c));
  c.analysis_extra = "max_iterations = 2\n";
  const HbmOutcome bridged = run(test::oscillator_case_text(c));
  const HbmLevel& a = reference.levels[0];
  const HbmLevel& b = bridged.levels[0];
  EXPECT_TRUE(a.failed_hz.empty());
  EXPECT_TRUE(b.failed_hz.empty());
  EXPECT_GT(b.path.points.size(), 2 * a.path.points.size());  // the bridges' own points
  ASSERT_EQ(b.peaks.size(), 1u);
  EXPECT_TRUE(b.peaks[0].trusted) << b.peaks[0].doubt;
  EXPECT_NEAR(b.peaks[0].frequency_hz, a.peaks[0].frequency_hz, 1e-5 * a.peaks[0].frequency_hz);
  EXPECT_NEAR(b.peaks[0].amplitude, a.peaks[0].amplitude, 1e-6 * a.peaks[0].amplitude);
}

// A Coulomb-like contact (kt = 1e4 k): with 64 samples of the sampled AFT the stick-slip kinks fall
// between samples and the peak of the near-stuck level is off by percents; aft_tolerance raises the
// samples until the estimated error is met, and the result agrees with a 4096-sample sweep.
TEST_F(HbmAnalysis, AftToleranceRaisesTheSamplesUntilTheStiffContactIsResolved) {
  test::OscillatorCase c;
  c.analysis_extra = "aft = \"samples\"\n";
  c.kt = "1.0e10";
  c.levels = "[12.0]";
  c.range = "[130.0, 220.0]";
  c.step = "1.0";
  c.samples = "4096";
  const HbmPeak reference = run(test::oscillator_case_text(c)).levels[0].peaks[0];
  c.samples = "64";
  const HbmLevel coarse = run(test::oscillator_case_text(c)).levels[0];
  c.analysis_extra += "aft_tolerance = 1e-3\n";
  const HbmLevel raised = run(test::oscillator_case_text(c)).levels[0];

  const auto relative = [&](const HbmPeak& pk) { return std::abs(pk.amplitude / reference.amplitude - 1); };
  EXPECT_GT(coarse.peaks[0].sampling_error, 1e-2);
  EXPECT_GT(relative(coarse.peaks[0]), 3e-2);  // 64 samples: the estimate is right to warn
  EXPECT_TRUE(coarse.sampling_trials.empty());
  ASSERT_GE(raised.sampling_trials.size(), 2u);
  EXPECT_EQ(raised.sampling_trials.front().samples, 64);
  EXPECT_EQ(raised.sampling_trials.back().samples, raised.samples);
  EXPECT_GT(raised.samples, 64);
  EXPECT_LE(raised.peaks[0].sampling_error, 1e-3);
  EXPECT_LT(relative(raised.peaks[0]), 1e-3);
  EXPECT_NEAR(raised.peaks[0].frequency_hz, reference.frequency_hz, 1e-3 * reference.frequency_hz);
}

// A Coulomb-like contact (kt = 100 k) swept through its stick-slip resonance at one level.
test::OscillatorCase coulomb_like_near_resonance() {
  test::OscillatorCase c;
  c.kt = "1.0e8";
  c.levels = "[12.0]";
  c.range = "[130.0, 220.0]";
  c.step = "1.0";
  c.samples = "2048";
  return c;
}

// A Coulomb-like contact (kt = 100 k) near its stick-slip resonance: the single harmonic leaves a
// few percent of the motion in harmonics 3 and 5. harmonic_tolerance raises H per level until the
// estimated share is met; the peak is then closer to a fixed H = 15 sweep than the H = 1 peak,
// the table lists every H tried, and a failed or unmet trial is never the one kept.
TEST_F(HbmAnalysis, HarmonicToleranceRaisesHUntilTheTruncationShareIsMet) {
  test::OscillatorCase c = coulomb_like_near_resonance();
  const std::string h1_text = test::oscillator_case_text(c);
  std::string reference_text = h1_text;
  reference_text.replace(reference_text.find("harmonics = 1\n"), 14, "harmonics = 15\n");
  const HbmPeak reference = run(reference_text).levels[0].peaks[0];
  const HbmLevel single = run(h1_text).levels[0];
  c.analysis_extra = "harmonic_tolerance = 1e-2\nmax_harmonics = 15\n";
  const HbmOutcome adaptive = run(test::oscillator_case_text(c));
  const HbmLevel& chosen = adaptive.levels[0];

  const auto error = [&](const HbmPeak& pk) { return std::abs(pk.amplitude / reference.amplitude - 1); };
  std::printf("  H = 1: share %.3e, amplitude error %.3e; chosen H = %d: share %.3e, error %.3e (%zu trials)\n",
              single.peaks[0].truncation.largest(), error(single.peaks[0]), chosen.harmonics,
              chosen.peaks[0].truncation.largest(), error(chosen.peaks[0]), chosen.harmonic_trials.size());
  EXPECT_GT(single.peaks[0].truncation.largest(), 1e-2);
  EXPECT_GT(chosen.harmonics, 1);
  EXPECT_LE(chosen.peaks[0].truncation.largest(), 1e-2);
  EXPECT_LT(error(chosen.peaks[0]), error(single.peaks[0]));
  ASSERT_GE(chosen.harmonic_trials.size(), 2u);
  EXPECT_EQ(chosen.harmonic_trials.front().harmonics, 1);
  int kept = 0;
  for (const HbmLevel::HarmonicTrial& t : chosen.harmonic_trials)
    if (t.chosen) {
      ++kept;
      EXPECT_EQ(t.harmonics, chosen.harmonics);
      EXPECT_TRUE(t.reached_end && t.trusted);
      EXPECT_LE(t.share, 1e-2);
    }
  EXPECT_EQ(kept, 1);
  ASSERT_TRUE(adaptive.tables.count("harmonic_selection"));
  EXPECT_EQ(adaptive.tables.at("harmonic_selection").values.rows(),
            static_cast<Eigen::Index>(chosen.harmonic_trials.size()));
}

// The same oscillator with H raised until the peak itself stops moving: the change each trial
// reports is the difference between fixed-H sweeps at the two H (measured, not estimated), the
// higher H of the pair that meets it is kept, and it is closer to H = 15 than H = 1 is. With the
// peaks scope the H above the first are swept on windows around the previous peaks, and the H
// chosen once more over the whole band: the windows' peaks are the whole band's.
TEST_F(HbmAnalysis, HarmonicChangeCriterionKeepsTheHigherHOfThePairThatAgrees) {
  test::OscillatorCase c = coulomb_like_near_resonance();
  const std::string h1_text = test::oscillator_case_text(c);
  const auto fixed = [&](int h) {
    std::string text = h1_text;
    text.replace(text.find("harmonics = 1\n"), 14, fmt::format("harmonics = {}\n", h));
    return run(text).levels[0].peaks[0];
  };
  const HbmPeak reference = fixed(15);
  const HbmPeak single = fixed(1);
  c.analysis_extra =
      "harmonic_tolerance = 2e-3\nmax_harmonics = 15\nharmonic_criterion = \"change\"\nharmonic_step = 2\n"
      "harmonic_scope = \"peaks\"\n";
  const HbmOutcome adaptive = run(test::oscillator_case_text(c));
  const HbmLevel& chosen = adaptive.levels[0];
  const auto& trials = chosen.harmonic_trials;

  const auto error = [&](const HbmPeak& pk) { return std::abs(pk.component / reference.component - 1); };
  std::printf("  H = 1: error %.3e; chosen H = %d: change %.3e, error %.3e (%zu trials)\n", error(single),
              chosen.harmonics, trials.empty() ? 0.0 : trials.back().change, error(chosen.peaks[0]), trials.size());
  for (const HbmLevel::HarmonicTrial& t : trials)
    std::printf("    H = %d: change %.3e, estimated error %.3e\n", t.harmonics, t.change, t.estimated_error);
  ASSERT_GE(trials.size(), 3u);
  EXPECT_TRUE(std::isnan(trials.front().change));
  EXPECT_EQ(trials.front().window_hz, 0.0);
  const HbmLevel::HarmonicTrial &band = trials.back(), &windows = trials[trials.size() - 2];
  EXPECT_TRUE(band.chosen);
  EXPECT_EQ(band.window_hz, 0.0);
  EXPECT_EQ(band.harmonics, chosen.harmonics);
  EXPECT_EQ(windows.harmonics, chosen.harmonics);
  EXPECT_LT(band.band_change, 1e-9);
  EXPECT_LE(band.change, 2e-3);
  EXPECT_EQ(band.change, windows.change);
  for (size_t t = 1; t + 1 < trials.size(); ++t) {
    EXPECT_GT(trials[t].window_hz, 0.0) << "trial " << t;
    EXPECT_TRUE(std::isnan(trials[t].band_change)) << "trial " << t;
  }
  for (size_t t = 1; t + 2 < trials.size(); ++t) EXPECT_GT(trials[t].change, 2e-3);
  const HbmPeak lower = fixed(trials[trials.size() - 3].harmonics), higher = fixed(chosen.harmonics);
  EXPECT_NEAR(chosen.peaks[0].frequency_hz / higher.frequency_hz, 1.0, 1e-12);
  EXPECT_NEAR(chosen.peaks[0].component / higher.component, 1.0, 1e-12);
  const double measured = std::max(std::abs(lower.frequency_hz / higher.frequency_hz - 1),
                                   std::abs(lower.component / higher.component - 1));
  // Each peak is polished by golden section to a bracket of 1e-7 of its frequency
  // (forced/hbm_sweep.cpp), the windows' from their own path: the two changes agree to the two
  // brackets, not to rounding.
  EXPECT_NEAR(trials.back().change, measured, 2e-7);
  EXPECT_LT(error(chosen.peaks[0]), 0.2 * error(single));
  // Friction converges slowly in H: the last change understates the error, the power law through
  // the last three H bounds it.
  ASSERT_GE(trials.size(), 3u);
  EXPECT_GE(trials.back().estimated_error, error(chosen.peaks[0]));
  EXPECT_LT(trials.back().estimated_error, 5 * error(chosen.peaks[0]));
}

// H per frequency (harmonic_scope = "point"): far from the stuck resonance the contact sticks, the
// motion is linear and the first pair (H = 1, 3) agrees; near it the contact slips and H rises.
// Each point holds the fixed-H solution at its H, its change is the difference of the fixed-H
// sweeps of its pair, and it is closer to H = 15 than H = 1 is.
TEST_F(HbmAnalysis, PointScopeRaisesHOnlyWhereTheContactSlips) {
  test::OscillatorCase c;
  c.step = "1.0";
  c.samples = "256";
  c.levels = "[3.0]";
  const std::string h1_text = test::oscillator_case_text(c);
  std::map<int, HbmLevel> fixed;
  const auto at_h = [&](int h) -> const HbmLevel& {
    if (!fixed.count(h)) {
      std::string text = h1_text;
      text.replace(text.find("harmonics = 1\n"), 14, fmt::format("harmonics = {}\n", h));
      fixed.emplace(h, run(text).levels[0]);
    }
    return fixed.at(h);
  };
  c.analysis_extra =
      "harmonic_tolerance = 1e-4\nmax_harmonics = 11\nharmonic_criterion = \"change\"\nharmonic_step = 2\n"
      "harmonic_scope = \"point\"\n";
  const HbmOutcome outcome = run(test::oscillator_case_text(c));
  const HbmLevel& level = outcome.levels[0];
  ASSERT_TRUE(level.path.converged);
  const size_t n = level.path.points.size();
  ASSERT_EQ(n, 131u);
  ASSERT_EQ(level.point_harmonics.size(), n);
  ASSERT_EQ(level.point_change.size(), n);
  EXPECT_EQ(std::count_if(level.point_change.begin(), level.point_change.end(), [](double d) { return !(d <= 1e-3); }),
            0);
  EXPECT_EQ(level.point_harmonics.front(), 3);
  EXPECT_EQ(level.point_harmonics.back(), 3);
  EXPECT_LT(level.point_change.front(), 1e-6);
  EXPECT_GT(level.harmonics, 3);
  EXPECT_GT(level.peaks[0].harmonics, 3);  // the largest H of the maximum and its neighbours

  double error = 0.0, error_h1 = 0.0;
  const HbmLevel& reference = at_h(15);
  for (size_t i = 0; i < n; ++i) {
    const int h = level.point_harmonics[i];
    const HbmLevel &upper = at_h(h), &lower = at_h(h - 2);
    ASSERT_EQ(upper.frequency_hz.size(), n);
    ASSERT_EQ(lower.frequency_hz.size(), n);
    const Eigen::Index r = static_cast<Eigen::Index>(i);
    EXPECT_NEAR(level.excursion(r, 0) / upper.excursion(r, 0), 1.0, 1e-7) << "point " << i;
    const double measured = std::max(std::abs(lower.excursion(r, 0) / upper.excursion(r, 0) - 1),
                                     std::abs(lower.amplitude(r, 0) / upper.amplitude(r, 0) - 1));
    EXPECT_NEAR(level.point_change[i], measured, 1e-6) << "point " << i;
    const double exact = reference.excursion(r, 0);
    error = std::max(error, std::abs(level.excursion(r, 0) / exact - 1));
    error_h1 = std::max(error_h1, std::abs(at_h(1).excursion(r, 0) / exact - 1));
  }
  int raised = 0;
  for (int h : level.point_harmonics) raised += h > 3;
  std::printf("  H per point 3-%d, %d of %zu points above H = 3; largest error vs H = 15: %.2e (H = 1: %.2e)\n",
              level.harmonics, raised, n, error, error_h1);
  EXPECT_LT(raised, static_cast<int>(n) / 2);
  EXPECT_LT(error, 0.2 * error_h1);
  ASSERT_TRUE(outcome.tables.count("harmonics_per_point"));
}

TEST_F(HbmAnalysis, ContactOnAnUnknownDofIsAnInputErrorNamingTheDof) {
  std::string text = oscillator_case("0.3", "[1.0]");
  const std::string from = "tangential = { \"A.x\" = 1.0 }";
  text.replace(text.find(from), from.size(), "tangential = { \"A.x\" = 1.0, \"Q.x\" = -1.0 }");
  const CaseSpec spec = parse_case_file(write(text));
  const Model model = build_model(spec.model);
  try {
    (void)run_hbm(model, std::get<HbmSpec>(spec.analysis));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Q.x"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ground"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb
