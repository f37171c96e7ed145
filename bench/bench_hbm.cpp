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
//   resolves, newton_its   re-solves and their Newton iterations per central-difference set
// BM_HbmSensitivityAnalytic and BM_HbmSensitivityCentralDifference price the same four derivatives
// (kn, kt, mu, N0 of the shared law) of one solution: the implicit function theorem (one
// factorization of J, one AFT per contact with law derivatives) against 8 warm-started re-solves;
// their time ratio is the speed-up of hbm/sensitivity.hpp.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "../tests/extremes/hbm_models.hpp"
#include "friction/aft.hpp"
#include "hbm/harmonic_balance.hpp"
#include "hbm/hill_stability.hpp"
#include "hbm/sensitivity.hpp"

namespace {

using bb::hbm::HarmonicBalance;

// Stick-slip with a varying normal load that never opens: u of 1e-5 m (about three times the
// stick limit mu N0 / kt = 3e-6 m) and v of 5e-6 m about a static 2e-5 m, plus small higher harmonics.
const bb::friction::PointParameters kStickSlipLaw{.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 10.0};

// The tangential (u) and normal (v) coefficients of that motion with H harmonics.
std::pair<Eigen::VectorXd, Eigen::VectorXd> stick_slip_motion(int harmonics) {
  const Eigen::Index m = bb::friction::harmonic_size(harmonics);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m), v = Eigen::VectorXd::Zero(m);
  u[1] = 1e-5;
  v[0] = 2e-5;
  v[2] = 5e-6;
  for (int h = 2; h <= harmonics; ++h) u[2 * h - 1] = 1e-6 / h, v[2 * h] = 5e-7 / h;
  return {u, v};
}

void BM_AftJenkins(benchmark::State& state) {
  const int harmonics = static_cast<int>(state.range(0));
  const bb::friction::PointParameters& law = kStickSlipLaw;
  const auto [u, v] = stick_slip_motion(harmonics);
  const Eigen::Index m = u.size();
  const bb::friction::AftOptions options{.samples = std::max(64, 16 * static_cast<int>(m))};
  for (auto _ : state) benchmark::DoNotOptimize(bb::friction::aft_jenkins(law, u, v, options));
  state.counters["samples"] = options.samples;
}
BENCHMARK(BM_AftJenkins)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMicrosecond);

