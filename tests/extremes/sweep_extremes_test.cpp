// The extremes matrix of tests/extremes/hbm_extremes_test.cpp carried to whole sweeps and to the
// nonlinear modes: a blade tied to the ground by one Jenkins contact, kn = kt from 1e3 to 1e12 N/m,
// mu 0-2, Fe 0.01-3000 N, zeta 1e-2 and 1e-5, swept over its stuck resonance at H = 1 and at H = 7
// with the events AFT (analysis level: grid, arclength bridges, peaks), and its first nonlinear
// mode from 1e-8 to 1e-2 m kg^1/2. The contract at every point: every path point is a converged,
// finite solve; a sweep that does not reach its end says where and why; a peak is a converged
// solve or the run refuses it (the analysis then stops with exit 3), and a peak next to a failed
// frequency is flagged doubtful; a nonlinear-mode branch holds finite points with omega > 0 and
// kappa >= 0 (a friction contact and viscous damping only dissipate), or stops with a reason.
// Units: SI.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/hbm_analysis.hpp"
#include "hbm/nonlinear_modes.hpp"
#include "hbm_models.hpp"

namespace bb {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct Case {
  double k, mu, force, zeta;
};

// The blade of hbm_models.hpp as a prepared analysis: response and force on the root DOF 0.
PreparedHbm prepared(const Case& c) {
  PreparedHbm p;
  p.model = hbm::models::blade_on_ground({.kn = c.k, .kt = c.k, .mu = c.mu, .n0 = 10.0}, 1.0, c.zeta);
  p.dof_names = {"root", "platform.t", "platform.n"};
  p.contact_names = {"ground"};
  p.responses = {0};
  p.response_names = {"root"};
  p.blade_dofs = 3;
  return p;
}

std::vector<Case> matrix() {
  std::vector<Case> cases;
  for (const double k : {1e3, 1e6, 1e9, 1e12})
    for (const double mu : {0.0, 0.3, 2.0})
      for (const double force : {0.01, 1.0, 100.0, 3000.0})
        for (const double zeta : {1e-2, 1e-5}) cases.push_back({k, mu, force, zeta});
  return cases;
}

// Sweeps the whole matrix at H harmonics (AFT: 64 samples, or the events AFT at its automatic
// samples) and checks the contract; returns the number of sweeps that reached their end.
int sweep_matrix(int harmonics, bool events) {
  int reached = 0, stopped = 0, refused = 0, doubtful = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const Case& c : matrix()) {
    const PreparedHbm p = prepared(c);
    const double f0 = hbm::models::stuck_resonance(p.model, 0) / kTwoPi;
    HbmSpec spec;
    spec.sweep.f_min = 0.8 * f0;
    spec.sweep.f_max = 1.2 * f0;
    spec.sweep.step_hz = 0.4 * f0 / 80;  // 81 frequencies
    spec.time_samples = events ? 0 : 64;
    spec.aft_events = events;
    spec.max_iterations = 20;
    const std::string where =
        ::testing::PrintToString(std::vector<double>{c.k, c.mu, c.force, c.zeta}) + " H = " + std::to_string(harmonics);
    const HbmLevel level = sweep_hbm_level(p, spec, c.force, harmonics);
    for (const hbm::ContinuationPoint& pt : level.path.points) {
      EXPECT_TRUE(pt.x.allFinite() && std::isfinite(pt.omega) && std::isfinite(pt.residual)) << where;
      EXPECT_GE(pt.omega, kTwoPi * spec.sweep.f_min * (1 - 1e-9)) << where;
    }
    if (level.path.converged) {
      ++reached;
      EXPECT_TRUE(level.failed_hz.empty()) << where;
    } else {
      ++stopped;
      EXPECT_FALSE(level.path.failure.empty()) << where;
      std::printf("stopped %s: %s\n", where.c_str(), level.path.failure.substr(0, 160).c_str());
    }
    for (const HbmPeak& pk : level.peaks) {
      if (!pk.solution.converged) {
        ++refused;  // run_hbm turns this into a SolverError: never a reported peak
        EXPECT_FALSE(pk.solution.failure.empty()) << where;
        continue;
      }
      EXPECT_TRUE(std::isfinite(pk.frequency_hz) && std::isfinite(pk.amplitude)) << where;
      EXPECT_GE(pk.amplitude, 0.0) << where;
      EXPECT_TRUE(std::isfinite(pk.sampling_error)) << where;
      if (!pk.trusted) {
        ++doubtful;
        EXPECT_FALSE(pk.doubt.empty()) << where;
      }
      // A failed frequency between the peak's neighbours must have made it doubtful.
      for (double f : level.failed_hz)
        if (std::abs(f - pk.frequency_hz) < 0.5 * spec.sweep.step_hz) {
          EXPECT_FALSE(pk.trusted) << where;
        }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "H = %d: sweeps %zu, reached the end %d, stopped with a reason %d, peaks refused %d, doubtful %d (%.1f s)\n",
      harmonics, matrix().size(), reached, stopped, refused, doubtful, seconds);
  return reached;
}

TEST(SweepExtremes, EverySweepReachesItsEndOrSaysWhereAndNoPeakSitsOnAFailure) {
  EXPECT_GT(sweep_matrix(1, false), static_cast<int>(matrix().size()) / 2);  // the benign part does converge
}

// Issue 31, point 1: the same matrix at H = 7 with the events AFT.
TEST(SweepExtremes, AtSevenHarmonicsEverySweepReachesItsEndOrSaysWhere) {
  EXPECT_GT(sweep_matrix(7, true), static_cast<int>(matrix().size()) / 2);
}

TEST(SweepExtremes, NonlinearModeBranchesHoldFinitePointsOrStopWithAReason) {
  std::vector<double> amplitudes;
  for (int i = 0; i <= 30; ++i) amplitudes.push_back(1e-8 * std::pow(1e6, i / 30.0));
  int complete = 0, stopped = 0;
  for (const Case& c : matrix()) {
    if (c.force != 1.0) continue;  // the mode does not depend on the force
    const PreparedHbm p = prepared(c);
    const std::string where = ::testing::PrintToString(std::vector<double>{c.k, c.mu, c.zeta});
    hbm::NonlinearModeOptions options;
    options.aft.samples = 64;
    const hbm::NonlinearModeBranch b = hbm::trace_nonlinear_mode(p.model, 1, amplitudes, {}, options);
    for (const hbm::NonlinearModePoint& pt : b.points) {
      ASSERT_TRUE(pt.coefficients.allFinite() && std::isfinite(pt.omega) && std::isfinite(pt.kappa)) << where;
      EXPECT_GT(pt.omega, 0.0) << where;
      EXPECT_GE(pt.kappa, -1e-9 * pt.omega) << where;
    }
    if (b.converged) {
      ++complete;
      EXPECT_EQ(b.points.size(), amplitudes.size()) << where;
    } else {
      ++stopped;
      EXPECT_FALSE(b.failure.empty()) << where;
      std::printf("stopped %s after %zu points: %s\n", where.c_str(), b.points.size(),
                  b.failure.substr(0, 160).c_str());
    }
  }
  std::printf("nonlinear-mode branches: complete %d, stopped with a reason %d\n", complete, stopped);
  EXPECT_GT(complete, 0);
}

}  // namespace
}  // namespace bb
