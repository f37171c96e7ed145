// The work estimate every analysis is held to before it runs (analysis/work_estimate,
// common/work_limits): it scales as the arithmetic does, and a refusal names the key, the estimate
// and the bound.
#include "analysis/work_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "common/errors.hpp"
#include "friction/iwan_law.hpp"

namespace bb {
namespace {

HbmSpec oscillator_sweep(double step_hz, int harmonics, int samples) {
  HbmSpec s;
  s.sweep.f_min = 100.0;
  s.sweep.f_max = 200.0;
  s.sweep.step_hz = step_hz;
  s.harmonics = harmonics;
  s.time_samples = samples;
  s.force_levels = {1.0, 10.0};
  HbmContactSpec c;
  c.tangential = {{PointDof{"A", 0}, 1.0}};
  s.contacts.push_back(c);
  s.at = {"case.toml", 12};
  return s;
}

TEST(WorkEstimate, HarmonicBalanceScalesWithFrequenciesLevelsSamplesAndHarmonics) {
  const Model none;
  const double base = estimate_work(oscillator_sweep(1.0, 3, 1024), none).operations;
  ASSERT_GT(base, 0.0);
  // 101 -> 201 frequencies.
  EXPECT_NEAR(estimate_work(oscillator_sweep(0.5, 3, 1024), none).operations / base, 201.0 / 101.0, 1e-9);
  // The AFT Jacobian dominates a one-contact model: linear in the samples, (2H + 1)^2 in H.
  EXPECT_NEAR(estimate_work(oscillator_sweep(1.0, 3, 4096), none).operations / base, 4.0, 0.01);
  EXPECT_NEAR(estimate_work(oscillator_sweep(1.0, 7, 1024), none).operations / base, 225.0 / 49.0, 0.01);
}

// An Iwan joint is as many Jenkins sliders as its distribution holds, each an AFT of its own: it
// counted as one contact (issue 70: 10 000 sliders ran for minutes, 50 harmonics past 4.6 GB).
TEST(WorkEstimate, AnIwanJointCountsEverySlider) {
  const Model none;
  const HbmSpec jenkins = oscillator_sweep(1.0, 3, 1024);
  HbmSpec iwan = jenkins;
  iwan.contacts[0].distribution =
      std::make_shared<friction::IwanDistribution>(friction::IwanParameters{.sliders = 1000});
  const WorkEstimate one = estimate_work(jenkins, none), many = estimate_work(iwan, none);
  EXPECT_NEAR(many.operations / one.operations, 1000.0, 10.0);
  EXPECT_GT(many.bytes, 100.0 * one.bytes);  // the DFT rows of each slider
}

// A point's solve costs more than its AFT and LU where both are tiny (H = 1, 64 samples: 2 300
// operations counted, 35 us measured): 5 levels of the reader's 1e6 frequencies ran for minutes
// (issue 70). Each solve now counts at least 1e5 operations; a costlier solve is counted as before.
TEST(WorkEstimate, ASolveCostsAtLeastItsOverheadWhereItsArithmeticIsTiny) {
  const Model none;
  HbmSpec tiny = oscillator_sweep(4e-5, 1, 64);
  tiny.sweep.f_max = tiny.sweep.f_min + 40.0;  // 1e6 + 1 frequencies
  tiny.force_levels = {1.0, 3.0, 10.0, 30.0, 100.0};
  EXPECT_GE(estimate_work(tiny, none).operations, 5.0 * 1e6 * 5.0 * 1e5);
  EXPECT_THROW(require_within(estimate_work(tiny, none), WorkLimits{}), InputError);
}

// The contact loop had no estimate: 1e4 sliders at 1e6 samples ran for an hour (issue 70).
TEST(WorkEstimate, AContactLoopCountsEverySliderAtEverySample) {
  ContactLoopSpec loop;
  loop.samples = 1000;
  const double one = estimate_work(loop, Model{}).operations;
  EXPECT_GT(one, 0.0);
  loop.samples = 1'000'000;
  loop.distribution = std::make_shared<friction::IwanDistribution>(friction::IwanParameters{.sliders = 10000});
  const WorkEstimate many = estimate_work(loop, Model{});
  EXPECT_NEAR(many.operations / one, 10000.0 * 1000.0, 1e4);
  EXPECT_THROW(require_within(many, WorkLimits{}), InputError);
}

TEST(WorkEstimate, ARefusalNamesTheKeyTheEstimateAndTheBound) {
  const WorkEstimate e = estimate_work(oscillator_sweep(1e-3, 50, 100000), Model{});
  WorkLimits limits;
  try {
    require_within(e, limits);
    FAIL() << "not refused: " << e.operations;
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("case.toml:12: 'analysis.step_hz"), std::string::npos) << what;
    EXPECT_NE(what.find("H up to 50, 100000 AFT samples"), std::string::npos) << what;
    EXPECT_NE(what.find("above the bound of 1e+12"), std::string::npos) << what;
  }
  limits.operations = 2.0 * e.operations;  // raised by one who means it
  limits.bytes = 2.0 * e.bytes;
  EXPECT_NO_THROW(require_within(e, limits));
}

TEST(WorkEstimate, MeshMemoryGrowsFasterThanItsDofs) {
  auto strip = [](int nx) {
    Model m;
    m.mesh.dim = 2;
    m.mesh.node_ids.resize(static_cast<size_t>(2 * (nx + 1)));
    ElementBlock b;
    b.type = ElementType::q4;
    b.conn.resize(nx, 4);
    m.mesh.blocks.push_back(b);
    return m;
  };
  const WorkEstimate small = estimate_mesh_work(strip(1000)), large = estimate_mesh_work(strip(100000));
  const double dofs = (2.0 * 100001) / (2.0 * 1001);
  EXPECT_GT(large.bytes / small.bytes, dofs);  // the factor's fill: n log n
  EXPECT_NEAR(large.operations / small.operations, std::pow(dofs, 1.5), 1e-9 * std::pow(dofs, 1.5));  // n^1.5
  EXPECT_EQ(estimate_mesh_work(Model{}).bytes, 0.0);
}

}  // namespace
}  // namespace bb
