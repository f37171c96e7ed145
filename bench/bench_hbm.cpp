// Nonlinear forced response with friction contacts: one AFT evaluation of a Jenkins contact, one
// Newton solve of the harmonic balance, and a frequency continuation across resonance, on the planar
// model of two 2-DOF blades and a rigid underplatform damper (tests/extremes/hbm_models.hpp:
// kn = kt = 1e6 N/m, mu = 0.3, CF = 300 N, Fe = 10 N on blade 1, zeta = 1e-2 on the blades: the
// contacts stick-slip and never open, and the response curve has no fold). Each at H = 1 and H = 5
// with the default AFT samples, max(64, 16 (2H + 1)). Units: SI. At Fe >= 20 N contact L1 starts to
// lift off near resonance and the solver stalls there (tests/extremes, bench/README.md), so that
// regime would time failures, not solves.
//
// Measurement only: nothing here asserts a time. Counters:
//   iterations             Newton iterations of the timed solve (BM_HbmNewtonSolve)
//   points, corrector_its  accepted points and total corrector iterations of the sweep
//   unknowns               size of the condensed nonlinear system, 7 (2H + 1)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <optional>
#include <string>

#include "../tests/extremes/hbm_models.hpp"
#include "contact/aft.hpp"
#include "hbm/harmonic_balance.hpp"

namespace {

using bb::hbm::HarmonicBalance;

// Stick-slip with a varying normal load that never opens: u of 1e-5 m (about three times the
// stick limit mu N0 / kt = 3e-6 m) and v of 5e-6 m about a static 2e-5 m, plus small higher harmonics.
void BM_AftJenkins(benchmark::State& state) {
  const int harmonics = static_cast<int>(state.range(0));
  const bb::contact::JenkinsParameters law{.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 10.0};
  const Eigen::Index m = bb::contact::harmonic_size(harmonics);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m), v = Eigen::VectorXd::Zero(m);
  u[1] = 1e-5;
  v[0] = 2e-5;
  v[2] = 5e-6;
  for (int h = 2; h <= harmonics; ++h) u[2 * h - 1] = 1e-6 / h, v[2 * h] = 5e-7 / h;
  const bb::contact::AftOptions options{.samples = std::max(64, 16 * static_cast<int>(m))};
  for (auto _ : state) benchmark::DoNotOptimize(bb::contact::aft_jenkins(law, u, v, options));
  state.counters["samples"] = options.samples;
}
BENCHMARK(BM_AftJenkins)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMicrosecond);

HarmonicBalance planar_system(int harmonics) {
  return HarmonicBalance(bb::hbm::models::planar_blades_with_damper({.kn = 1e6, .kt = 1e6, .mu = 0.3}, 10.0, 1e-2),
                         {.harmonics = harmonics});
}

// One Newton solve at the stuck resonance from the converged solution 1% below it.
void BM_HbmNewtonSolve(benchmark::State& state) {
  const HarmonicBalance system = planar_system(static_cast<int>(state.range(0)));
  const double omega = bb::hbm::models::stuck_resonance(system.model(), 0);
  const bb::hbm::HbmSolution neighbour = bb::hbm::solve_at_frequency(system, 0.99 * omega);
  if (!neighbour.converged) {
    state.SkipWithError(("neighbour did not converge: " + neighbour.failure).c_str());
    return;
  }
  int iterations = 0;
  for (auto _ : state) {
    const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(system, omega, neighbour.x);
    if (!s.converged) {
      state.SkipWithError(("solve did not converge: " + s.failure).c_str());
      return;
    }
    iterations = s.iterations;
  }
  state.counters["iterations"] = iterations;
  state.counters["unknowns"] = static_cast<double>(system.unknowns());
  state.counters["omega"] = omega;
}
BENCHMARK(BM_HbmNewtonSolve)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

// Continuation from 0.8 to 1.2 times the stuck resonance (the stick-slip resonance lies inside).
void BM_HbmContinuationSweep(benchmark::State& state) {
  const HarmonicBalance system = planar_system(static_cast<int>(state.range(0)));
  const double omega = bb::hbm::models::stuck_resonance(system.model(), 0);
  bb::hbm::ContinuationResult last;
  for (auto _ : state) {
    last = bb::hbm::continue_in_frequency(system, {.omega_start = 0.8 * omega, .omega_end = 1.2 * omega, .progress = {}});
    if (!last.converged) {
      state.SkipWithError(("continuation stopped: " + last.failure).c_str());
      return;
    }
  }
  state.counters["points"] = static_cast<double>(last.points.size());
  state.counters["corrector_its"] = last.corrector_iterations;
  state.counters["rejected"] = last.rejected_steps;
  state.counters["unknowns"] = static_cast<double>(system.unknowns());
}
BENCHMARK(BM_HbmContinuationSweep)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace
