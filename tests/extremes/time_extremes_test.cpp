// Numerical stability of the Newmark integrator with friction contacts at extreme parameters (the
// matrix of the harmonic-balance extremes): kn, kt from 1e3 to 1e12 N/m, mu 0-2, Fe 0.01-3000 N,
// zeta down to 1e-5, N0 from 0 to 1e5 N. Every run either completes with finite values or stops at
// a step that reports its time and residual; never NaN, never more Newton iterations than allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "hbm_models.hpp"
#include "timeint/newmark.hpp"
#include "timeint/static_state.hpp"

namespace bb::timeint {
namespace {

struct Tally {
  int completed = 0, stopped = 0;
};

// Three periods at 64 steps per period near the blade's first mode, from the static state.
void run_point(const friction::FrictionModel& model, Tally& tally) {
  const double omega = 1000.0;
  const NewmarkIntegrator integrator(model, {.time_step = 2 * std::numbers::pi / (omega * 64)});
  const StaticState s = static_initial_state(model);
  if (!s.converged) {
    EXPECT_FALSE(s.failure.empty());
    EXPECT_TRUE(s.q.allFinite());
    ++tally.stopped;
    return;
  }
  const Excitation f = harmonic_excitation(model.harmonic_load, omega);
  const DynamicState start = integrator.initial_state(s.q, Eigen::VectorXd::Zero(s.q.size()), 0.0, f, s.sliders);
  const TimeHistory h = integrate(integrator, start, f, 3 * 64, {.dofs = {0, 1, 2}, .contacts = true});
  EXPECT_LE(h.max_iterations, integrator.options().max_iterations);
  EXPECT_TRUE(h.displacement.topRows(h.steps + 1).allFinite());
  EXPECT_TRUE(h.final_state.displacement.allFinite());
  if (h.converged) {
    EXPECT_EQ(h.steps, 3 * 64);
    ++tally.completed;
  } else {
    EXPECT_NE(h.failure.find("t ="), std::string::npos) << h.failure;
    ++tally.stopped;
  }
}

TEST(TimeExtremes, BladeOnGroundCompletesOrStopsWithAReason) {
  Tally tally;
  for (const double kn : {1e3, 1e6, 1e9, 1e12})
    for (const double kt : {1e3, 1e6, 1e12})
      for (const double mu : {0.0, 0.3, 2.0})
        for (const double force : {0.01, 100.0, 3000.0})
          for (const double n0 : {0.0, 1e5}) {
            const friction::FrictionModel m =
                hbm::models::blade_on_ground({.kn = kn, .kt = kt, .mu = mu, .n0 = n0}, force, 1e-5);
            run_point(m, tally);
          }
  std::printf("  blade on ground: %d completed, %d stopped with a reason\n", tally.completed, tally.stopped);
  EXPECT_GT(tally.completed, 0);
}

TEST(TimeExtremes, BladesWithDamperCompleteOrStopWithAReason) {
  Tally tally;
  for (const double k : {1e3, 1e6, 1e9, 1e12})
    for (const double mu : {0.0, 0.3, 2.0})
      for (const double force : {0.01, 10.0, 3000.0})
        for (const double zeta : {1e-5, 1e-2}) {
          const friction::FrictionModel m =
              hbm::models::planar_blades_with_damper({.kn = k, .kt = k, .mu = mu}, force, zeta);
          run_point(m, tally);
        }
  std::printf("  blades + damper: %d completed, %d stopped with a reason\n", tally.completed, tally.stopped);
  EXPECT_GT(tally.completed, 0);
}

}  // namespace
}  // namespace bb::timeint