// The same AFT (with its exact Jacobian) against the number of samples, at H = 1 and 7: the cost
// is linear in the samples (the transforms are products with the n x (2H + 1) synthesis matrix,
// and the Jacobian's chain rule through the slider is a row of 2 (2H + 1) per sample). Samples
// that are not powers of two cost the same per sample.
void BM_AftJenkinsSamples(benchmark::State& state) {
  const int harmonics = static_cast<int>(state.range(0));
  const int samples = static_cast<int>(state.range(1));
  const bb::friction::PointParameters& law = kStickSlipLaw;
  const auto [u, v] = stick_slip_motion(harmonics);
  const bb::friction::AftOptions options{.samples = samples};
  for (auto _ : state) benchmark::DoNotOptimize(bb::friction::aft_jenkins(law, u, v, options));
  state.counters["ns_per_sample"] = benchmark::Counter(
      static_cast<double>(samples), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_AftJenkinsSamples)
    ->ArgNames({"H", "samples"})
    ->ArgsProduct({{1, 7}, {64, 240, 256, 512, 1000, 1024, 4096, 16384}})
    ->Unit(benchmark::kMicrosecond);

// The event-resolved AFT (friction/aft_events.hpp) on the same motion against its sample intervals,
// beside the sampled AFT above at the samples each needs for the same accuracy.
void BM_AftJenkinsEvents(benchmark::State& state) {
  const int harmonics = static_cast<int>(state.range(0));
  const auto [u, v] = stick_slip_motion(harmonics);
  bb::friction::AftOptions options{.samples = static_cast<int>(state.range(1))};
  options.resolve_events = true;
  for (auto _ : state) benchmark::DoNotOptimize(bb::friction::aft_jenkins(kStickSlipLaw, u, v, options));
}
BENCHMARK(BM_AftJenkinsEvents)
    ->ArgNames({"H", "samples"})
    ->ArgsProduct({{1, 7}, {16, 32, 64, 240}})
    ->Unit(benchmark::kMicrosecond);

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

// Hill's method at the stuck resonance (hbm/hill_stability.hpp): one eigenproblem of size
// 2 n (2H + 1) = 14 (2H + 1) on the full model, against the Newton solve above that produced it.
void BM_HillStability(benchmark::State& state) {
  const HarmonicBalance system = planar_system(static_cast<int>(state.range(0)));
  const double omega = bb::hbm::models::stuck_resonance(system.model(), 0);
  const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(system, omega);
  if (!s.converged) {
    state.SkipWithError(("solve did not converge: " + s.failure).c_str());
    return;
  }
  double max_real = 0.0;
  for (auto _ : state) {
    const bb::hbm::HillStability st = bb::hbm::hill_stability(system, s.x, omega);
    if (!st.ok) {
      state.SkipWithError(st.failure.c_str());
      return;
    }
    max_real = st.max_real;
  }
  state.counters["eigenproblem_size"] =
      2.0 * static_cast<double>(system.model().mass.rows()) * static_cast<double>(2 * state.range(0) + 1);
  state.counters["max_real"] = max_real;
}
BENCHMARK(BM_HillStability)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

// Continuation from 0.8 to 1.2 times the stuck resonance (the stick-slip resonance lies inside).
void BM_HbmContinuationSweep(benchmark::State& state) {
  const HarmonicBalance system = planar_system(static_cast<int>(state.range(0)));
  const double omega = bb::hbm::models::stuck_resonance(system.model(), 0);
  bb::hbm::ContinuationResult last;
  for (auto _ : state) {
    last =
        bb::hbm::continue_in_frequency(system, {.omega_start = 0.8 * omega, .omega_end = 1.2 * omega, .progress = {}});
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

// The planar model at Fe = 200 N with the sliders resting at the frictionless static seat (as
// analysis/hbm_analysis does), 10 % below the stuck resonance, where a good part of the samples
// slip and none opens (counter slip; tests/unit/hbm_sensitivity_test.cpp checks this point with
// N0 = 0 against differences). N0 = 10 N on top of CF so that its difference costs re-solves too.
HarmonicBalance sensitivity_system(int harmonics) {
  bb::friction::FrictionModel m =
      bb::hbm::models::planar_blades_with_damper({.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 10.0}, 200.0, 1e-2);
  Eigen::MatrixXd k = m.stiffness;
  for (const bb::friction::ContactElement& c : m.contacts) k += c.point.kn * c.normal.transpose() * c.normal;
  const Eigen::VectorXd seat = k.fullPivLu().solve(m.static_load);
  for (bb::friction::ContactElement& c : m.contacts) c.tangential_offset = c.tangential.dot(seat);
  return HarmonicBalance(std::move(m), {.harmonics = harmonics, .tolerance = 1e-12});
}

// Counter slip = fraction of slipping samples over all contacts.
std::optional<bb::hbm::HbmSolution> sensitivity_point(const HarmonicBalance& system, benchmark::State& state) {
  const double omega = 0.9 * bb::hbm::models::stuck_resonance(system.model(), 0);
  bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(system, omega);
  if (!s.converged) {
    state.SkipWithError(("base solve did not converge: " + s.failure).c_str());
    return std::nullopt;
  }
  double slip = 0.0, samples = 0.0;
  for (const bb::friction::AftResult& r : s.contacts)
    for (const bb::friction::ContactState c : r.state) {
      samples += 1.0;
      if (c == bb::friction::ContactState::slip_positive || c == bb::friction::ContactState::slip_negative) slip += 1.0;
    }
  state.counters["slip"] = slip / samples;
  return s;
}

void BM_HbmSensitivityAnalytic(benchmark::State& state) {
  const HarmonicBalance system = sensitivity_system(static_cast<int>(state.range(0)));
  const auto base = sensitivity_point(system, state);
  if (!base) return;
  std::vector<bb::hbm::ModelDerivative> d;
  for (const auto p : {bb::friction::law_kn, bb::friction::law_kt, bb::friction::law_mu, bb::friction::law_n0})
    d.push_back(bb::hbm::law_derivative(system.model(), p));
  for (auto _ : state) benchmark::DoNotOptimize(bb::hbm::solution_sensitivity(system, *base, d));
  state.counters["unknowns"] = static_cast<double>(system.unknowns());
}
BENCHMARK(BM_HbmSensitivityAnalytic)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

// Relative step 1e-6 on each law parameter, re-solved from the base solution; a HarmonicBalance
// per perturbed model, as a caller of the solver would have to build. Tolerance 1e-12 (that of
// tests/unit/hbm_sensitivity_test.cpp): at the default 1e-9 a 1e-6 step changes R by less than the
// target, the warm start is accepted as it is and most differences come out exactly zero.
void BM_HbmSensitivityCentralDifference(benchmark::State& state) {
  const int harmonics = static_cast<int>(state.range(0));
  const HarmonicBalance system = sensitivity_system(harmonics);
  const auto base = sensitivity_point(system, state);
  if (!base) return;
  int iterations = 0;
  for (auto _ : state) {
    iterations = 0;
    Eigen::MatrixXd dx(system.unknowns(), 4);
    for (int p = 0; p < 4; ++p) {
      std::array<Eigen::VectorXd, 2> x;
      for (int side = 0; side < 2; ++side) {
        bb::friction::FrictionModel m = system.model();
        for (bb::friction::ContactElement& c : m.contacts) {
          double* field = p == 0 ? &c.point.kn : p == 1 ? &c.point.kt : p == 2 ? &c.point.mu : &c.point.n0;
          *field *= side == 0 ? 1.0 + 1e-6 : 1.0 - 1e-6;
        }
        const HarmonicBalance perturbed(std::move(m), system.options());
        const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(perturbed, base->omega, base->x);
        if (!s.converged) {
          state.SkipWithError(("re-solve did not converge: " + s.failure).c_str());
          return;
        }
        iterations += s.iterations;
        x[static_cast<size_t>(side)] = s.x;
      }
      dx.col(p) = (x[0] - x[1]) / 2e-6;
    }
    benchmark::DoNotOptimize(dx);
  }
  state.counters["resolves"] = 8;
  state.counters["newton_its"] = iterations;
  state.counters["unknowns"] = static_cast<double>(system.unknowns());
}
BENCHMARK(BM_HbmSensitivityCentralDifference)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace
