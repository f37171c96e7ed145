// Time-domain forced response (thesis section 3.4): one Newmark step of a linear model, one step
// with the implicit Table XII contact, and one stepped-sine frequency point to the steady state, on
// the planar blades + rigid damper of tests/extremes/hbm_models.hpp (kn = kt = 1e6 N/m, mu = 0.3,
// CF = 300 N, Fe = 10 N: stick-slip without lift-off) and on the same blades without contacts.
// 128 steps per period at the stuck resonance. Measurement only: nothing here asserts a time.
// Counters: dofs, contact_dofs, iterations (Newton per step), cycles (periods to the steady state).
// Shooting (timeint/shooting.hpp) on the same point from the same start, and on Den Hartog's
// oscillator: counters iterations (Newton), periods (integrated), transitions (per period); its stop
// motion with the Jenkins element against Coulomb's stick (stick = "rigid").
#include <benchmark/benchmark.h>

#include <numbers>

#include "../tests/extremes/hbm_models.hpp"
#include "timeint/newmark.hpp"
#include "timeint/shooting.hpp"
#include "timeint/static_state.hpp"
#include "timeint/steady_state.hpp"

namespace {

using bb::friction::FrictionModel;

FrictionModel friction_model() {
  return bb::hbm::models::planar_blades_with_damper({.kn = 1e6, .kt = 1e6, .mu = 0.3}, 10.0, 1e-2);
}

// The same blades and damper with the contacts replaced by their springs: a linear model.
FrictionModel linear_model() {
  FrictionModel m = friction_model();
  for (const bb::friction::ContactElement& c : m.contacts)
    m.stiffness += c.point.kn * c.normal.transpose() * c.normal + c.point.kt * c.tangential.transpose() * c.tangential;
  m.contacts.clear();
  return m;
}

void step_benchmark(benchmark::State& state, const FrictionModel& model) {
  const double omega = bb::hbm::models::stuck_resonance(friction_model(), 0);
  const bb::timeint::NewmarkIntegrator integrator(model, {.time_step = 2 * std::numbers::pi / (omega * 128)});
  const auto excitation = bb::timeint::harmonic_excitation(model.harmonic_load, omega);
  // Warm up a few periods from the static state, so the timed steps see the stick-slip cycle.
  const bb::timeint::StaticState s = bb::timeint::static_initial_state(model);
  bb::timeint::DynamicState x =
      integrator.initial_state(s.q, Eigen::VectorXd::Zero(s.q.size()), 0.0, excitation, s.sliders);
  for (int k = 0; k < 20 * 128; ++k) integrator.step(x, excitation);
  long iterations = 0, steps = 0;
  for (auto _ : state) {
    const bb::timeint::StepReport r = integrator.step(x, excitation);
    iterations += r.iterations;
    ++steps;
    if (!r.converged) {
      state.SkipWithError(r.failure.c_str());
      return;
    }
  }
  state.counters["dofs"] = static_cast<double>(model.mass.rows());
  state.counters["contact_dofs"] = static_cast<double>(integrator.contact_dofs().size());
  state.counters["iterations"] = static_cast<double>(iterations) / static_cast<double>(std::max(1L, steps));
}

void BM_NewmarkStepLinear(benchmark::State& state) { step_benchmark(state, linear_model()); }
BENCHMARK(BM_NewmarkStepLinear)->Unit(benchmark::kMicrosecond);

void BM_NewmarkStepFriction(benchmark::State& state) { step_benchmark(state, friction_model()); }
BENCHMARK(BM_NewmarkStepFriction)->Unit(benchmark::kMicrosecond);

// One frequency point of a stepped sine: from the steady state 1 % below, to the steady state here.
void BM_SteadyStateFrequencyPoint(benchmark::State& state) {
  const FrictionModel model = friction_model();
  const double omega = bb::hbm::models::stuck_resonance(model, 0);
  bb::timeint::SteadyStateOptions options;
  options.dofs = {0, 2};
  options.steps_per_period = 128;
  options.tolerance = 1e-6;
  const bb::timeint::SteadyState below = bb::timeint::steady_state(model, 0.99 * omega, options);
  if (!below.converged) {
    state.SkipWithError(("no steady state below: " + below.failure).c_str());
    return;
  }
  int cycles = 0;
  for (auto _ : state) {
    const bb::timeint::SteadyState s = bb::timeint::steady_state(model, omega, options, below.final_state);
    cycles = s.cycles;
    benchmark::DoNotOptimize(s.amplitude);
  }
  state.counters["cycles"] = cycles;
}
BENCHMARK(BM_SteadyStateFrequencyPoint)->Unit(benchmark::kMillisecond);

// The same frequency point by shooting, started from the periodic state 1 % below.
void BM_ShootingFrequencyPoint(benchmark::State& state) {
  const FrictionModel model = friction_model();
  const double omega = bb::hbm::models::stuck_resonance(model, 0);
  bb::timeint::ShootingOptions options;
  options.dofs = {0, 2};
  options.steps_per_period = 128;
  const bb::timeint::ShootingResult below = bb::timeint::shooting(model, 0.99 * omega, options);
  if (!below.steady.converged) {
    state.SkipWithError(("no periodic state below: " + below.steady.failure).c_str());
    return;
  }
  bb::timeint::ShootingResult s;
  for (auto _ : state) {
    s = bb::timeint::shooting(model, omega, options, below.start);
    benchmark::DoNotOptimize(s.steady.amplitude);
  }
  state.counters["iterations"] = static_cast<double>(s.steady.total_iterations);
  state.counters["periods"] = s.steady.cycles;
  state.counters["transitions"] = s.transitions;
}
BENCHMARK(BM_ShootingFrequencyPoint)->Unit(benchmark::kMillisecond);

// Den Hartog's oscillator: m = 1 kg, k = 1e6 N/m, slip force 3 N on a Jenkins element of `kt`
// [N/m], driven at `force` [N]; shot with 64 sub-intervals, 3 harmonics and the multipliers.
FrictionModel coulomb_oscillator(double kt, double force) {
  FrictionModel m;
  m.mass = Eigen::MatrixXd::Constant(1, 1, 1.0);
  m.stiffness = Eigen::MatrixXd::Constant(1, 1, 1e6);
  m.contacts.push_back({.point = {.kn = 1e12, .kt = kt, .mu = 0.3, .n0 = 10.0},
                        .tangential = Eigen::RowVectorXd::Ones(1),
                        .normal = Eigen::RowVectorXd::Zero(1)});
  m.harmonic_load = Eigen::VectorXcd::Constant(1, force);
  return m;
}

bb::timeint::ShootingOptions coulomb_shooting() {
  bb::timeint::ShootingOptions options;
  options.dofs = {0};
  options.steps_per_period = 64;
  options.harmonics = 3;
  options.floquet = true;
  return options;
}

// Den Hartog's oscillator (cases/verification/coulomb_oscillator_shooting.toml: kt = 1e14 N/m,
// Ff/F0 = 0.3) at one frequency [Hz] from the static state, Floquet multipliers included.
void BM_ShootingCoulombOscillator(benchmark::State& state) {
  const FrictionModel m = coulomb_oscillator(1e14, 10.0);
  const bb::timeint::ShootingOptions options = coulomb_shooting();
  const double omega = 2 * std::numbers::pi * static_cast<double>(state.range(0));
  bb::timeint::ShootingResult s;
  for (auto _ : state) {
    s = bb::timeint::shooting(m, omega, options);
    benchmark::DoNotOptimize(s.largest);
  }
  state.counters["iterations"] = static_cast<double>(s.steady.total_iterations);
  state.counters["periods"] = s.steady.cycles;
  state.counters["transitions"] = s.transitions;
}
BENCHMARK(BM_ShootingCoulombOscillator)->Arg(200)->Arg(300)->Arg(400)->Unit(benchmark::kMillisecond);

// The stop motion of cases/verification/coulomb_oscillator_shooting_stops.toml (Ff/F0 = 0.9 at
// 100 Hz, one stop per half period) from the static state: the Jenkins element at kt = 1e12 N/m,
// whose stuck mass rings on kt (rigid:0), against Coulomb's stick (rigid:1).
void BM_ShootingCoulombStop(benchmark::State& state) {
  const FrictionModel m = coulomb_oscillator(1e12, 10.0 / 3.0);
  bb::timeint::ShootingOptions options = coulomb_shooting();
  options.rigid_stick = state.range(0) == 1;
  const double omega = 2 * std::numbers::pi * 100.0;
  bb::timeint::ShootingResult s;
  for (auto _ : state) {
    s = bb::timeint::shooting(m, omega, options);
    benchmark::DoNotOptimize(s.largest);
  }
  state.counters["converged"] = s.steady.converged;
  state.counters["iterations"] = static_cast<double>(s.steady.total_iterations);
  state.counters["periods"] = s.steady.cycles;
  state.counters["transitions"] = s.transitions;
}
BENCHMARK(BM_ShootingCoulombStop)->ArgName("rigid")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
